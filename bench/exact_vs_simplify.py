"""Speed of the exact rational-point test against proving equality with sympy's simplify.

For every problem and every model pair, time
  * the exact test (``compare_models``, 8 random rational points), and
  * the textbook route: solve both models symbolically for q'' and ``simplify`` the difference,
and print the ratio measured in the same run.  A script, not a test: run
``python bench/exact_vs_simplify.py`` (``--quick`` skips the slow simplify on big models).
"""
from __future__ import annotations

import argparse
import time

import sympy as sp

from dualmech import compare_models
from dualmech.problems import all_problems
from dualmech.verify.sampling import Context


def _simplify_route(ref, cand, limit: float) -> tuple[float, bool]:
    t0 = time.perf_counter()
    if not (ref.is_square and cand.is_square):
        return float("nan"), None        # a model judged only with the others (a DAE part)
    try:
        a, b = ref.accelerations_solved(), cand.accelerations_solved()
    except ValueError:                    # singular where sympy's LU pivots on a zero
        return float("nan"), None
    ok = all(sp.simplify(a[k] - b[k]) == 0 for k in a)
    return time.perf_counter() - t0, ok


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="exact test only")
    args = parser.parse_args()
    print(f"{'problem':20s} {'pair':34s} {'exact [s]':>10s} {'simplify [s]':>13s} {'ratio':>8s}")
    for p in all_problems():
        ref = p.model(p.reference)
        # the problem's context: its coordinate branches and ranges (two_rod_linkage's x
        # maps to theta on the branch sin(theta) > 0; without it the two differ elsewhere)
        ctx = Context(ref.coordinates, p.parameter_symbols, p)
        for name, m in p.models().items():
            if name == p.reference:
                continue
            cand = p.in_reference_coordinates(m)
            t0 = time.perf_counter()
            r = compare_models(ref, cand, context=ctx)
            t_exact = time.perf_counter() - t0
            if args.quick:
                t_simp, ok = float("nan"), None
            else:
                t_simp, ok = _simplify_route(ref, cand, 60.0)
            ratio = t_simp / t_exact if t_simp == t_simp else float("nan")
            flag = ("" if ok is None or ok == r.equivalent else "  (verdicts differ!)")
            if not r.equivalent:          # e.g. a reduced model judged only with the others
                flag += f"  [pair alone: {r.mismatches[0].reason if r.mismatches else 'no reason given'}]"
            print(f"{p.name:20s} {name + ' vs ' + p.reference:34s} {t_exact:10.3f} "
                  f"{t_simp:13.3f} {ratio:8.1f}{flag}")


if __name__ == "__main__":
    main()
