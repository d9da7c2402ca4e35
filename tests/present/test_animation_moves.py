"""The animation moves the mechanism's artists in place (cams.present.mechanism's ``move``): after a move to a cam
angle, every artist holds what a fresh drawing at that angle holds."""

from __future__ import annotations

import numpy as np
import pytest

from cams.cam import Cam
from tests.conftest import EXAMPLES


def _data(ax) -> list[np.ndarray]:
    """What each artist of ``ax`` draws: a line's points, a polygon's vertices, a circle's centre and radius."""
    out = []
    for a in [*ax.patches, *ax.lines]:
        if hasattr(a, "get_xydata"):
            out.append(np.asarray(a.get_xydata(), float))
        elif hasattr(a, "get_xy") and not hasattr(a, "get_radius"):
            out.append(np.asarray(a.get_xy(), float))
        else:
            out.append(np.array([*a.get_center(), a.get_radius()], float))
    return out


@pytest.mark.parametrize(
    "example", ["rocker_force.toml", "translating_flat.toml", "rocker_flat.toml", "translating_force.toml"]
)
def test_move_draws_what_a_fresh_drawing_draws(example):
    from matplotlib.figure import Figure

    from cams.present.faces import presenter

    cam = Cam.from_file(EXAMPLES / example)
    draw = presenter(cam).draw_mechanism
    phi0, phi1 = 0.3, 2.1  # radians, inside different phases
    moved_ax = Figure().add_subplot()
    move = draw(moved_ax, cam, cam.profile, phi0)
    before = _data(moved_ax)
    moved = move(phi1)
    fresh_ax = Figure().add_subplot()
    draw(fresh_ax, cam, cam.profile, phi1)
    after, fresh = _data(moved_ax), _data(fresh_ax)
    assert len(after) == len(fresh)
    for x, y in zip(after, fresh, strict=True):
        np.testing.assert_allclose(x, y, rtol=0, atol=1e-12)
    # the artists that move are the ones whose data changed, and the cam itself is among them
    changed = [not np.array_equal(x, y) for x, y in zip(before, after, strict=True)]
    assert sum(changed) == len(moved) >= 3


def test_one_palette_keeps_every_frame_close_to_what_was_drawn(tmp_path, monkeypatch):
    """The GIF's frames (one palette for the turn, cams.present.plots._paletted) against the frames as drawn
    (RGBA, taken before the palette): the same size and count, no pixel off by more than a few levels on average,
    and the colours of the drawing (its lines and fills, fully saturated or not) kept to within a small distance."""
    from PIL import Image, ImageSequence

    from cams.present import plots

    drawn = []
    real = plots._paletted

    def keep(images, **kw):
        drawn.extend(np.asarray(im.convert("RGB"), float) for im in images)
        return real(images, **kw)

    monkeypatch.setattr(plots, "_paletted", keep)
    cam = Cam.from_file(EXAMPLES / "rocker_force.toml")
    path = plots.animate_profile(cam, tmp_path / "turn.gif", frames=12)
    with Image.open(path) as im:
        shown = [np.asarray(f.convert("RGB"), float) for f in ImageSequence.Iterator(im)]
    assert len(shown) == len(drawn) == 12
    for a, b in zip(drawn, shown, strict=True):
        assert a.shape == b.shape
        err = np.abs(a - b).max(axis=-1)
        assert err.mean() < 1.0  # of 255 levels
        assert np.quantile(err, 0.999) < 16 and err.max() < 32
    assert shown[0][2, 2].tolist() == [255.0, 255.0, 255.0]  # the background's white, exact


@pytest.mark.parametrize("example", ["rocker_force.toml", "translating_flat.toml"])
def test_the_turn_has_no_empty_band_above_or_below(tmp_path, example):
    """A wide view (a rocker's arm) on a square frame left a fifth of each frame blank above and below it: the
    frame's height now fits the view. Measured on the pixels of the GIF's first frame: the rows with no drawn
    pixel at the top and at the bottom are few."""
    from PIL import Image

    from cams.present import plots

    cam = Cam.from_file(EXAMPLES / example)
    path = plots.animate_profile(cam, tmp_path / "turn.gif", frames=2)
    frame = np.asarray(Image.open(path).convert("L"))
    drawn = np.flatnonzero((frame < 250).any(axis=1))
    top, bottom = drawn[0], len(frame) - 1 - drawn[-1]
    assert top + bottom <= 0.05 * len(frame), (top, bottom, frame.shape)
