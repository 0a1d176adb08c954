"""``compare(problem)`` against the sympy.physics.mechanics route, problem by problem.

For every peer pipeline in ``bench/peers/`` (``PROBLEM`` and ``run()``: LagrangesMethod, and
KanesMethod with auxiliary speeds for the reactions, equivalence by LUsolve + simplify), time in
the same run, medians over repeats, sympy's cache cleared before each repeat:

* ours, verdicts: ``compare(problem)`` -- every derivation, the exact verdict, the reactions
  shared by two models compared, every printed answer judged;
* ours, with the report: the same plus ``str()`` of the result -- what ``dualmech check``
  prints: the symbolic accelerations and reaction formulas, every wrong printed answer
  explained;
* the peer's ``run()``.

Prints the ratios ours / peer.  Usage: ``python bench/compare_vs_mechanics.py [--repeat N]
[NAME ...]`` (needs ``pip install -e '.[bench]'`` for nothing beyond sympy; run from the
repository root).
"""
from __future__ import annotations

import argparse
import importlib.util
import statistics
import sys
import time
from pathlib import Path

from sympy.core.cache import clear_cache

ROOT = Path(__file__).resolve().parent
sys.path.insert(0, str(ROOT.parent))

from dualmech import compare, get  # noqa: E402


def _peer(path: Path):
    spec = importlib.util.spec_from_file_location(f"peer_{path.stem}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _timed(fn) -> float:
    clear_cache()
    t0 = time.perf_counter()
    fn()
    return time.perf_counter() - t0


def _medians(fns, repeat: int) -> list[float]:
    """Median time of each of ``fns``, the repeats interleaved (ours, ours with the report,
    peer, ours, ...) so that a slow spell of the machine falls on every side alike."""
    times = [[] for _ in fns]
    for _ in range(repeat):
        for i, fn in enumerate(fns):
            times[i].append(_timed(fn))
    return [statistics.median(ts) for ts in times]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*", help="problems (default: every peer in bench/peers)")
    ap.add_argument("--repeat", type=int, default=3, help="repeats per timing (median)")
    args = ap.parse_args(argv)
    peers = sorted((ROOT / "peers").glob("*.py"))
    if args.names:
        peers = [p for p in peers if p.stem in args.names]
    rows = []
    print(f"{'problem':26s} {'ours (s)':>9s} {'+report':>9s} {'peer (s)':>9s} "
          f"{'ratio':>7s} {'ratio+report':>13s}")
    for path in peers:
        mod = _peer(path)
        compare(get(mod.PROBLEM))   # untimed warm-up: imports and one-time set-up of both
        mod.run()
        def full():
            str(compare(get(mod.PROBLEM)))   # what `dualmech check` prints: the whole report

        verdict, shown, peer = _medians([lambda: compare(get(mod.PROBLEM)), full, mod.run],
                                        args.repeat)
        rows.append((mod.PROBLEM, verdict, shown, peer))
        print(f"{mod.PROBLEM:26s} {verdict:9.3f} {shown:9.3f} {peer:9.3f} "
              f"{verdict / peer:7.2f} {shown / peer:13.2f}", flush=True)
    if rows:
        ratios = [v / p for _, v, _, p in rows]
        print(f"\nmedian ratio ours / peer: {statistics.median(ratios):.2f} "
              f"(with the report {statistics.median([s / p for _, _, s, p in rows]):.2f}); "
              f"total ours {sum(r[1] for r in rows):.1f} s, peers {sum(r[3] for r in rows):.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
