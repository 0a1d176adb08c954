"""Cost of ``dualmech chart`` and ``dualmech atlas`` per problem; steps and RHS calls per solve.

Usage::

    python bench/chart_atlas.py                      # a representative set of problems
    python bench/chart_atlas.py toy_car two_rod_linkage
    python bench/chart_atlas.py --all --quick        # every problem, the quick chart sweep

For each problem: the CPU seconds of the work-precision sweep (full, or ``--quick``: three
tolerances, two step counts; one run per point, ``--repeats K`` for the chart's own median) and of the stability atlas (every applicable section), then for
each integrator one solve of the reference model over the scene's span at ``rtol = 1e-6``:
accepted steps, right-hand-side calls and states evaluated (a vectorised call of an implicit
method's finite-difference Jacobian evaluates several).  Numbers from one run on this
machine; compare them with each other, not across machines.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

DEFAULT = ("pendulum_particle", "toy_car", "falling_container", "two_rod_linkage",
           "compound_double_pendulum", "mobile_robot")


def _cpu(fn):
    start = time.process_time()
    out = fn()
    return out, time.process_time() - start


def main(argv=None) -> int:
    import numpy as np

    from dualmech import problems
    from dualmech.numeric.studies.atlas import atlas
    from dualmech.numeric.contacts import scene_span
    from dualmech.numeric.formulations import formulations
    from dualmech.numeric.integrators import SCIPY_METHODS
    from dualmech.numeric.studies.workprecision import work_precision

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*")
    ap.add_argument("--all", action="store_true")
    ap.add_argument("--quick", action="store_true", help="the quick chart sweep")
    ap.add_argument("--repeats", type=int, default=1, help="runs per chart point (default 1)")
    args = ap.parse_args(argv)
    names = [d.name for d in problems.declarations()] if args.all else (args.names or DEFAULT)
    sweep = dict(tolerances=(1e-3, 1e-6, 1e-9), steps=(32, 256)) if args.quick else {}
    sweep["repeats"] = args.repeats
    print(f"{'problem':26s} {'chart [s]':>10s} {'runs':>5s} {'atlas [s]':>10s}  sections")
    solves = []
    for name in names:
        p = problems.get(name)
        wp, t_chart = _cpu(lambda: work_precision(p, progress=False, **sweep))
        at, t_atlas = _cpu(lambda: atlas(p, progress=False))
        print(f"{name:26s} {t_chart:10.2f} {len(wp.runs):5d} {t_atlas:10.2f}  "
              f"{', '.join(at.results)}")
        span = scene_span(p, 5.0)
        ref = formulations(p, models=[p.reference], stabilisations=())[0][0]
        te = np.linspace(span.t0, span.t_end, 101)
        for m in SCIPY_METHODS:
            run = ref.run(m, (span.t0, span.t_end), te, rtol=1e-6)
            solves.append((name, m, run.steps, run.calls, run.evaluations, run.cpu,
                           run.success))
    print(f"\n{'problem':26s} {'method':7s} {'steps':>7s} {'RHS calls':>10s} "
          f"{'states':>8s} {'CPU [ms]':>9s}  (reference model, rtol 1e-6, scene span)")
    for name, m, steps, calls, evals, cpu, ok in solves:
        print(f"{name:26s} {m:7s} {steps:7d} {calls:10d} {evals:8d} {1e3 * cpu:9.2f}"
              + ("" if ok else "  FAILED"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
