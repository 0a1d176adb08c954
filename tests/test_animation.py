"""Animations of the motion (dualmech.report.animation), checked against hand facts.

References, by hand: the simple pendulum's bob is at ``(a sin theta, -a cos theta)`` and the
string pulls it towards the pivot with ``T = M (g cos theta + a theta'^2)`` (radial
``sum F = m a``); Kapitza's pivot moves as ``(0, a cos(Omega t))``.
"""
import io

import numpy as np
import pytest
from PIL import Image

from dualmech.problems import get
from dualmech.report import write_report
from dualmech.report.animation import DPI, MOST_FRAMES, animate
from dualmech.verify.check import compare


@pytest.fixture(scope="module")
def pendulum():
    return animate(get("simple_pendulum"), duration=2.0, frames=24)


def test_the_bob_and_the_string_force_arrow_follow_the_hand_solution(pendulum):
    from dualmech.numeric.simulation import simulate
    traj = simulate(get("simple_pendulum"), t_span=(0.0, pendulum.t[-1]), samples=24)
    th, thd = traj.q[0], traj.qd[0]
    M, a, g = 1.0, 0.8, 9.81                         # problems/simple_pendulum.py defaults
    bob = pendulum.xy[pendulum.names.index("bob")]
    assert bob[0] == pytest.approx(a * np.sin(th), abs=1e-12)
    assert bob[1] == pytest.approx(-a * np.cos(th), abs=1e-12)
    T = M * (g * np.cos(th) + a * thd**2)
    towards_pivot = -bob / a
    assert pendulum.arrows == ["T"]
    assert pendulum.forces[0] == pytest.approx(T * towards_pivot, rel=1e-9, abs=1e-9)


def test_the_gif_is_bounded_and_has_every_frame(pendulum, tmp_path):
    path = pendulum.save_gif(tmp_path / "p.gif")
    im = Image.open(path)
    assert im.n_frames == 24
    assert max(im.size) <= (pendulum.inches + 0.6) * DPI + 1
    assert path.stat().st_size < 300_000
    html = pendulum._repr_html_()
    assert html.startswith("<figure><img") and "data:image/gif;base64," in html
    assert "<script" not in html


def test_sizes_past_the_bounds_are_refused():
    with pytest.raises(ValueError, match="`frames` must be between 2 and"):
        animate(get("simple_pendulum"), frames=MOST_FRAMES + 1)


def test_a_declared_drawing_joins_its_points():
    a = animate(get("kapitza_pendulum"), duration=0.1, frames=11)
    assert a.lines == (("pivot", "bob"),)
    pivot = a.xy[a.names.index("pivot")]
    assert pivot[0] == pytest.approx(0.0, abs=1e-15)
    assert pivot[1] == pytest.approx(0.01 * np.cos(80 * np.pi * a.t), abs=1e-12)
    # the rod's force is drawn at the bob (a point kept for the arrow, not drawn twice)
    at = a.arrow_at[0]
    assert at in a.hidden
    # 2 pi / (80 pi) = 0.025 s between pushes, 0.01 s between frames: faster than 4 frames
    assert a.notes and "the drive's period (0.025 s)" in a.notes[0]
    assert a.xy[at] == pytest.approx(a.xy[a.names.index("bob")], abs=1e-12)


def test_the_report_embeds_the_animation(tmp_path):
    written = write_report([compare(get("simple_pendulum"))], tmp_path, 1.0, progress=False)
    page = written.html.read_text(encoding="utf-8")
    assert page.count('src="data:image/gif;base64,') == 1
    assert "simple_pendulum_motion.gif" in written.markdown.read_text()
    frames = Image.open(io.BytesIO((tmp_path / "simple_pendulum_motion.gif").read_bytes()))
    assert frames.n_frames == 48


def test_bad_drawings_and_scenes_are_refused_saying_what_to_fix():
    from dualmech import ChartScene, Drawing
    with pytest.raises(TypeError, match="non-empty dict"):
        Drawing({})
    with pytest.raises(ValueError, match=r"names \['tip'\]"):
        Drawing({"O": (0, 0), "bob": (1, 0)}, lines=(("O", "tip"),))
    with pytest.raises(ValueError, match="two of"):
        Drawing({"O": (0, 0)}, view=("x", "w"))
    with pytest.raises(TypeError, match=r"`ChartScene.params\['Omega'\]` must be a number"):
        ChartScene({"Omega": "fast"})
