"""Shared chart plumbing: a headless matplotlib, PNG and SVG side by side, stable styles.

Every chart states the scene it shows -- the parameter values and the initial state
(:func:`conditions`) -- in a line under its panels (``save(..., caption=...)``), so a
picture read on its own says what was simulated.

Example
-------
>>> import tempfile
>>> from dualmech.problems import get
>>> print(conditions(get("simple_pendulum")))
M = 1 kg, a = 0.8 m, g = 9.81 m/s^2; from theta = 0.5 rad, theta' = 0 rad/s
>>> fig, axes = panels(2, "a title")
>>> with tempfile.TemporaryDirectory() as out:
...     [p.name for p in save(fig, Path(out) / "example", caption="m = 1 kg")]
['example.png', 'example.svg']
"""
from __future__ import annotations

from pathlib import Path

__all__ = ["pyplot", "panels", "save", "METHOD_COLORS", "FORM_STYLES", "style_of",
           "conditions"]

#: One colour per integrator, one line style and marker per formulation (cycled).
METHOD_COLORS = {"RK45": "#1f77b4", "DOP853": "#ff7f0e", "Radau": "#2ca02c", "BDF": "#d62728",
                 "LSODA": "#9467bd", "midpoint": "#8c564b",
                 "IDA": "#e377c2"}
FORM_STYLES = [("-", "o"), ("--", "s"), (":", "^"), ("-.", "D"), ((0, (5, 1)), "v"),
               ((0, (1, 1)), "P"), ((0, (3, 1, 1, 1)), "X"), ((0, (5, 3)), "*")]


def pyplot():
    """matplotlib's pyplot on the non-interactive Agg backend (no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def panels(count: int, title: str, *, width: float = 8.0, height: float = 2.8,
           sharex: bool = True, columns: int = 1):
    """A figure with ``count`` stacked panels; returns ``(fig, [axes...])``."""
    plt = pyplot()
    rows = -(-count // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(width, height * rows + 0.6),
                             sharex=sharex, squeeze=False)
    fig.suptitle(title, fontsize="medium")
    flat = list(axes.flat)
    for ax in flat[count:]:
        ax.set_visible(False)
    return fig, flat[:count]


def save(fig, stem: Path, dpi: int = 110, tight: bool = True,
         caption: str = "") -> list[Path]:
    """Write ``stem.png`` and ``stem.svg`` (folders created) and close the figure;
    ``caption`` (the scene, :func:`conditions`) is written under the panels."""
    stem = Path(stem)
    stem.parent.mkdir(parents=True, exist_ok=True)
    lines = _caption(fig, caption) if caption else 0
    if tight:   # room at the bottom for the caption's lines (0.15 in each)
        fig.tight_layout(rect=(0, min(0.5, (0.15 * lines + 0.05) / fig.get_figheight()), 1, 1))
    out = [stem.with_suffix(".png"), stem.with_suffix(".svg")]
    fig.savefig(out[0], dpi=dpi)
    fig.savefig(out[1])
    pyplot().close(fig)
    return out


def style_of(index: int) -> tuple:
    """``(linestyle, marker)`` of the ``index``-th formulation."""
    return FORM_STYLES[index % len(FORM_STYLES)]


def _caption(fig, text: str) -> int:
    """``text`` along the bottom edge, wrapped to the figure's width; its line count."""
    import textwrap
    lines = textwrap.wrap(text, int(fig.get_figwidth() * 14))
    fig.text(0.01, 0.005, "\n".join(lines), fontsize="x-small", color="0.25", ha="left",
             va="bottom")
    return len(lines)


def conditions(problem, params=None, state=None, t0: float = 0.0, start: bool = True,
               tex: bool = False) -> str:
    """The scene in one line: every parameter's value with its unit (``params`` overriding
    the defaults, by symbol or name), then the initial state in the reference coordinates
    (``state``: ``[q..., q'...]`` or a mapping as ``initial_state`` takes it; default: the
    problem's initial state) -- ``"m = 0.2 kg, ...; from theta = 1.3 rad, theta' = 0 rad/s"``;
    a problem driven by given inputs adds each one's history after the parameters (``"F(t)
    = default: 2*sin(3*t)"``: charts take the declared default, the ``history`` of
    :class:`~dualmech.model.inputs.Input`).  ``start=False`` for the parameters alone (a
    chart over many starts); ``tex=True`` writes each name in mathtext (``$\\theta$``,
    ``$\\dot{\\theta}$``), as a chart's other texts.
    """
    from dualmech.model.notation import mathtext

    def name_of(name: str, order: int = 0) -> str:
        if tex:
            return mathtext(name, order)
        return name + "'" * order
    from dualmech.model.facts import state_vector
    from dualmech.numeric.inputs import describe
    from dualmech.numeric.simulation import default_initial_state, problem_parameters
    from dualmech.numeric.units import rate_unit, unit
    values = problem_parameters(problem, params, check_ranges=False)
    parts = [f"{name_of(p.symbol.name)} = {_number(values[p.symbol])} {unit(p.dimension)}"
             for p in problem.parameters]
    parts += [f"{name_of(name)}(t) = {text}" for name, text in describe(problem).items()]
    if not start:
        return ", ".join(parts)
    coords = list(problem.model(problem.reference).coordinates)
    n = len(coords)
    if state is None:
        q0, qd0 = default_initial_state(problem)
        y0 = list(q0) + list(qd0)
    elif hasattr(state, "items"):
        y0 = state_vector(problem, state, "the chart's state")
    else:
        y0 = [float(v) for v in state]
    info = {c.name: c for c in problem.all_coordinates()}
    start = []
    for i, q in enumerate(coords):
        name = q.func.__name__
        dim = info[name].dimension if name in info else None
        start.append(f"{name_of(name)} = {_number(y0[i])} {unit(dim)}")
    for i, q in enumerate(coords):
        name = q.func.__name__
        dim = info[name].dimension if name in info else None
        start.append(f"{name_of(name, 1)} = {_number(y0[n + i])} {rate_unit(dim)}")
    when = f" at t = {t0:g} s" if t0 else ""
    return ", ".join(parts) + f"; from{when} " + ", ".join(start)


def _number(x: float) -> str:
    return f"{float(x):.4g}"
