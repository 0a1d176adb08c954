"""How often the grader's diagnosis names exactly the mistake that was made.

For every problem of the catalogue, :func:`dualmech.grade.generate.wrong_answers` writes the
classic mistakes from the verified equations -- a wrong sign, a dropped velocity term, ``l``
where ``l^2`` belongs, swapped parameters, a dropped damper, a wrong reaction, a group of terms
dropped as written, a sign inside a factor, a flipped term among like terms -- each carrying the
term it broke.  Each is graded, and the diagnosis counts as naming the mistake when its edits
are exactly the injected one (:func:`dualmech.grade.generate.names_mistake`): the right kind,
the right term(s), in the right equation, and nothing else.

Prints the rate per mistake kind and overall, and the cases missed.  A script, not a test:
``python bench/grade_diagnosis.py [--problems a,b,...] [--quiet]``.
"""
from __future__ import annotations

import argparse
import time
from collections import Counter

from dualmech import problems
from dualmech import Grader
from dualmech.grade.context import GradingUnavailable
from dualmech.grade.generate import names_mistake, wrong_answers


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--problems", default="", help="comma-separated names (default: all)")
    ap.add_argument("--quiet", action="store_true", help="do not list the cases missed")
    args = ap.parse_args()
    names = args.problems.split(",") if args.problems else \
        [d.name for d in problems.declarations()]
    total, hit = Counter(), Counter()
    missed, skipped = [], []
    t0 = time.perf_counter()
    for name in names:
        g = Grader.of(name)
        try:
            ctx = g.context
        except GradingUnavailable as exc:
            skipped.append(f"{name} ({exc})")
            continue
        for s in wrong_answers(ctx):
            r = g.grade(s.text, s.quantity)
            total[s.mistake] += 1
            if r.status == "wrong" and names_mistake(ctx, s, r.edits):
                hit[s.mistake] += 1
            else:
                missed.append((name, s, r))
    print(f"{'mistake':28s} {'named':>6s} {'of':>5s} {'rate':>7s}")
    for kind in sorted(total):
        print(f"{kind:28s} {hit[kind]:6d} {total[kind]:5d} {hit[kind] / total[kind]:7.1%}")
    n, h = sum(total.values()), sum(hit.values())
    print(f"{'overall':28s} {h:6d} {n:5d} {h / max(n, 1):7.1%}")
    print(f"({len(names) - len(skipped)} problems, {time.perf_counter() - t0:.1f} s)")
    for s in skipped:
        print(f"  skipped: {s}")
    if not args.quiet:
        for name, s, r in missed:
            print(f"\n--- {name}: {s.variant} (term {s.term})\n{s.text[:300]}\n{r}")


if __name__ == "__main__":
    main()
