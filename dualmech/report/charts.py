"""The report's per-problem chart: the simulated motion and the reactions, one panel per unit.

:func:`trajectory_chart` simulates the problem's reference model over a span that fits its
scene (:func:`~dualmech.numeric.contacts.scene_span`: it stops where a length coordinate
leaves its declared range or a one-sided contact would have to pull) and draws

* one panel per unit of the coordinates (lengths in m, angles in rad, ...), one per unit of
  the reactions (forces in N, torques in N m), each axis labelled with its unit;
* curves that coincide (to 1e-9 of the panel's scale) once, the legend naming all of them;
* reactions that stay zero along the whole motion, and curves that stay constant, not drawn
  but said in words on their panel ("identically zero along the whole motion: ...");
* every name in textbook notation: legends and panel texts in mathtext from the problem's
  symbols (``theta1`` as θ₁, :func:`~dualmech.model.notation.mathtext`), the caption in the
  page's one-line text (:func:`~dualmech.model.notation.symbol_text`).

The notes (:attr:`Chart.notes`) are the chart's caption; the page prints them once, under it
(:attr:`Chart.notes_html`: the same sentences with each name typeset in MathML).

It returns a :class:`Chart` with the paths and the notes, or the reason it could not draw.

Example
-------
>>> import tempfile
>>> from dualmech.problems import get
>>> with tempfile.TemporaryDirectory() as out:
...     print(trajectory_chart(get("block_on_wedge"), Path(out), 5.0).notes[0])
simulated for t in [0, 0.49] s; it stops there because q1 leaves its declared range [0, 2] (distance of the block down the slope, relative to the wedge) at t = 0.49 s
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import html

import numpy as np
import sympy as sp

from dualmech.report.mathml import inline
from dualmech.model.dimensions import ANGLE
from dualmech.model.notation import mathtext, symbol_text
from dualmech.numeric.units import unit

__all__ = ["Chart", "trajectory_chart", "group_curves", "animation_for"]

#: Curves closer than this fraction of their panel's scale are the same curve; a reaction
#: smaller than this fraction of the largest reaction (or of 1 N when all vanish) is zero.
SAME = 1e-9

_KIND = {"m": "position", "rad": "angle", "N": "force", "N m": "torque or moment"}


@dataclass
class Chart:
    """What :func:`trajectory_chart` drew (``paths``, ``notes``) or why not (``error``);
    ``caption`` is the scene line under the panels (parameters and initial states);
    ``panels`` the unit of each panel drawn, top to bottom; ``samples`` the default scene's;
    ``animation`` the GIF of the motion (:mod:`.animation`) or why none
    (``animation_error``).

    ``notes`` are the caption's sentences as text (names in the page's one-line form, ``θ₁``);
    ``notes_html`` the same sentences as HTML, each name typeset (MathML ``<msub>``).
    """

    paths: list = field(default_factory=list)
    notes: list = field(default_factory=list)
    notes_html: list = field(default_factory=list)
    error: str = ""
    span: tuple = ()
    caption: str = ""
    panels: list = field(default_factory=list)
    samples: int = 0
    animation: Path | None = None
    animation_error: str = ""

    def _repr_html_(self) -> str:
        """Jupyter: the picture and its one caption."""
        from dualmech.report.jupyter import chart_html
        return chart_html(self)


def animation_for(problem, chart: Chart, out_dir: Path, duration: float,
                  frames: int = 48) -> None:
    """Draw ``out_dir/NAME_motion.gif`` (:func:`~dualmech.report.animation.animate`) into
    ``chart.animation``, or say in ``chart.animation_error`` why there is none."""
    from dualmech.report.animation import animate
    try:
        a = animate(problem, duration, frames)
        chart.animation = a.save_gif(Path(out_dir) / f"{problem.name}_motion.gif")
    except Exception as exc:  # noqa: BLE001 - the verdicts do not depend on the picture
        chart.animation_error = f"{type(exc).__name__}: {exc}"


def group_curves(names, values, scale: float) -> list[list[str]]:
    """Names grouped by identical curves (max difference <= SAME * scale), first-seen order."""
    groups: list[list] = []
    for name, v in zip(names, values):
        for g in groups:
            if np.abs(values[names.index(g[0])] - v).max() <= SAME * scale:
                g.append(name)
                break
        else:
            groups.append([name])
    return groups


def split_scales(panels, ratio: float = 20.0) -> list:
    """``[(unit, curves)]`` with a panel whose curves' excursions differ more than ``ratio``
    times split in two, the small ones in a panel of their own (same unit), so that a
    bicycle's lean and steer are not flattened under its wheels' spin angles.

    >>> import numpy as np
    >>> t = np.linspace(0, 1, 5)
    >>> out = split_scales([("rad", [("spin", 80 * t), ("lean", 0.1 * np.sin(t)),
    ...                              ("yaw", 0 * t)])])
    >>> [(u, [n for n, _ in c]) for u, c in out]
    [('rad', ['spin', 'yaw']), ('rad', ['lean'])]
    """
    out = []
    for u, curves in panels:
        values = [np.asarray(v, dtype=float) for _, v in curves]
        spans = [float(np.ptp(v)) for v in values]
        top = max(spans, default=0.0)
        flat = SAME * max((float(np.abs(v).max()) for v in values), default=0.0)
        # (a flat curve stays: the panel says it in words, a panel of its own would be empty)
        small = [c for c, s in zip(curves, spans) if flat < s and s * ratio < top]
        big = [c for c in curves if not any(c is x for x in small)]
        out += [(u, big), (u, small)] if big and small else [(u, curves)]
    return out


def _panels(entries, kind_of):
    """``{unit: [(name, values)]}`` in first-seen order."""
    out: dict = {}
    for name, values, dim in entries:
        out.setdefault(kind_of(dim), []).append((name, values))
    return out


def trajectory_chart(problem, out_dir: Path, duration: float, samples: int = 400) -> Chart:
    """Simulate ``problem`` and draw its chart into ``out_dir/NAME_reactions.{png,svg}``:
    its default scene, and the further scenes it declares (``chart_scenes``) dashed on the
    coordinates' panels; the caption under the panels states each scene's parameters and
    initial state."""
    from dualmech.numeric.charts import conditions, pyplot, save
    from dualmech.numeric.inputs import driven_problem
    chart = Chart()
    try:
        problem = driven_problem(problem)   # given inputs: their declared default histories
        span, traj = _simulate(problem, duration, samples)
    except Exception as exc:  # noqa: BLE001 - the verdicts do not depend on the chart
        chart.error = f"simulation failed -- {type(exc).__name__}: {exc}"
        return chart
    chart.span = (span.t0, span.t_end)
    _note(chart, f"simulated for t in [{span.t0:g}, {span.t_end:.3g}] s"
          + (f"; it stops there because {span.reason}" if span.reason else ""))
    extra = _extra_scenes(problem, duration, samples, chart)
    info = {c.name: c for c in problem.all_coordinates()}
    coords = _panels([(n, q, info[n].dimension if n in info else None)
                      for n, q in zip(traj.coordinate_names, traj.q)], _unit)
    rinfo = problem.reaction_info()
    reactions = dict(getattr(traj, "reactions", {}) or {})
    biggest = max((float(np.abs(v).max()) for v in reactions.values()), default=0.0)
    floor = SAME * max(biggest, 1.0)
    zero = [k for k, v in reactions.items() if float(np.abs(v).max()) <= floor]
    if zero:
        _note(chart, *_names(zero, ", "), " = 0 along the whole motion (not drawn)")
    forces = _panels([(k, v, rinfo[k].dimension if k in rinfo else None)
                      for k, v in reactions.items() if k not in zero], _unit)
    # a panel whose every curve stays constant would be an empty box: its values go to the
    # caption instead (the notes _draw writes), and the panel is not drawn
    constants: list = []
    forces = {u: c for u, c in forces.items() if not _all_flat(u, c, chart, constants)}
    plt = pyplot()
    panels = split_scales(list(coords.items())) + list(forces.items())
    chart.panels, chart.samples = [u for u, _ in panels], len(traj.t)
    count = len(panels)
    fig, axes = plt.subplots(count, 1, figsize=(8, 2.4 * count + 0.9), sharex=True,
                             squeeze=False)
    axes = list(axes[:, 0])
    title = f"{problem.name}: {problem.title}"
    if not reactions:
        title += " (no reaction unknowns)"
    elif not forces:
        title += " (reactions constant: below)"
    import textwrap
    fig.suptitle("\n".join(textwrap.wrap(title, 90)), fontsize="medium")
    for ax, (u, curves) in zip(axes, panels):
        said = _draw(ax, u, curves, traj.t, chart, "default scene" if extra else "")
        for (label, t_x, traj_x) in extra:
            _draw_extra(ax, u, curves, traj_x, label)
        if said:
            ax.text(0.5, 0.5, "\n".join(said), transform=ax.transAxes, ha="center",
                    va="center", fontsize="small",
                    bbox={"facecolor": "white", "edgecolor": "0.7", "alpha": 0.9})
        if extra and ax.get_legend_handles_labels()[0]:
            ax.legend(loc="best", fontsize="x-small")
    axes[-1].set_xlabel("t [s]")
    axes[-1].set_xlim(span.t0, max([span.t_end] + [t for _, t, _ in extra]))
    caption = ("solid: " if extra else "") + conditions(problem, tex=True)
    if constants:
        caption += ". Constant along the whole motion (not drawn): " + ", ".join(constants)
    if zero:
        caption += ". Zero along the whole motion (not drawn): " + _tex(zero, ", ")
    for k, (label, _, _) in enumerate(extra):
        caption += f". Dashed{'' if len(extra) == 1 else f' ({k + 1})'}: {label}"
    chart.paths = save(fig, Path(out_dir) / f"{problem.name}_reactions", caption=caption)
    chart.caption = caption
    return chart


#: Samples per period of a periodic drive: fewer would alias a fast oscillation into a
#: slow beat that is not in the motion (two samples per period draw a false envelope).
PER_PERIOD = 24
#: The most samples a chart draws.
MOST_SAMPLES = 20000


def _samples(problem, span, samples: int, params=None) -> int:
    """``samples``, raised to :data:`PER_PERIOD` per period of a periodic drive."""
    from dualmech.numeric.simulation import problem_parameters
    from dualmech.numeric.studies.floquet import NotDriven, forcing_period
    try:
        period = forcing_period(problem.model(problem.reference),
                                problem_parameters(problem, params))
    except (NotDriven, ValueError, TypeError):
        return samples
    wanted = int(np.ceil(PER_PERIOD * (span.t_end - span.t0) / period)) + 1
    return int(min(max(samples, wanted), MOST_SAMPLES))


def _simulate(problem, duration, samples, params=None, y0=None):
    from dualmech.numeric.contacts import scene_span
    from dualmech.numeric.simulation import simulate
    span = scene_span(problem, duration, y0=y0, params=params)
    samples = _samples(problem, span, samples, params)
    traj = simulate(problem, t_span=(span.t0, span.t_end), samples=samples, y0=y0,
                    params=params)
    return span, traj


def _extra_scenes(problem, duration, samples, chart) -> list:
    """``[(label, t_end, trajectory)]`` of the problem's ``chart_scenes``."""
    from dualmech.model.facts import is_declared, state_vector
    from dualmech.numeric.charts import conditions
    out = []
    for scene in getattr(problem, "chart_scenes", ()) or ():
        y0 = state_vector(problem, scene.state, "`ChartScene.state`") \
            if is_declared(scene.state) else None
        try:
            span, traj = _simulate(problem, duration, samples, scene.params, y0)
        except Exception as exc:  # noqa: BLE001 - one scene failing leaves the others
            _note(chart, f"the scene '{scene.why}' could not be simulated -- "
                  f"{type(exc).__name__}: {exc}")
            continue
        label = f"{scene.why} ({conditions(problem, scene.params, y0)})"   # page text
        _note(chart, f"dashed: {label}, simulated for t in [{span.t0:g}, {span.t_end:.3g}] s"
              + (f"; it stops there because {span.reason}" if span.reason else ""))
        out.append((scene.why, span.t_end, traj))
    return out


