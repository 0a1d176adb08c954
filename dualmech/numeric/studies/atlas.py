"""The stability atlas of a problem: every way its methods can fail, found, measured, charted.

:func:`atlas` runs the sections that apply to a problem:

* ``singularities`` -- degenerate points of every formulation (:func:`~.singularities.scan`)
  and, for each probe the problem declares (``probes``), what each integrator does when the
  motion runs into them (:func:`~.singularities.probe`: unguarded, guarded, switched to a
  safe form);
* ``dae_drift`` -- constraint drift of a multiplier model's DAE forms (:func:`~.regimes.dae_drift`);
* ``stiffness`` -- a stiff spring swept past its range, in the scene the problem declares
  (``stiff_scene``, :func:`~.regimes.stiffness`);
* ``linearisation`` -- the amplitudes where the small-oscillation model errs by 1 % and 10 %
  (:func:`~.regimes.linearisation`);
* ``floquet`` -- for a periodically driven problem, its periodic motions and their Floquet
  multipliers (:func:`~.floquet.floquet`), with the stability chart of Mathieu's equation
  where an equilibrium's linearisation is one (:mod:`~.mathieu`);
* ``chaos`` -- how long two formulations agree at each tolerance (:func:`~.regimes.chaos`),
  from the problem's ``chaotic_state`` (default: its initial state),
  and how long a run stays right against a reference more accurate than it, with the
  Lyapunov exponent those horizons imply beside Benettin's (:func:`~.horizon.horizons`).

A section that does not apply says why (no DAE form, no stable equilibrium, ...); where a
declaration would make it apply, it names the declaration.
:meth:`Atlas.write` saves ``NAME_atlas.json``, ``NAME_atlas.txt`` and one chart per section
(PNG and SVG).

Example
-------
One section, to keep the example fast (``dualmech atlas NAME`` draws them all):

>>> from dualmech.problems import get
>>> a = atlas(get("toy_car"), sections=("singularities",), progress=False)
>>> sorted(a.results)
['singularities']
"""
from __future__ import annotations

import json
import math
import sys
from dataclasses import asdict, dataclass, field, is_dataclass
from pathlib import Path
from typing import Sequence

import numpy as np

from dualmech.model.notation import mathtext
from dualmech.model.facts import is_declared, state_vector
from dualmech.numeric.inputs import driven_problem
from dualmech.numeric.studies.regimes import NO_STIFF_SCENE, chaos, dae_drift, linearisation, \
    stiffness
from dualmech.numeric.studies.singularities import GARBAGE, KAPPA_LIMIT, NO_PROBE, probe, scan

__all__ = ["Atlas", "atlas", "SECTIONS"]

SECTIONS = ("singularities", "dae_drift", "stiffness", "linearisation", "floquet", "chaos")


@dataclass
class Atlas:
    """Results per section (a result object), why the others were left out, and the scene of
    each section's chart (``conditions``: parameters and initial state, its caption)."""

    problem: str
    title: str
    results: dict = field(default_factory=dict)
    skipped: dict = field(default_factory=dict)
    conditions: dict = field(default_factory=dict)

    def __str__(self) -> str:
        lines = [f"stability atlas of {self.problem}: {self.title}"]
        for name in SECTIONS:
            if name in self.results:
                lines.append(f"\n[{name}]")
                for r in _as_list(self.results[name]):
                    lines.append(str(r))
            elif name in self.skipped:
                lines.append(f"\n[{name}] not applicable: {self.skipped[name]}")
        return "\n".join(lines)

    def to_dict(self) -> dict:
        return {"problem": self.problem, "title": self.title, "skipped": dict(self.skipped),
                "results": {k: [_plain(x) for x in _as_list(v)]
                            for k, v in self.results.items()}}

    def write(self, out_dir: Path) -> list[Path]:
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        stem = out_dir / f"{self.problem}_atlas"
        stem.with_suffix(".json").write_text(json.dumps(self.to_dict(), indent=1) + "\n")
        stem.with_suffix(".txt").write_text(str(self) + "\n")
        paths = [stem.with_suffix(".json"), stem.with_suffix(".txt")]
        for name, result in self.results.items():
            draw = _CHARTS.get(name)
            if draw is not None:
                paths += draw(result, out_dir / f"{self.problem}_atlas_{name}",
                              self.conditions.get(name, ""))
        return paths


