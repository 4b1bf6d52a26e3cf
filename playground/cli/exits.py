"""Exit codes: every error of a command becomes a one-line message on stderr and a code, here.

0 ok; 1 a check failed (or a level did not validate, for ``check``); 2 bad input or environment
(a malformed level, an unusable path, a missing optional dependency); 130 interrupted (Ctrl-C).
Nothing ends in a traceback. Ctrl-C is caught even when it lands inside a pymunk callback (see
:func:`_on_interrupt`).

>>> def needs_pygame() -> int:
...     raise ModuleNotFoundError("No module named 'pygame'", name="pygame")
>>> guarded("playground play", needs_pygame)  # stderr: needs pygame-ce: pip install '...[view]'
2
"""

from __future__ import annotations

import contextlib
import signal
import sys
import threading
import types
from collections.abc import Callable, Iterator

from playground.cli.preflight import UsageError
from playground.level.errors import LevelError

__all__ = [
    "EXIT_FAILED",
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
            return command()
    except KeyboardInterrupt:
        print(f"{who}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
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


INTERRUPT_RETRY_S = 0.002
"""s before a Ctrl-C that arrived inside a pymunk callback is delivered again."""


def _on_interrupt(signum: int, frame: types.FrameType | None) -> None:
    """Raise KeyboardInterrupt, unless Python is inside a pymunk callback (called from C through
    cffi, which would print the exception and drop it): then try again in a moment."""
    f = frame
    while f is not None:
        if f.f_globals.get("__name__") == "pymunk._callbacks":
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