def _draw_extra(ax, u: str, curves, traj, label: str) -> None:
    """A further scene's curves of this panel's coordinates, dashed."""
    names = {n for n, _ in curves}
    for n, q in zip(traj.coordinate_names, traj.q):
        if n in names:
            ax.plot(traj.t, q, linestyle="--", linewidth=1.1, label=f"{mathtext(n)}: {label}")


def _all_flat(u: str, curves, chart: Chart, constants: list) -> bool:
    """Whether every curve of a panel stays constant; if so, say their values in the
    caption and in ``constants`` (the panel is then not drawn)."""
    values = [np.asarray(v, dtype=float) for _, v in curves]
    scale = max((float(np.abs(v).max()) for v in values), default=0.0) or 1.0
    if any(np.ptp(v) > SAME * scale for v in values):
        return False
    for name, v in curves:
        constants.append(f"{_tex([name])} = {float(np.asarray(v)[0]):.4g} {u}")
        _note(chart, sp.Symbol(name) if _symbolic(name) else name,
              f" stays at {float(np.asarray(v)[0]):.4g} {u} (not drawn)")
    return True


def _unit(dimension) -> str:
    if dimension is None:
        return "?"
    return "rad" if dimension == ANGLE else unit(dimension)


def _tex(names, sep: str = "") -> str:
    """Names as chart text: each one in mathtext (``$\\theta_{1}$``), joined by ``sep``."""
    return sep.join(mathtext(n) for n in names)