def _as_list(x) -> list:
    return list(x) if isinstance(x, (list, tuple)) else [x]


def _plain(x):
    """JSON-able form of a result dataclass (arrays as lists, non-finite as None)."""
    if is_dataclass(x):
        return {k: _plain(v) for k, v in asdict(x).items()}
    if isinstance(x, dict):
        return {str(k): _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.ndarray):
        return _plain(x.tolist())
    if isinstance(x, (np.floating, float)):
        return float(x) if math.isfinite(float(x)) else None
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, (complex, np.complexfloating)):
        return {"re": _plain(x.real), "im": _plain(x.imag)}
    return x


def atlas(problem, sections: Sequence[str] = SECTIONS, progress: bool = True) -> Atlas:
    """Run the applicable ``sections`` (see the module docstring) for ``problem``."""
    from tqdm import tqdm

    from dualmech.progress import is_tty
    unknown = [s for s in sections if s not in SECTIONS]
    if unknown:
        raise ValueError(f"unknown atlas sections {unknown}; choose from {SECTIONS}.")
    problem = driven_problem(problem)   # given inputs: their declared default histories
    out = Atlas(problem.name, problem.title)
    bar = tqdm(list(sections), desc=f"{problem.name}: atlas", unit="section",
               file=sys.stderr, leave=False, disable=not progress or not is_tty(sys.stderr))
    for name in bar:
        bar.set_postfix_str(name)
        try:
            result = _RUN[name](problem)
        except _NotApplicable as exc:
            out.skipped[name] = str(exc)
            continue
        except (ValueError, RuntimeError) as exc:
            out.skipped[name] = f"{type(exc).__name__}: {exc}"
            continue
        out.results[name] = result
        out.conditions[name] = _scene_of(problem, name)
    return out


def _scene_of(problem, section: str) -> str:
    """The caption of a section's chart: the parameters, and the state it starts from."""
    from functools import partial
    from dualmech.numeric.charts import conditions
    scene = partial(conditions, problem, tex=True)
    if section in ("linearisation", "floquet"):
        return scene(start=False) + " (starts: see the legend)"
    if section == "stiffness":
        sc = problem.stiff_scene
        return scene(state=state_vector(problem, sc.state, "`stiff_scene`")) + \
            f"; {mathtext(sc.parameter)} swept"
    if section == "chaos" and is_declared(problem.chaotic_state):
        return scene(state=state_vector(problem, problem.chaotic_state, "`chaotic_state`"))
    if section == "singularities":
        return scene() + " (each coordinate swept, the others held here)"
    return scene()


class _NotApplicable(Exception):
    pass


def _singularities(problem):
    s = scan(problem)
    results = [s]
    for declared in problem.probes:
        results.append(probe(problem, declared))
    if s.points and not problem.probes:
        results.append(NO_PROBE)
    return results


def _dae(problem):
    try:
        return dae_drift(problem)
    except ValueError as exc:
        raise _NotApplicable(str(exc)) from None


def _stiff(problem):
    if problem.stiff_scene is None:
        raise _NotApplicable(NO_STIFF_SCENE)
    return stiffness(problem)


def _driven(problem) -> str | None:
    """Why the reference model is periodically driven (its period), or ``None``."""
    from dualmech.numeric.studies.floquet import NotDriven, forcing_period
    from dualmech.numeric.simulation import problem_parameters
    try:
        period = forcing_period(problem.model(problem.reference), problem_parameters(problem))
    except NotDriven:
        return None
    return f"period {period:.4g} s"


def _linear(problem):
    driven = _driven(problem)
    if driven is not None:
        raise _NotApplicable(f"the model is driven ({driven}): a linearisation frozen at one "
                             "instant says nothing about its stability; see [floquet]")
    try:
        return linearisation(problem)
    except ValueError as exc:
        raise _NotApplicable(str(exc)) from None


