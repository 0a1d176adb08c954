"""Animations of the motion, with the reaction forces drawn as arrows.

:func:`animate` simulates the problem's reference model over a span that fits its scene
(:func:`~dualmech.numeric.contacts.scene_span`), places the problem's points in the ground
frame (:func:`~dualmech.numeric.scene.scene`: the problem's declared
:class:`~dualmech.model.drawing.Drawing`, else the direct form's mass centres and reaction
points) and draws, frame by frame, the lines and points of the drawing, a faint trail of
each moving point, and each reaction force as an arrow at its point along its declared
direction -- its length proportional to the force (one scale for all of them, stated in the
legend with each force's largest value).  The caption states the parameters and the start.

An :class:`Animation` saves itself as a GIF (the static picture drawn once, the moving
artists blitted over it frame by frame, the frames written by Pillow: an ``<img>`` the report
embeds, no script), shows itself in Jupyter as that GIF, and gives an HTML5 player with
controls on demand (:meth:`Animation.to_jshtml`, matplotlib's ``FuncAnimation``).  It stays small: at most :data:`MOST_FRAMES` frames of at most
:data:`MOST_INCHES` inches at :data:`DPI` dots per inch.

Example
-------
>>> import tempfile
>>> from dualmech.problems import get
>>> a = animate(get("simple_pendulum"), duration=1.0, frames=8)
>>> a.frames, a.arrows
(8, ['T'])
>>> with tempfile.TemporaryDirectory() as out:
...     a.save_gif(Path(out) / "pendulum.gif").suffix
'.gif'
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Mapping

import numpy as np

__all__ = ["Animation", "animate", "MOST_FRAMES", "MOST_INCHES", "DPI"]

#: Bounds that keep an animation small (a report embeds it).
MOST_FRAMES, MOST_INCHES, DPI = 120, 6.0, 72
#: The longest arrow, as a fraction of the scene's extent.
ARROW = 0.3
_COLORS = ["#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b"]


@dataclass
class Animation:
    """A motion ready to draw: ``t`` (frames), ``xy`` (``(points, 2, frames)`` in the view),
    ``forces`` (``(arrows, 2, frames)`` in N), the scene's ``names``, ``lines`` and
    ``arrows`` (reaction names at ``arrow_at`` points), axis names and the caption."""

    problem: str
    title: str
    t: np.ndarray
    xy: np.ndarray
    names: list
    lines: tuple
    arrows: list
    arrow_at: list
    forces: np.ndarray
    axes: tuple
    caption: str
    inches: float = 4.0
    notes: list = field(default_factory=list)
    hidden: list = field(default_factory=list)

    @property
    def frames(self) -> int:
        return int(self.t.size)

    def _setup(self):
        """``(figure, draw)``: the static picture, and ``draw(k)`` that moves the artists
        to frame ``k`` and returns them."""
        from dualmech.model.notation import mathtext
        from dualmech.numeric.charts import pyplot
        plt = pyplot()
        fig, ax = plt.subplots(figsize=(self.inches, self.inches + 0.6))
        fig.suptitle(f"{self.problem}: {self.title}", fontsize="small")
        (x0, x1), (y0, y1) = self._limits()
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect("equal")
        ax.set_xlabel(f"{self.axes[0]} [m]", fontsize="small")
        ax.set_ylabel(f"{self.axes[1]} [m]", fontsize="small")
        ax.tick_params(labelsize="x-small")
        ax.grid(True, alpha=0.3)
        shown = [i for i in range(len(self.names)) if i not in self.hidden]
        moving = [i for i in shown if np.ptp(self.xy[i], axis=1).max() > 0]
        trails = [ax.plot([], [], color="0.75", linewidth=0.8)[0] for _ in moving]
        segs = [ax.plot([], [], color="0.2", linewidth=2.0)[0] for _ in self.lines]
        dots = ax.plot([], [], "o", color="#1f4e9c", markersize=6)[0]
        labels = [ax.text(0, 0, " " + mathtext(self.names[i]), fontsize="x-small",
                          color="0.3") for i in shown]
        scale = self._scale()
        quiver = None
        if self.arrows:
            colors = [_COLORS[k % len(_COLORS)] for k in range(len(self.arrows))]
            quiver = ax.quiver(*self._arrow_field(0, scale), angles="xy", scale_units="xy",
                               scale=1, color=colors, width=0.012)
            for k, name in enumerate(self.arrows):
                peak = float(np.linalg.norm(self.forces[k], axis=0).max())
                ax.plot([], [], color=colors[k], linewidth=3,
                        label=f"{mathtext(name)} (largest {peak:.3g} N)")
            ax.legend(fontsize="x-small", loc="upper right")
        clock = ax.text(0.02, 0.95, "", transform=ax.transAxes, fontsize="small")
        if self.caption:
            import textwrap
            fig.text(0.01, 0.005, "\n".join(textwrap.wrap(self.caption, int(self.inches * 12))),
                     fontsize=6.5, color="0.25", va="bottom")
        fig.tight_layout(rect=(0, 0.1 if self.caption else 0, 1, 1))
        moved = trails + segs + [dots] + labels + ([quiver] if quiver else []) + [clock]
        for a in moved:
            a.set_animated(True)

        def draw(k):
            for trail, i in zip(trails, moving):
                trail.set_data(self.xy[i, 0, : k + 1], self.xy[i, 1, : k + 1])
            for seg, chain in zip(segs, self.lines):
                idx = [self.names.index(n) for n in chain]
                seg.set_data(self.xy[idx, 0, k], self.xy[idx, 1, k])
            dots.set_data(self.xy[shown, 0, k], self.xy[shown, 1, k])
            for i, lab in zip(shown, labels):
                lab.set_position((self.xy[i, 0, k], self.xy[i, 1, k]))
            if quiver is not None:
                X, Y, U, V = self._arrow_field(k, scale)
                quiver.set_offsets(np.column_stack([X, Y]))
                quiver.set_UVC(U, V)
            clock.set_text(f"t = {self.t[k]:.2f} s")
            return moved
        return fig, draw

    def _interval(self) -> float:
        """Milliseconds per frame: real time, within 30 ms (33 fps) and 1 s."""
        step = float(np.median(np.diff(self.t))) if self.frames > 1 else 0.1
        return float(min(1000.0, max(30.0, 1000 * step)))

    def images(self) -> list:
        """The frames as PIL images: the static picture drawn once, the moving artists
        drawn over it frame by frame (blitting)."""
        from PIL import Image
        from dualmech.numeric.charts import pyplot
        fig, draw = self._setup()
        try:
            fig.set_dpi(DPI)
            canvas = fig.canvas
            canvas.draw()
            background = canvas.copy_from_bbox(fig.bbox)
            out = []
            for k in range(self.frames):
                canvas.restore_region(background)
                for artist in draw(k):
                    fig.draw_artist(artist)
                rgba = np.asarray(canvas.buffer_rgba())
                out.append(Image.fromarray(rgba[..., :3].copy()))
            return out
        finally:
            pyplot().close(fig)

    def gif_bytes(self) -> bytes:
        """The animation as GIF bytes (looping)."""
        import io
        frames = [im.convert("P", palette=1, colors=64) for im in self.images()]
        buf = io.BytesIO()
        frames[0].save(buf, format="GIF", save_all=True, append_images=frames[1:],
                       duration=int(self._interval()), loop=0, optimize=True)
        return buf.getvalue()

    def figure(self):
        """``(figure, FuncAnimation)`` of the motion (the figure stays open: close it)."""
        from matplotlib.animation import FuncAnimation
        fig, draw = self._setup()
        return fig, FuncAnimation(fig, draw, frames=self.frames, interval=self._interval(),
                                  blit=False)

    def _limits(self):
        lo, hi = self.xy.min(axis=(0, 2)), self.xy.max(axis=(0, 2))
        size = float(max(hi - lo)) or 1.0
        mid = (lo + hi) / 2
        half = size / 2 * (1 + 2 * ARROW) + 0.05 * size
        return (mid[0] - half, mid[0] + half), (mid[1] - half, mid[1] + half)

    def _scale(self) -> float:
        """Metres per newton: the largest force is :data:`ARROW` of the scene's extent."""
        if not self.arrows:
            return 0.0
        lo, hi = self.xy.min(axis=(0, 2)), self.xy.max(axis=(0, 2))
        size = float(max(hi - lo)) or 1.0
        peak = float(np.linalg.norm(self.forces, axis=1).max())
        return ARROW * size / peak if peak > 0 else 0.0

    def _arrow_field(self, k: int, scale: float):
        at = self.xy[self.arrow_at, :, k]
        return at[:, 0], at[:, 1], scale * self.forces[:, 0, k], scale * self.forces[:, 1, k]

    def save_gif(self, path: Path) -> Path:
        """Write the animation as a looping GIF to ``path``; returns ``path``."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(self.gif_bytes())
        return path

    def to_jshtml(self) -> str:
        """An HTML5 player with controls (matplotlib's ``to_jshtml``), for Jupyter."""
        from dualmech.numeric.charts import pyplot
        fig, anim = self.figure()
        try:
            return anim.to_jshtml(default_mode="loop")
        finally:
            pyplot().close(fig)

    def html(self) -> str:
        """The animation as an ``<img>`` of an embedded GIF, with its caption's notes (no
        script: what the report's page and Jupyter both show)."""
        import base64
        import html as _html
        data = base64.b64encode(self.gif_bytes()).decode("ascii")
        alt = _html.escape(f"{self.problem}: the motion, reaction forces as arrows")
        notes = "".join(f"<br>{_html.escape(n)}" for n in self.notes)
        return (f'<figure><img alt="{alt}" src="data:image/gif;base64,{data}">'
                f"<figcaption>the motion; reaction forces as arrows, one scale for all"
                f"{notes}</figcaption></figure>")

    def _repr_html_(self) -> str:
        return self.html()


def animate(problem, duration: float = 5.0, frames: int = 60, params: Mapping | None = None,
            y0=None, inches: float = 4.0) -> Animation:
    """The :class:`Animation` of ``problem``'s motion (see the module docstring) over at most
    ``duration`` seconds, in ``frames`` frames; ``params`` and ``y0`` as for
    :func:`~dualmech.numeric.simulation.simulate`.  Raises ``ValueError`` past the size bounds
    and :class:`~dualmech.numeric.scene.NoScene` when there is nothing to draw."""
    from dualmech.numeric.charts import conditions
    from dualmech.numeric.contacts import scene_span
    from dualmech.numeric.inputs import driven_problem
    from dualmech.numeric.scene import scene
    from dualmech.numeric.simulation import simulate
    if not 2 <= frames <= MOST_FRAMES:
        raise ValueError(f"`frames` must be between 2 and {MOST_FRAMES}, got {frames}.")
    if not 1.0 <= inches <= MOST_INCHES:
        raise ValueError(f"`inches` must be between 1 and {MOST_INCHES}, got {inches}.")
    if not duration > 0:
        raise ValueError(f"`duration` must be positive, got {duration!r}.")
    problem = driven_problem(problem)   # given inputs: their declared default histories
    sc = scene(problem, params)
    span = scene_span(problem, duration, y0=y0, params=params)
    traj = simulate(problem, t_span=(span.t0, span.t_end), samples=frames, y0=y0,
                    params=params)
    Y = np.vstack([traj.q, traj.qd])
    P = sc.positions(traj.t, Y)
    i, j = sc.view_axes(traj.t, Y)
    D = sc.directions(traj.t, Y)
    names = [a.reaction for a in sc.arrows]
    values = np.array([np.asarray(traj.reactions.get(n, np.zeros(traj.t.size)), dtype=float)
                       for n in names]).reshape(len(names), traj.t.size)
    forces = (D * values[:, None, :])[:, [i, j], :] if names else np.zeros((0, 2, traj.t.size))
    notes = [f"stops at t = {span.t_end:.3g} s: {span.reason}"] if span.reason else []
    notes += _strobe(problem, params, traj.t)
    caption = conditions(problem, params, None if y0 is None else y0, tex=True)
    return Animation(problem.name, problem.title, traj.t, P[:, [i, j], :], list(sc.names),
                     sc.lines, names, [a.at for a in sc.arrows], forces,
                     ("xyz"[i], "xyz"[j]), caption, inches, notes, sorted(sc.hidden))


def _strobe(problem, params, t) -> list[str]:
    """A note when a periodic drive is faster than the frames: the arrows then show the
    forces at the frames' instants, not their oscillation (a stroboscope)."""
    from dualmech.numeric.simulation import problem_parameters
    from dualmech.numeric.studies.floquet import NotDriven, forcing_period
    try:
        period = forcing_period(problem.model(problem.reference),
                                problem_parameters(problem, params))
    except (NotDriven, ValueError, TypeError):
        return []
    gap = float(np.median(np.diff(t))) if t.size > 1 else 0.0
    if gap <= period / 4:
        return []
    return [f"the drive's period ({period:.3g} s) is shorter than four frames' spacing "
            f"({gap:.3g} s): the arrows show the forces at the frames' instants, not their "
            "oscillation -- see the chart for that"]
