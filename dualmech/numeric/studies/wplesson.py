"""The work-precision figure a teacher shows: one question, one panel, one line per integrator.

The full grid of :meth:`WorkPrecision.chart <dualmech.numeric.studies.workprecision.
WorkPrecision.chart>` (every measure, every formulation, every integrator) answers every
question at once and none in a lesson.  :func:`lesson_chart` answers one -- *which integrator
for this scene, and at what cost?* -- with the state error along the path against CPU time,
one line per integrator, each at its best formulation (the one whose runs reach the least
error per CPU second: :func:`best_curves`), labelled at its end.  Runs that did not finish
within the budget, and integrators that never succeeded, are listed under the panel; the
scene (parameter values, initial conditions, span) is stated above it.

Example
-------
>>> from dualmech.problems import get
>>> scene_text(get("simple_pendulum"))
"M = 1 kg, a = 0.8 m, g = 9.81 m/s^2; from theta = 0.5 rad, theta' = 0 rad/s"
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path

import numpy as np

__all__ = ["best_curves", "lesson_chart", "scene_text"]


def scene_text(problem, params: Mapping | None = None, y0=None) -> str:
    """``"m = 1 kg, ...; from theta = 0.6 rad, theta' = 0 rad/s"``: the values a run used, as
    every chart states them (:func:`dualmech.numeric.charts.conditions`)."""
    from dualmech.numeric.charts import conditions
    return conditions(problem, params or None, None if y0 is None else list(y0))


def _score(runs) -> float:
    """Mean of ``log10(cpu) + log10(error)`` over the successful runs (lower is better)."""
    ok = [r for r in runs if r.success and np.isfinite(r.path_error) and np.isfinite(r.cpu)]
    return float(np.mean([math.log10(max(r.cpu, 1e-6)) + math.log10(max(r.path_error, 1e-17))
                          for r in ok])) if ok else math.inf


def best_curves(wp) -> dict:
    """``{method: (formulation, runs)}``: per integrator, among its curves with the most
    successful runs, the one of least :func:`_score` (curves drawn once count once)."""
    by_method: dict = {}
    for (form, method), runs in wp.curves().items():
        if runs[0].same_as:
            continue
        good = sum(r.success and np.isfinite(r.path_error) for r in runs)
        if good:
            by_method.setdefault(method, []).append((good, -_score(runs), form, runs))
    return {m: (max(c, key=lambda x: x[:2])[2], max(c, key=lambda x: x[:2])[3])
            for m, c in by_method.items()}


def _footnotes(wp, best: dict) -> list[str]:
    notes = []
    for m in dict.fromkeys(r.method for r in wp.runs):
        if m not in best:
            why = next((r.message for r in wp.runs if r.method == m), "")
            notes.append(f"{m}: no run succeeded ({why[:90]})")
            continue
        form, runs = best[m]
        dnf = [r for r in runs if r.did_not_finish]
        if dnf:
            notes.append(f"{m} ({form}): did not finish within the budget"
                         + (f" ({wp.budget})" if wp.budget else "") + " at rtol "
                         + ", ".join(f"{r.tolerance:g}" for r in dnf))
    return notes


def lesson_chart(wp, stem: Path) -> list[Path]:
    """Write ``stem.png`` and ``stem.svg``: the one-panel figure of the module docstring."""
    from dualmech.numeric.charts import METHOD_COLORS, pyplot
    plt = pyplot()
    best = best_curves(wp)
    notes = _footnotes(wp, best)
    fig, ax = plt.subplots(figsize=(10.0, 6.4 + 0.16 * len(notes)))
    ends = []
    for method, (form, runs) in best.items():
        ok = [r for r in runs if r.success and np.isfinite(r.path_error)]
        colour = METHOD_COLORS.get(method, "k")
        xs = [max(r.cpu, 1e-5) for r in ok]
        ys = [max(r.path_error, 1e-17) for r in ok]
        ax.plot(xs, ys, "-o", color=colour, linewidth=2.0, markersize=5)
        for r, x, y in zip(ok, xs, ys):
            tag = f"{r.steps} steps" if method == "midpoint" else \
                f"1e{math.log10(r.tolerance):.0f}"
            ax.annotate(tag, (x, y), xytext=(0, -10), textcoords="offset points",
                        fontsize=6.5, color=colour, ha="center")
        end = int(np.argmin(ys))
        ends.append((xs[end], ys[end], f"{method}\n" + form.replace(" (", "\n("), colour))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.margins(x=0.08, y=0.08)
    _label_ends(ax, ends)
    ax.axhline(wp.reference_error, color="0.5", linewidth=0.8, linestyle=":")
    ax.annotate("reference's own error", (1, wp.reference_error), xycoords=("axes fraction",
                "data"), xytext=(-4, 3), textcoords="offset points", ha="right",
                fontsize=7, color="0.4")
    ax.grid(True, which="major", alpha=0.3)
    ax.set_xlabel("CPU time of the integration [s]  (less is cheaper)")
    ax.set_ylabel("largest state error along the path\n[relative to each coordinate's range]"
                  "  (lower is better)")
    title = _wrap(f"{wp.title}: which integrator, and at what cost?", 80)
    head = _wrap(f"The scene: t in [{wp.span[0]:g}, {wp.span[1]:.3g}] s; {wp.scene}", 125) \
        + "\nEach integrator on its best formulation; each point marked with its tolerance " \
        "(rtol)."
    fig.text(0.45, 0.99, title, ha="center", va="top", fontsize="large")
    fig.text(0.45, 0.99 - 0.035 * (title.count("\n") + 1), head, ha="center", va="top",
             fontsize=7.5, color="0.2")
    text = "\n".join(_wrap(n, 130) for n in notes)
    if text:
        fig.text(0.02, 0.01, text, fontsize=7, va="bottom", color="0.2")
    lines = title.count("\n") + 1
    fig.subplots_adjust(left=0.11, right=0.76,
                        top=0.97 - 0.035 * lines - 0.022 * (head.count("\n") + 1),
                        bottom=0.1 + (0.022 * (text.count("\n") + 1) if text else 0))
    from dualmech.numeric.charts import save
    return save(fig, stem, tight=False)


def _label_ends(ax, ends: list, fontsize: float = 8.0) -> None:
    """Label each line at its most accurate point: the labels in a column right of the
    panel, at the height of their point, nudged apart so that none overlaps another, each
    joined to its point by a thin line of its colour."""
    ax.autoscale_view()
    box = ax.get_window_extent()
    line = 1.25 * fontsize * ax.figure.dpi / 72.0          # pixels per line of text
    pixels = [ax.transData.transform((x, y)) for x, y, _, _ in ends]
    order = sorted(range(len(ends)), key=lambda i: pixels[i][1])
    half = [0.5 * line * (ends[i][2].count("\n") + 1) + 2 for i in order]
    placed: list = []
    for k, i in enumerate(order):
        y = pixels[i][1]
        placed.append(max(y, placed[-1] + half[k - 1] + half[k]) if placed else y)
    overflow = (placed[-1] + half[-1] - box.y1) if placed else 0.0
    if overflow > 0:  # move the column down to stay inside the panel, gaps kept
        placed = [y - overflow for y in placed]
    for i, y in zip(order, placed):
        x0, y0, text, colour = ends[i]
        ax.annotate(text, (x0, y0), xytext=(1.02, (y - box.y0) / box.height),
                    textcoords="axes fraction", fontsize=fontsize, color=colour,
                    fontweight="bold", va="center", ha="left", annotation_clip=False,
                    arrowprops={"arrowstyle": "-", "color": colour, "linewidth": 0.5,
                                "alpha": 0.6, "shrinkA": 0, "shrinkB": 3})


def _wrap(text: str, width: int) -> str:
    import textwrap
    return "\n".join(textwrap.wrap(text, width)) if text else ""