def _chaos(problem):
    ref = problem.model(problem.reference)
    if ref.n < 2:
        raise _NotApplicable("one degree of freedom: no chaos")
    from dualmech.numeric.energy import conservative_reason
    from dualmech.numeric.simulation import problem_parameters
    why = conservative_reason(ref, problem_parameters(problem))
    if why is not None:
        raise _NotApplicable(f"the reference model does not conserve energy ({why}); the "
                             "agreement study needs a conservative motion")
    from dualmech.numeric.studies.horizon import horizons
    declared = problem.chaotic_state
    y0 = state_vector(problem, declared, "`chaotic_state`") if is_declared(declared) else None
    try:
        agreement = chaos(problem, y0=y0)
    except ValueError as exc:
        raise _NotApplicable(str(exc)) from None
    if agreement.regular:        # no chaos: no horizons of a chaotic run, no exponent
        return [agreement]
    return [agreement, horizons(problem, y0=y0, duration=10.0,
                                tolerances=[r["rtol"] for r in agreement.rows],
                                exponent=agreement.lyapunov)]


def _floquet(problem):
    from dualmech.numeric.studies.floquet import NotDriven, floquet
    try:
        return floquet(problem)
    except NotDriven as exc:
        raise _NotApplicable(str(exc)) from None


_RUN = {"singularities": _singularities, "dae_drift": _dae, "stiffness": _stiff,
        "linearisation": _linear, "floquet": _floquet, "chaos": _chaos}


# -- charts ------------------------------------------------------------------------------------
def _chart_singularities(results, stem: Path, caption: str = "") -> list[Path]:
    from dualmech.numeric.charts import panels, save
    s = results[0]
    fig, axes = panels(len(s.curves), f"{s.problem}: degeneracy of each formulation "
                       "along each coordinate (others at the initial state)", height=2.6,
                       sharex=False)
    for ax, (coord, (grid, curves)) in zip(axes, s.curves.items()):
        for name, kap in curves.items():
            ax.plot(grid, np.where(np.isfinite(kap), kap, np.nan), label=name, linewidth=1.1)
        ax.axhline(KAPPA_LIMIT, color="0.4", linestyle=":", linewidth=0.9,
                   label=f"{KAPPA_LIMIT:.0e}: half the digits lost")
        ax.axhline(GARBAGE, color="0.6", linestyle="--", linewidth=0.9,
                   label=f"{GARBAGE:.0e}: guard (errors grow 1000-fold)")
        ax.set_yscale("log")
        ax.set_xlabel(f"{mathtext(coord)} [{s.units.get(coord, '?')}]")
        ax.set_ylabel(r"degeneracy $\kappa$ [1]")
        ax.legend(fontsize="x-small", loc="upper right")
    return save(fig, stem, caption=caption)


#: a constraint residual at or below this (in SI units, scenes of order 1 m) is rounding: a
#: thousand units in the last place of a number of order one
ROUNDING = 1e3 * float(np.finfo(float).eps)


def _chart_drift(d, stem: Path, caption: str = "") -> list[Path]:
    from dualmech.numeric.charts import panels, save
    fig, (ax,) = panels(1, f"{d.problem}: constraint drift of {d.model}, {d.method} at rtol "
                        f"{d.rtol:g}", height=3.2)
    flat = []
    for k, g in d.residual.items():
        t = d.times[k]
        note = " -- stopped early" if k in d.stopped else ""
        peak = float(np.abs(g).max()) if g.size else 0.0
        if peak <= ROUNDING:   # a flat line at the floor says nothing: say it in words
            flat.append(f"{k}: " + ("exactly zero" if peak == 0 else
                                    f"at rounding level (max |g| = {peak:.1e} {d.unit})")
                        + " along the whole run" + note)
            continue
        ax.plot(t[1:], np.maximum(np.abs(g[1:]), ROUNDING / 10),
                label=f"{k} ($|g| \\sim t^{{{d.growth[k]:.2f}}}$){note}")
    if flat:
        ax.text(0.02, 0.04, "\n".join(flat), transform=ax.transAxes, fontsize="small",
                va="bottom", bbox={"facecolor": "white", "edgecolor": "0.7"})
    ax.set_yscale("log")
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"$|g|$ [{d.unit}]")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize="small")
    return save(fig, stem, caption=caption)


