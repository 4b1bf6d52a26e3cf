"""Exit codes: every error of a command becomes a one-line message on stderr and a code, here.

0 ok; 1 a check failed (or a level did not validate, for ``check``); 2 bad input or environment
(a malformed level, an unusable path, a missing optional dependency); 3 an internal error (a bug:
one line says so and names the file the full traceback was written to); 130 interrupted
(Ctrl-C). Nothing ends in a traceback on the terminal. Ctrl-C is caught even when it lands inside
a pymunk callback (see :func:`_on_interrupt`); a reader that stops reading (``playground list |
head -1``) ends the command quietly.

>>> def needs_pygame() -> int:
...     raise ModuleNotFoundError("No module named 'pygame'", name="pygame")
>>> guarded("playground play", needs_pygame)  # stderr: needs pygame-ce: pip install '...[view]'
2
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import tempfile
import threading
import time
import traceback
import types
from collections.abc import Callable, Iterator

from playground._engine.raw import c_callback_code
from playground.cli.preflight import UsageError
from playground.level.errors import LevelError

__all__ = [
    "CRASH_DIR_ENV",
    "EXIT_FAILED",
    "EXIT_INTERNAL",
    "EXIT_INTERRUPTED",
    "EXIT_OK",
    "EXIT_USAGE",
    "EXTRAS",
    "INTERRUPT_RETRY_S",
    "guarded",
]

EXIT_OK = 0
"""Everything ran and every check passed."""
EXIT_FAILED = 1
"""A check failed (or, for ``check``, a level file has problems)."""
EXIT_USAGE = 2
"""Bad input or environment: a malformed level, an unusable path, a missing optional dependency."""
EXIT_INTERNAL = 3
"""An internal error: a bug of the playground, not of the input (the traceback goes to a file)."""
EXIT_INTERRUPTED = 130
"""Interrupted by Ctrl-C (128 + SIGINT, as shells report it)."""

EXTRAS = {"pygame": "view", "PIL": "view", "matplotlib": "bench"}
"""Optional dependencies by module, and the extra of ``pymunk-playground`` that installs each."""


def guarded(who: str, command: Callable[[], int]) -> int:
    """Run ``command`` (a command's body, returning its exit code) and turn what it raises into
    ``who: message`` on stderr and an exit code; argparse itself exits 2 on a malformed command
    line."""
    try:
        with _interruptible():
            code = command()
            # What is still buffered goes out now, where a closed pipe is caught below, not at
            # the interpreter's exit, which would print its own complaint.
            sys.stdout.flush()
            return code
    except KeyboardInterrupt:
        print(f"{who}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        # The reader went away (``| head``): nothing is left to say to it. Later writes, and the
        # interpreter's own flush at exit, go to the null device instead of failing again.
        _silence_stdout()
        return EXIT_OK
    except (LevelError, UsageError) as exc:
        print(f"{who}: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except ModuleNotFoundError as exc:
        print(f"{who}: {_missing(exc)}", file=sys.stderr)
        return EXIT_USAGE
    except OSError as exc:
        where = f"{exc.filename}: " if exc.filename is not None else ""
        print(f"{who}: {where}{exc.strerror or exc}", file=sys.stderr)
        return EXIT_USAGE
    except Exception as exc:  # the one place a bug becomes one line and exit 3
        where = _write_traceback(who, exc)
        print(
            f"{who}: internal error ({type(exc).__name__}: {_first_line(exc)}); "
            f"the full traceback is in {where}; please report it",
            file=sys.stderr,
        )
        return EXIT_INTERNAL


CRASH_DIR_ENV = "PLAYGROUND_CRASH_DIR"
"""Environment variable: the folder internal errors' tracebacks are written to (default: the
system's temporary folder)."""


def _write_traceback(who: str, exc: BaseException) -> str:
    """Write ``exc``'s full traceback to a new file; its path (or why none could be written)."""
    folder = os.environ.get(CRASH_DIR_ENV) or tempfile.gettempdir()
    stamp = time.strftime("%Y%m%dT%H%M%S")
    text = f"{who}\n" + "".join(traceback.format_exception(exc))
    try:
        fd, path = tempfile.mkstemp(prefix=f"playground-crash-{stamp}-", suffix=".txt", dir=folder)
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(text)
    except OSError as err:
        return f"(nowhere: {folder}: {err.strerror or err})"
    return path


def _first_line(exc: BaseException) -> str:
    lines = str(exc).strip().splitlines()
    return lines[0][:200] if lines else "no message"


def _silence_stdout() -> None:
    """Point stdout at the null device (a closed pipe would fail every later write)."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass


INTERRUPT_RETRY_S = 0.002
"""s before a Ctrl-C that arrived inside a pymunk callback is delivered again."""


def _on_interrupt(signum: int, frame: types.FrameType | None) -> None:
    """Raise KeyboardInterrupt, unless Python is inside a callback called from C through cffi
    (pymunk's, or the playground's own queries'), which would print the exception and drop it:
    then try again in a moment."""
    f = frame
    while f is not None:
        if f.f_globals.get("__name__") == "pymunk._callbacks" or c_callback_code(f.f_code):
            signal.setitimer(signal.ITIMER_REAL, INTERRUPT_RETRY_S)
            return
        f = f.f_back
    raise KeyboardInterrupt


@contextlib.contextmanager
def _interruptible() -> Iterator[None]:
    """Ctrl-C (and its retry timer) through :func:`_on_interrupt` while a command runs.

    A process started with SIGINT ignored (``nohup``, a background job of a script) keeps
    ignoring it.
    """
    if (
        threading.current_thread() is not threading.main_thread()
        or signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    ):
        yield
        return
    previous = {s: signal.signal(s, _on_interrupt) for s in (signal.SIGINT, signal.SIGALRM)}
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        for s, handler in previous.items():
            signal.signal(s, handler)


def _missing(exc: ModuleNotFoundError) -> str:
    """What to install for a missing module."""
    top = (exc.name or "").split(".")[0]
    extra = EXTRAS.get(top)
    if extra is None:
        return f"missing module {top!r} ({exc})"
    package = {"pygame": "pygame-ce", "PIL": "Pillow"}.get(top, top)
    return f"needs {package}: pip install 'pymunk-playground[{extra}]'"
