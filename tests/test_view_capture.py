"""Pictures out of `playground play`: animated GIFs and screenshots at any size, and bad output
options refused with one line and exit code 2 before anything runs — never a traceback, never a
half-written file."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PIL import Image, ImageChops

from playground.cli import main
from playground.view.capture import GifWriter


def _play(args: list[str]) -> int:
    return main(["play", "--headless", *args])


def test_gif_holds_one_frame_in_three_at_the_asked_size_and_moves(tmp_path: Path) -> None:
    """Law: `--frames N --gif F --size WxH` writes a looping GIF of ceil(N/3) frames (20 fps of
    60 Hz frames) of W×H px whose frames are not all the same picture."""
    out = tmp_path / "run.gif"
    assert _play(["moving_platform", "--frames", "30", "--size", "320x200", "--gif", str(out)]) == 0
    with Image.open(out) as gif:
        assert gif.format == "GIF"
        assert gif.size == (320, 200)
        assert gif.n_frames == 10
        assert gif.info["duration"] == 50
        assert gif.info["loop"] == 0
        gif.seek(0)
        first = gif.convert("RGB")
        gif.seek(gif.n_frames - 1)
        last = gif.convert("RGB")
    assert ImageChops.difference(first, last).getbbox() is not None


def test_screenshot_has_the_asked_size(tmp_path: Path) -> None:
    """Law: `--size WxH` sets the off-screen surface, so the screenshot is W×H px."""
    out = tmp_path / "shot.png"
    assert _play(["rest", "--frames", "1", "--size", "300x170", "--screenshot", str(out)]) == 0
    with Image.open(out) as shot:
        assert shot.size == (300, 170)


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["--size", "0x0"], "--size: expected WIDTHxHEIGHT"),
        (["--size=-640x360"], "--size: expected WIDTHxHEIGHT"),
        (["--size", "640x-360"], "--size: expected WIDTHxHEIGHT"),
        (["--size", "100000x100000"], "--size: expected WIDTHxHEIGHT"),
        (["--size", "640 by 360"], "--size: expected WIDTHxHEIGHT"),
        (["--gif", "{tmp}/missing/run.gif"], "--gif: folder"),
        (["--gif", "{tmp}/run.png"], "--gif: expected a file name ending in .gif"),
        (["--screenshot", "{tmp}/shot.webp"], "--screenshot: '"),
        (["--screenshot", "{tmp}/shot"], "unknown picture type"),
        (["--screenshot", "{tmp}/missing/shot.png"], "--screenshot: folder"),
        (["--frames", "0", "--gif", "{tmp}/run.gif"], "--gif: needs at least one frame"),
    ],
)
def test_bad_output_options_are_one_line_exit_2_and_write_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], args: list[str], expected: str
) -> None:
    """Law: a bad --size, --gif or --screenshot gets one line on stderr naming the option and
    exit code 2, before any frame runs: the folder stays empty (no file, no temporary)."""
    args = [a.replace("{tmp}", str(tmp_path)) for a in args]
    code = _play(["rest", "--frames", "5", *args])
    err = capsys.readouterr().err
    assert code == 2
    assert expected in err
    assert len(err.strip().splitlines()) == 1, err
    assert "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_a_failed_gif_write_leaves_no_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Law: a GIF whose encoding fails half-way leaves neither the file nor its temporary."""
    import pygame

    pygame.display.init()
    writer = GifWriter(every=1)
    for shade in (0, 128, 255):
        surface = pygame.Surface((16, 16))
        surface.fill((shade, shade, shade))
        writer.offer(surface)
    real_save = Image.Image.save

    def failing_save(self: Image.Image, fp: object, *args: object, **kwargs: object) -> None:
        real_save(self, fp, *args, **kwargs)  # type: ignore[arg-type]
        raise OSError("disk full")

    monkeypatch.setattr(Image.Image, "save", failing_save)
    with pytest.raises(OSError, match="disk full"):
        writer.save(tmp_path / "run.gif")
    assert list(tmp_path.iterdir()) == []


def test_gifs_command_writes_one_gif_per_sequence_at_the_gallery_size(tmp_path: Path) -> None:
    """Law: `playground gifs LEVEL --out DIR` writes DIR/LEVEL.gif: the level's scripted
    seconds at FPS frames per second, SIZE pixels, looping."""
    from playground.level import find, load
    from playground.view.gallery import FPS, SIZE

    assert main(["gifs", "null_enemy", "--out", str(tmp_path / "gifs")]) == 0
    seconds = load(find("null_enemy")).settings.seconds
    with Image.open(tmp_path / "gifs" / "null_enemy.gif") as gif:
        assert gif.size == SIZE
        assert gif.n_frames == round(seconds * FPS) + 1
        assert gif.info["duration"] == round(1000 / FPS)


def test_docs_embed_every_sequence_gif_and_only_gifs_the_gallery_makes() -> None:
    """Law: the README and the teaching chapters show each seed sequence's GIF, every GIF they
    embed is one `playground gifs` makes, and it is committed."""
    from playground.view.gallery import SEQUENCES

    root = Path(__file__).resolve().parent.parent
    gif = re.compile(r"!\[[^\]]*\]\((?:\.\./)?(?:docs/)?img/gifs/([^)]+)\.gif\)")
    readme = set(gif.findall((root / "README.md").read_text(encoding="utf-8")))
    chapters: set[str] = set()
    for path in sorted((root / "docs" / "chapters").glob("*.md")):
        chapters |= set(gif.findall(path.read_text(encoding="utf-8")))
    assert readme == set(SEQUENCES)
    assert chapters == set(SEQUENCES)
    for name in SEQUENCES:
        with Image.open(root / "docs" / "img" / "gifs" / f"{name}.gif") as shown:
            assert shown.format == "GIF" and shown.n_frames > 1