def _chart_stiffness(s, stem: Path, caption: str = "") -> list[Path]:
    from dualmech.numeric.charts import METHOD_COLORS, panels, save
    fig, axes = panels(2, f"{s.problem}: stiffness in {mathtext(s.parameter)} (declared "
                       f"{s.declared[0]:g}-{s.declared[1]:g} {s.unit}), rtol {s.rtol:g}",
                       height=2.8)
    methods = list(dict.fromkeys(r["method"] for r in s.rows))
    for m in methods:
        rows = [r for r in s.rows if r["method"] == m and r["success"]]
        x = [r["value"] for r in rows]
        c = METHOD_COLORS.get(m, "k")
        axes[0].plot(x, [r["steps"] for r in rows], marker="o", color=c, label=m)
        axes[1].plot(x, [r["cpu"] for r in rows], marker="o", color=c, label=m)
        if rows and rows[0]["min_steps"]:
            axes[0].plot(x, [r["min_steps"] for r in rows], linestyle=":", color=c,
                         label=f"{m}: stability boundary")
    for ax, label in zip(axes, ("accepted steps [1]", "CPU time [s]")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylabel(label)
        ax.axvspan(*s.declared, color="0.9", label="declared range")
        ax.legend(fontsize="x-small", ncol=2)
    axes[-1].set_xlabel(f"{mathtext(s.parameter)} [{s.unit}]")
    return save(fig, stem, caption=caption)


def _chart_linear(lin, stem: Path, caption: str = "") -> list[Path]:
    from dualmech.numeric.charts import panels, save
    fig, (ax,) = panels(1, f"{lin.problem}: small-oscillation model against the nonlinear "
                        "one, over one period", height=3.4)
    ax.plot(lin.amplitudes, lin.errors, marker="o", markersize=3)
    for lv, a in lin.thresholds.items():
        ax.axhline(lv, color="0.5", linestyle=":", linewidth=0.9)
        if a is not None:
            ax.axvline(a, color="0.5", linestyle="--", linewidth=0.9)
            ax.annotate(f"{100 * lv:g} % at {a:.3g} {lin.unit}", (a, lv), fontsize="small",
                        xytext=(4, 4), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"amplitude of {mathtext(lin.coordinate)} [{lin.unit}]")
    ax.set_ylabel("largest error / amplitude [1]")
    return save(fig, stem, caption=caption)


def _chart_chaos(results, stem: Path, caption: str = "") -> list[Path]:
    from dualmech.numeric.charts import panels, save
    c, h = (results + [None])[:2] if isinstance(results, list) else (results, None)
    title = (f"{c.problem}: how long a chaotic run stays right" if not c.regular else
             f"{c.problem}: regular motion -- no chaos, no Lyapunov exponent")
    fig, axes = panels(2, title, height=3.0, sharex=False)
    _draw_exponents(axes[0], c)
    ax = axes[1]
    x = [-np.log(r["rtol"]) for r in c.rows]
    ax.plot(x, [r["horizon"] for r in c.rows], marker="o",
            label=f"{c.pair[0]} and {c.pair[1]} agree (each other, not the truth; hollow: "
                  "the whole run, at least)")
    for xx, r in zip(x, c.rows):
        if not r["diverged"]:
            ax.plot([xx], [r["horizon"]], marker="o", color="white", markersize=4)
    if h is not None:
        xs = [-np.log(r["rtol"]) for r in h.rows]
        ax.plot(xs, [r["horizon"] for r in h.rows], marker="s",
                label=f"{h.formulation} right against the reference (hollow: at least)")
        for xx, r in zip(xs, h.rows):
            if r["bound"]:
                ax.plot([xx], [r["horizon"]], marker="s", color="white", markersize=4)
        good = [(xx, r["horizon"]) for xx, r in zip(xs, h.rows) if not r["bound"]]
        if good and np.isfinite(h.lyapunov) and h.lyapunov > 0:
            x0, t0 = np.mean(good, axis=0)
            line = np.array([min(xs), max(xs)])
            ax.plot(line, t0 + (line - x0) / h.lyapunov, linestyle="--", color="0.4",
                    label="slope $1/\\lambda$ of the exponent above")
        ax.axhline(h.reference_valid, color="0.7", linestyle=":",
                   label=f"reference trusted until {h.reference_valid:.3g} s")
    ax.set_xlabel("-ln(relative tolerance) [1]")
    ax.set_ylabel("horizon [s]")
    ax.legend(fontsize="x-small")
    return save(fig, stem, caption=caption)


def _draw_exponents(ax, c) -> None:
    """Benettin's finite-time exponent against its window, with ``ln(t)/t`` (what a
    separation growing like ``t`` gives) through the first point for comparison."""
    w, e = np.array(c.windows), np.array(c.exponents)
    ax.plot(w, np.where(e > 0, e, np.nan), marker="o", label="finite-time exponent")
    ref = e[0] * np.log(w) / w / (np.log(w[0]) / w[0]) if w[0] > 1 else None
    if ref is not None and e[0] > 0:
        ax.plot(w, ref, linestyle=":", color="0.4", label="ln(t)/t through the first point "
                "(regular motion)")
    if not c.regular:
        ax.axhline(c.lyapunov, color="0.4", linestyle="--", linewidth=0.9,
                   label=f"$\\lambda$ = {c.lyapunov:.3g} 1/s (window {w[-1]:g} s)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("window [s]")
    ax.set_ylabel("exponent [1/s]")
    ax.set_title("chaotic: the exponent settles" if not c.regular else
                 "regular: the exponent falls with the window", fontsize="small")
    ax.legend(fontsize="x-small")


def _chart_floquet(fl, stem: Path, caption: str = "") -> list[Path]:
    from dualmech.numeric.charts import panels, save
    from dualmech.numeric.studies.mathieu import draw_chart
    points = {f"{_orbit(o)}: {'stable' if o.stable else 'unstable'}": o.mathieu
              for o in fl.orbits if o.mathieu is not None}
    count = 3 if points else 1
    fig, axes = panels(count, f"{fl.problem}: Floquet multipliers of each periodic motion"
                       + (" and the stability chart of its linearisation (Mathieu)"
                          if points else ""), height=3.6, sharex=False)
    ax = axes[0]
    circle = np.exp(1j * np.linspace(0, 2 * np.pi, 361))
    ax.plot(circle.real, circle.imag, color="0.5", linewidth=0.8, label="unit circle")
    for o in fl.orbits:
        mu = np.array(o.multipliers, dtype=complex)
        ax.plot(mu.real, mu.imag, marker="o", linestyle="none",
                label=f"{_orbit(o)}: largest $|\\mu|$ = {o.radius:.10f}")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(r"Re $\mu$ [1]")
    ax.set_ylabel(r"Im $\mu$ [1]")
    ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1.0))
    if points:
        qmax = max(abs(q) for _, q in points.values())
        amax = max(abs(a) for a, _ in points.values())
        draw_chart(axes[1], (0.0, 3.0), (-2.0, 5.0), points)
        axes[1].set_title("stable where shaded: |trace of the monodromy matrix| < 2",
                          fontsize="small")
        axes[1].legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1.0))
        draw_chart(axes[2], (0.0, 2.5 * qmax), (-2.5 * amax, 2.5 * amax), points)
        axes[2].set_title("near the problem's own parameters", fontsize="small")
        axes[2].legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1.0))
    return save(fig, stem, caption=caption)


def _orbit(orbit) -> str:
    """An orbit's state at ``t = 0`` for a legend: ``$\\theta$ = 3.1416, $\\dot{\\theta}$ = 0``
    (its names are the coordinates, then their rates with a prime: ``theta'``)."""
    parts = []
    for name, value in zip(orbit.names, orbit.state):
        stem = name.rstrip("'")
        parts.append(f"{mathtext(stem, len(name) - len(stem))} = {value:.5g}")
    return ", ".join(parts)


_CHARTS = {"singularities": _chart_singularities, "dae_drift": _chart_drift,
           "stiffness": _chart_stiffness, "linearisation": _chart_linear,
           "floquet": _chart_floquet, "chaos": _chart_chaos}