def _names(names, sep: str) -> list:
    """Caption parts: each name as a symbol (text stays text), ``sep`` between them."""
    parts: list = []
    for i, n in enumerate(names):
        parts += ([sep] if i else []) + [sp.Symbol(n) if _symbolic(n) else n]
    return parts


def _note(chart: Chart, *parts) -> None:
    """One sentence of the caption from text and symbols: as text (``θ₁``, the page's
    one-line form) and as HTML (text escaped, each symbol typeset)."""
    chart.notes.append("".join(symbol_text(p.name) if isinstance(p, sp.Symbol) else p
                               for p in parts))
    chart.notes_html.append("".join(inline(p) if isinstance(p, sp.Symbol) else html.escape(p)
                                    for p in parts))


def _symbolic(name: str) -> bool:
    """Is ``name`` a symbol's name (what :func:`mathtext` typesets)?"""
    return mathtext(name).startswith("$")


def _draw(ax, u: str, curves, t, chart: Chart, scene: str = "") -> list[str]:
    """Draw the curves of one panel; return what the panel must say in words instead of
    drawing it (curves that stay constant along the whole motion)."""
    names = [n for n, _ in curves]
    values = [np.asarray(v, dtype=float) for _, v in curves]
    scale = max((float(np.abs(v).max()) for v in values), default=0.0) or 1.0
    kind = _KIND.get(u, "value")
    ax.set_ylabel(f"{kind} [{u}]")
    said, drawn = [], 0
    groups = group_curves(names, values, scale)
    # a panel of flat lines only is drawn as flat lines (never an empty box)
    flat_only = all(np.ptp(values[names.index(g[0])]) <= SAME * scale for g in groups)
    for group in groups:
        v = values[names.index(group[0])]
        label = _tex(group) if len(group) == 1 else f"{_tex(group, ' = ')} (identical)"
        if len(group) > 1:
            _note(chart, *_names(group, " and "), " coincide along the whole motion "
                  "(drawn once)")
        if flat_only:
            label += f" = {v[0]:.4g} {u} (constant)"
            _note(chart, *_names(group, " = "), f" stays at {v[0]:.4g} {u} (drawn flat: "
                  "nothing on its panel varies)")
        elif np.ptp(v) <= SAME * scale:      # a flat line beside curves: say its value
            said.append(f"{_tex(group, ' = ')} = {v[0]:.4g} {u}, constant along the whole "
                        "motion")
            _note(chart, *_names(group, " = "), f" stays at {v[0]:.4g} {u} (not drawn)")
            continue
        ax.plot(t, v, label=f"{label}: {scene}" if scene else label, linewidth=1.3)
        drawn += 1
    ax.grid(True, alpha=0.3)
    if drawn:   # many curves (a bicycle's 21 reactions): the legend in columns beside them
        ax.legend(loc="best" if drawn <= 6 else "center left", fontsize="small",
                  ncol=1 if drawn <= 6 else -(-drawn // 8),
                  bbox_to_anchor=None if drawn <= 6 else (1.01, 0.5))
    else:
        ax.set_yticks([])
    return said
