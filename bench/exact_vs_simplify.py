"""Speed of the exact rational-point test against proving equality with sympy's simplify.

For every problem and every model pair, time
  * the exact test (``compare_models``, 8 random rational points), and
  * the textbook route: solve both models symbolically for q'' and ``simplify`` the difference,
and print the ratio measured in the same run.  A script, not a test: run
``python bench/exact_vs_simplify.py`` (``--quick`` skips the slow simplify on big models).
"""
from __future__ import annotations

import argparse
import random
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


def _numeric_difference(p, ref, cand, states: int = 3) -> float:
    """The largest |q''_ref - q''_cand| at random states inside the declared ranges (30
    digits): says which route is right when simplify leaves a difference it cannot reduce."""
    rng = random.Random(1)
    a, b = ref.accelerations_solved(), cand.accelerations_solved()
    worst = 0.0
    for _ in range(states):
        vals = {}
        for par in p.parameters:
            vals[par.symbol] = sp.Rational(f"{rng.uniform(*par.range):.6f}")
        for c in p.all_coordinates():
            q = c.function
            vals[q.diff(c.function.args[0])] = sp.Rational(f"{rng.uniform(*c.rate_range):.6f}")
            vals[q] = sp.Rational(f"{rng.uniform(*c.range):.6f}")
        for k in a:
            d = (a[k] - b[k]).subs(vals)      # rates first: a Derivative holds q itself
            d = d.subs({s: 0 for s in d.free_symbols})   # time, where it is left alone
            worst = max(worst, abs(complex(sp.N(d, 30))))
    return worst


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="exact test only")
    parser.add_argument("--problems", nargs="+", metavar="NAME", help="only these problems")
    args = parser.parse_args()
    print(f"{'problem':20s} {'pair':34s} {'exact [s]':>10s} {'simplify [s]':>13s} {'ratio':>8s}")
    for p in all_problems():
        if args.problems and p.name not in args.problems:
            continue
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
            if ok is False and r.equivalent:
                d = _numeric_difference(p, ref, cand)
                flag = (f"  (simplify did not reach 0; the difference is {d:.1e} at 3 "
                        "random states: the exact verdict stands)" if d < 1e-20 else
                        f"  (VERDICTS DIFFER: |difference| = {d:.3g})")
            if not r.equivalent:          # e.g. a reduced model judged only with the others
                flag += f"  [pair alone: {r.mismatches[0].reason if r.mismatches else 'no reason given'}]"
            print(f"{p.name:20s} {name + ' vs ' + p.reference:34s} {t_exact:10.3f} "
                  f"{t_simp:13.3f} {ratio:8.1f}{flag}")


if __name__ == "__main__":
    main()
