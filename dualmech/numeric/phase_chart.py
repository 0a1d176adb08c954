"""The chart of a run across contact phases (:func:`~dualmech.numeric.phases.simulate_phases`).

:func:`phase_series` gives what the chart shows: each coordinate, rate (``name'``), reaction
and given input over every phase that has it, with NaN between phases (a curve is broken at
a switch, where the next model takes over).  :func:`phase_chart` draws it for a teacher:
each phase's span shaded and named (its problem's title), the coordinates above with their
units, the reactions of each phase below with the given inputs that drive the run (dashed),
each switch a dashed line with the reaction that reached zero, and where the run ended
early a dotted line with what ended it; the sentences (what happens at each switch, why
the run ends) under the panels.

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.numeric.phases import simulate_phases
>>> series = phase_series(simulate_phases(get("simple_pendulum"), (0, 1), samples=3))
>>> series["theta"][0].tolist(), series["switches"]
([0.0, 0.5, 1.0], [])
"""
from __future__ import annotations

import textwrap

import numpy as np

__all__ = ["phase_series", "phase_chart"]


def phase_series(run) -> dict:
    """``{name: (times, values)}`` of every coordinate, rate (``name'``), reaction and given
    input over the phases that have it (NaN between them), with ``"switches"``: the switch
    times."""
    out: dict = {}
    for ph in run.phases:
        tr = ph.trajectory
        rows = {n: tr.q[i] for i, n in enumerate(tr.coordinate_names)}
        rows.update({f"{n}'": tr.qd[i] for i, n in enumerate(tr.coordinate_names)})
        rows.update(tr.reactions)
        rows.update(ph.inputs)
        for name, values in rows.items():
            ts, vs = out.setdefault(name, ([], []))
            if ts:
                ts.append(np.nan)
                vs.append(np.nan)
            ts.extend(tr.t.tolist())
            vs.extend(np.asarray(values, dtype=float).tolist())
    series = {k: (np.array(t), np.array(v)) for k, (t, v) in out.items()}
    series["switches"] = [s.time for s in run.switches]
    return series


def phase_chart(run, path, title: str = "") -> str:
    """Draw ``run`` (see the module docstring); write the PNG to ``path``, return its path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    series = phase_series(run)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    _spans(run, top, bottom)
    _curves(run, series, top, bottom)
    _events(run, top, bottom)
    top.set_ylabel("coordinates")
    driven = any(ph.inputs for ph in run.phases)
    bottom.set_ylabel("reactions, given inputs" if driven else "reactions")
    bottom.set_xlabel("t (s)")
    for ax in (top, bottom):
        if ax.get_legend_handles_labels()[0]:
            ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    fig.suptitle(title or " -> ".join(ph.problem for ph in run.phases) or "no phase ran",
                 fontsize=10)
    notes = _notes(run)
    fig.tight_layout(rect=(0, 0.035 * len(notes), 1, 1))
    for i, line in enumerate(notes):
        fig.text(0.01, 0.035 * (len(notes) - i) - 0.025, line, fontsize=8, va="bottom")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return str(path)


def _spans(run, top, bottom) -> None:
    """Each phase's span shaded (every other one) and named above the top panel."""
    for i, ph in enumerate(run.phases):
        t = ph.trajectory.t
        a, b = float(t[0]), float(t[-1])
        if i % 2:
            for ax in (top, bottom):
                ax.axvspan(a, b, color="0.92", zorder=0)
        top.annotate(f"phase {i + 1}: {ph.title or ph.problem}", ((a + b) / 2, 1.01),
                     xycoords=("data", "axes fraction"), ha="center", va="bottom", fontsize=8)


def _curves(run, series, top, bottom) -> None:
    """Coordinates above, reactions below (solid), given inputs below (dashed), each named
    with its unit."""
    kinds, units = {}, {}
    for ph in run.phases:
        kinds.update({k: "reaction" for k in ph.trajectory.reactions})
        kinds.update({k: "input" for k in ph.inputs})
        units.update(ph.units)
    for name, tv in series.items():
        if name == "switches" or name.endswith("'"):
            continue
        kind = kinds.get(name, "coordinate")
        label = name + (f" ({units[name]})" if units.get(name, "?") != "?" else "")
        if kind == "input":
            bottom.plot(*tv, linestyle="--", color="k", linewidth=1,
                        label=label[:-1] + ", given)" if label.endswith(")")
                        else label + " (given)")
        else:
            (bottom if kind == "reaction" else top).plot(*tv, label=label)
    bottom.axhline(0.0, color="0.5", linewidth=0.6)


def _events(run, top, bottom) -> None:
    """Each switch a dashed line with the reaction that reached zero; an early end a dotted
    line."""
    for s in run.switches:
        for ax in (top, bottom):
            ax.axvline(s.time, color="k", linestyle="--", linewidth=1)
        bottom.annotate(f" {s.reaction} = 0", (s.time, 0.97), xycoords=("data", "axes fraction"),
                        va="top", ha="left", fontsize=8)
    if run.ended and run.phases:
        end = float(run.phases[-1].trajectory.t[-1])
        for ax in (top, bottom):
            ax.axvline(end, color="tab:red", linestyle=":", linewidth=1.2)
        top.annotate("end ", (end, 0.03), xycoords=("data", "axes fraction"), va="bottom",
                     ha="right", fontsize=8, color="tab:red")


def _notes(run) -> list[str]:
    """The sentences under the chart: each switch, and why the run ended early."""
    lines = [f"t = {s.time:.4g} s: {s.reaction} = 0, {s.source} -> {s.target}: {s.why}"
             for s in run.switches]
    if run.ended:
        end = run.phases[-1].trajectory.t[-1] if run.phases else 0.0
        lines.append(f"end at t = {end:.4g} s: {run.end or run.ended}")
    return [w for line in lines for w in textwrap.wrap(line, 130)]
