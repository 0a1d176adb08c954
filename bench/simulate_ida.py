"""IDA with no Python per step: the compiled residual against the Python residual.

The same DAE form of the same problem, the same tolerances (``atol = rtol * scales``, as the
work-precision charts set them), the same 101 samples over the chart's scene, solved by
:class:`dualmech.numeric.daesolve.IDASolver` on its two routes, timed in one run (rounds
interleaved, medians of ``Run.cpu``: the integration's CPU time, consistent start
included, the C code compiled and loaded before the clock starts):

* C: the residual generated as C (:mod:`dualmech.numeric.ida`), IDA run by the C driver
  (:mod:`dualmech.numeric.ida_driver`) calling it through a function pointer;
* Python: the Python residual called by IDA through scikit-sundae at every evaluation (the
  route before this one, and the fallback).

Scenes: the Cartesian pendulum (GGL, rtol 1e-8), the four-bar linkage (GGL, rtol 1e-8), and
the two chart points issue 27 found slow: ``two_rod_linkage``'s GGL form at rtol 1e-9 and
``cart_pendulum``'s index-3 form at rtol 1e-3 (both routes perturb the Jacobian's
difference quotients by each component's size, the cure of that point's stall: the ratio
is the residual's cost alone).  Prints each route's CPU seconds, steps and
residual calls, the ratio Python / C, and the largest difference between the routes' samples
in units of each component's range (the routes must agree to within their tolerance, or the
timing compares different work; index 3 branches on round-off, see tests/test_ida.py).
A run past ``--budget`` CPU seconds (default 20, a chart point's) is a *did not finish*
run and says so.

A script, not a test: ``python bench/simulate_ida.py`` (``--rounds N``, default 5; a
route stops repeating after a run that failed or took more than 20 s).
"""
from __future__ import annotations

import argparse
import statistics

import numpy as np

from dualmech.numeric.daesolve import IDASolver
from dualmech.numeric.formulations import formulations
from dualmech.numeric.integrators import WorkBudget
from dualmech.numeric.studies.workprecision import scene_span
from dualmech.problems import get

#: (problem, model, form, rtol)
SCENES = [("pendulum_particle", "cartesian", "ggl", 1e-8),
          ("four_bar", "multiplier", "ggl", 1e-8),
          ("two_rod_linkage", "multiplier", "ggl", 1e-9),
          ("cart_pendulum", "lagrange_multipliers", "index3", 1e-3)]


def scene(name: str, model: str, form: str):
    problem = get(name)
    forms, _ = formulations(problem, stabilisations=(form,))
    (f,) = [f for f in forms if f.dae_solver is not None and f.model.name == model]
    span = scene_span(problem, 5.0, None, None)
    return f, np.linspace(span.t0, span.t_end, 101)


def timed(f, form: str, route: str, te, rtol: float, rounds: int, budget: WorkBudget):
    solver = IDASolver(f.constrained, form, route=route)
    runs = []
    for _ in range(rounds):
        runs.append(solver.run((te[0], te[-1]), f.y0, te, rtol=rtol, atol=rtol * f.scales,
                               budget=budget))
        if not runs[-1].success or runs[-1].cpu > 20:
            break
    return runs[0], statistics.median(r.cpu for r in runs), len(runs)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--budget", type=float, default=20.0,
                    help="CPU seconds one run may spend (default 20, as `dualmech chart`)")
    args = ap.parse_args()
    budget = WorkBudget(seconds=args.budget)
    print(f"{'scene':<34} {'route':<7} {'CPU s':>9} {'steps':>7} {'calls':>8}  ok")
    for name, model, form, rtol in SCENES:
        f, te = scene(name, model, form)
        out = {}
        for route in ("C", "Python"):
            out[route] = timed(f, form, route, te, rtol, args.rounds, budget)
            run, cpu, k = out[route]
            label = f"{name} {form} rtol {rtol:g}"
            print(f"{label:<34} {route:<7} {cpu:9.4f} {run.steps:7d} {run.calls:8d}  "
                  f"{run.success} ({k} run{'s' * (k > 1)})"
                  + ("" if run.success else f": {run.message[:90]}"), flush=True)
        (c, cc, _), (p, pc, _) = out["C"], out["Python"]
        m = min(c.y.shape[1], p.y.shape[1])
        diff = np.abs(c.y[:, :m] - p.y[:, :m]) / f.scales[:, None]
        worse = ">= " if not p.success else ""
        print(f"{'':<34} Python / C CPU: {worse}{pc / max(cc, 1e-9):.1f}x; largest difference "
              f"between the routes: {diff.max() if m else float('nan'):.2e} of the range "
              f"over {m} samples\n", flush=True)


if __name__ == "__main__":
    main()
