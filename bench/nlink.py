"""Planar n-link pendulum: derive both + verdict + reactions, against the sympy.physics.mechanics
derivations alone, with fitted growth exponents.

For each ``n`` (default 2, 5, 10, 15, 20), time in the same run, every measurement in a fresh
Python process (so sympy's and symengine's caches start empty each repeat) killed at a hard
limit (printed ``> limit``):

* **ours**: ``NLinkPendulum(n, cartesian=False)`` from ``problems/n_link_pendulum.py`` -- its
  ``newton_euler()`` (free-body diagrams, the n rod tensions as reactions) and ``lagrange()``
  (``T`` and ``V`` by hand) derived, brought to the reference coordinates, and judged by
  :func:`dualmech.verify.verdicts.judge` exactly as ``compare()`` calls it: the exact verdict at
  the sampled rational points, with the tensions solved at each of those points (a model whose
  tensions are undetermined fails the verdict);
* **Kane**: the same chain of point masses written with ``sympy.physics.mechanics`` (frames
  ``A_i`` at ``theta_i`` about ``N.z``, mass ``i`` at ``P_{i-1} - l_i A_i.y``, gravity ``-g N.y``)
  and ``KanesMethod.kanes_equations`` -- the derivation alone, no reactions, no verdict;
* **Lagrange**: the same chain and ``LagrangesMethod.form_lagranges_equations`` alone.

Each figure is the median over ``--repeat`` processes of the time from building the first
symbol to the last result, imports excluded; wall clock and CPU time of the process are both
kept (the machine may be shared: the load average is printed beside each row, and CPU time is
the fairer figure under load).  Prints the seconds, the ratios ours / Kane and ours / Lagrange
per ``n``, and each pipeline's growth exponent ``p`` in ``time ~ n^p`` (least squares of
``log time`` against ``log n`` over the ``n`` that finished).  Before timing, the peers'
accelerations are checked against ours at a random state (30 digits) for the smallest ``n``.

Targets (issue 5): ours <= Kane's derivation alone at n = 10 and n = 20, <= 1/10 of
LagrangesMethod's; n = 20 under a minute; growth exponent no worse than Kane's.

Usage (from the repository root)::

    python bench/nlink.py [--ns 2 5 10 15 20] [--repeat 3] [--limit 120] [--no-check]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import random
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PIPELINES = ("ours", "kane", "lagrange")


# -- the pipelines (run in a child process) --------------------------------------------------
def ours(n: int):
    """Derive both models, judge them, solve the tensions at the sampled points."""
    from dualmech.verify.check import claims_of
    from dualmech.verify.sampling import Context
    from dualmech.verify.verdicts import judge
    from problems.n_link_pendulum import NLinkPendulum

    p = NLinkPendulum(n, cartesian=False)
    models = p.models()                      # newton_euler() and lagrange()
    ref = models[p.reference]
    ctx = Context(ref.coordinates, p.parameter_symbols, p)
    mapped = {name: p.in_reference_coordinates(m) for name, m in models.items()}
    j = judge(mapped, context=ctx, reference=p.reference, claims=claims_of(p))
    if not j.equivalent:
        raise AssertionError(f"n = {n}: the derivations disagree: {j.summary()}")
    return j


def _chain(n: int, kane: bool):
    """The planar chain of point masses in sympy.physics.mechanics, as a user writes it."""
    import sympy as sp
    from sympy.physics.mechanics import Particle, Point, ReferenceFrame, dynamicsymbols

    q = dynamicsymbols(f"theta1:{n + 1}")
    qd = [qi.diff(dynamicsymbols._t) for qi in q]
    u = dynamicsymbols(f"u1:{n + 1}")
    m = sp.symbols(f"m1:{n + 1}", positive=True)
    l = sp.symbols(f"l1:{n + 1}", positive=True)
    g = sp.Symbol("g", positive=True)
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    rates = u if kane else qd
    particles, forces, prev = [], [], O
    for i in range(n):
        A = N.orientnew(f"A{i + 1}", "Axis", (q[i], N.z))
        A.set_ang_vel(N, rates[i] * N.z)
        P = prev.locatenew(f"P{i + 1}", -l[i] * A.y)
        P.v2pt_theory(prev, N, A)
        pa = Particle(f"pa{i + 1}", P, m[i])
        pa.potential_energy = m[i] * g * P.pos_from(O).dot(N.y)
        particles.append(pa)
        forces.append((P, -m[i] * g * N.y))
        prev = P
    return dict(q=q, qd=qd, u=u, m=m, l=l, g=g, N=N, particles=particles, forces=forces)


def kane(n: int):
    """``KanesMethod.kanes_equations`` of the chain: ``(M, f)`` in the speeds ``u``."""
    from sympy.physics.mechanics import KanesMethod
    c = _chain(n, kane=True)
    km = KanesMethod(c["N"], q_ind=c["q"], u_ind=c["u"],
                     kd_eqs=[qd - u for qd, u in zip(c["qd"], c["u"])])
    km.kanes_equations(c["particles"], c["forces"])
    return km, c


def lagrange(n: int):
    """``LagrangesMethod.form_lagranges_equations`` of the chain."""
    from sympy.physics.mechanics import LagrangesMethod, Lagrangian
    c = _chain(n, kane=False)
    lm = LagrangesMethod(Lagrangian(c["N"], *c["particles"]), c["q"], frame=c["N"])
    lm.form_lagranges_equations()
    return lm, c


def check(n: int) -> str:
    """The peers' accelerations equal ours (the ``lagrange`` model) at a random state."""
    import sympy as sp
    from dualmech import t
    from problems.n_link_pendulum import NLinkPendulum

    p = NLinkPendulum(n, cartesian=False)
    mine = p.model("lagrange")
    rng = random.Random(n)
    rand = lambda: sp.Rational(rng.randint(-900, 900), 1000)  # noqa: E731
    par = {s: sp.Rational(rng.randint(500, 2000), 1000) for s in p.parameter_symbols}
    qv = [rand() for _ in range(n)]
    wv = [rand() for _ in range(n)]

    def acc(M, f, q, w, extra=None):
        rules = dict(extra or {})
        rules.update(zip(w, wv))
        rules.update(zip(q, qv))
        rules.update(par)
        Mn = M.xreplace(rules).evalf(30)
        fn = f.xreplace(rules).evalf(30)
        return Mn.LUsolve(fn)

    ours_acc = acc(mine.mass_matrix(), mine.forcing(), mine.coordinates,
                   [qi.diff(t) for qi in mine.coordinates])
    km, c = kane(n)
    lm, cl = lagrange(n)
    rename = {s_peer: s_ours for s_peer, s_ours in
              zip(list(c["m"]) + list(c["l"]) + [c["g"]], list(p.m) + list(p.l) + [sp.Symbol(
                  "g", positive=True)])}
    out = []
    for label, M, f, q, w in (("Kane", km.mass_matrix, km.forcing, c["q"], c["u"]),
                              ("Lagrange", lm.mass_matrix, lm.forcing, cl["q"], cl["qd"])):
        a = acc(M.xreplace(rename), f.xreplace(rename), q, w)
        err = max(abs(x - y) for x, y in zip(a, ours_acc))
        scale = max(abs(y) for y in ours_acc)
        if not err <= sp.Float("1e-20", 30) * (1 + scale):
            raise AssertionError(f"n = {n}: {label}'s accelerations differ from ours by {err}")
        out.append(f"{label} {float(err):.1e}")
    return f"peers agree with ours at n = {n} (max |difference| of accelerations, 30 digits: " \
           + ", ".join(out) + ")"


def child(which: str, n: int) -> None:
    """Run one pipeline once and print ``{"wall": s, "cpu": s}`` (or the check's message)."""
    sys.path.insert(0, str(ROOT))
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10_000))
    import sympy  # noqa: F401  (imports outside the timing)
    import sympy.physics.mechanics  # noqa: F401
    import dualmech.verify.verdicts  # noqa: F401
    import problems.n_link_pendulum  # noqa: F401
    from sympy.core.cache import clear_cache
    if which == "check":
        print(json.dumps({"message": check(n)}))
        return
    fn = {"ours": ours, "kane": kane, "lagrange": lagrange}[which]
    clear_cache()
    w0, c0 = time.perf_counter(), time.process_time()
    fn(n)
    print(json.dumps({"wall": time.perf_counter() - w0, "cpu": time.process_time() - c0}))


# -- the parent: processes, medians, table ---------------------------------------------------
def measure(which: str, n: int, limit: float) -> dict | None:
    """One fresh process; ``None`` when it passes ``limit`` seconds (it is killed)."""
    try:
        done = subprocess.run([sys.executable, __file__, "--child", which, str(n)],
                              capture_output=True, text=True, timeout=limit, cwd=ROOT)
    except subprocess.TimeoutExpired:
        return None
    if done.returncode != 0:
        raise RuntimeError(f"{which} at n = {n} failed:\n{done.stderr[-3000:]}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def exponent(ns: list, times: list) -> float | None:
    """Least-squares slope of ``log time`` against ``log n``; ``None`` below two points."""
    pts = [(math.log(n), math.log(t)) for n, t in zip(ns, times) if t is not None]
    if len(pts) < 2:
        return None
    mx = statistics.fmean(x for x, _ in pts)
    my = statistics.fmean(y for _, y in pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


def _fmt(v: float | None, limit: float) -> str:
    return f"> {limit:g}" if v is None else f"{v:.3f}"


def _ratio(a: float | None, b: float | None, limit: float) -> str:
    """ours / peer; a bound when one side ran out of time."""
    if a is None and b is None:
        return "?"
    if a is None:
        return f"> {limit / b:.3g}"
    if b is None:
        return f"< {a / limit:.3g}"
    return f"{a / b:.3f}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ns", type=int, nargs="+", default=[2, 5, 10, 15, 20])
    ap.add_argument("--repeat", type=int, default=3, help="processes per figure (median)")
    ap.add_argument("--limit", type=float, default=120.0, help="seconds before a run is killed")
    ap.add_argument("--no-check", action="store_true", help="skip the peers' correctness check")
    ap.add_argument("--child", nargs=2, metavar=("WHICH", "N"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        child(args.child[0], int(args.child[1]))
        return 0
    if not args.no_check:
        res = measure("check", min(args.ns), max(args.limit, 300.0))
        print(res["message"] if res else f"check at n = {min(args.ns)}: > limit")
    print(f"medians over {args.repeat} fresh processes; limit {args.limit:g} s per run; "
          f"load = 1-minute load average before the row ({os.cpu_count()} CPUs)")
    ns = sorted(args.ns)
    wall = {p: {} for p in PIPELINES}
    cpu = {p: {} for p in PIPELINES}
    gave_up = set()
    head = (f"{'n':>3s} {'load':>5s} | {'ours':>9s} {'Kane':>9s} {'Lagrange':>9s} | "
            f"{'ours/Kane':>9s} {'ours/Lagr':>9s} | wall clock (s)")
    print(head)
    rows = []
    for n in ns:
        load = os.getloadavg()[0]
        for p in PIPELINES:
            if p in gave_up:
                wall[p][n] = cpu[p][n] = None
                continue
            runs = []
            for _ in range(args.repeat):
                r = measure(p, n, args.limit)
                if r is None:
                    runs = None
                    gave_up.add(p)    # larger n would only run longer
                    break
                runs.append(r)
            wall[p][n] = None if runs is None else statistics.median(r["wall"] for r in runs)
            cpu[p][n] = None if runs is None else statistics.median(r["cpu"] for r in runs)
        rows.append((n, load))
        print(_row(n, load, wall, args.limit), flush=True)
    print("\nsame runs, CPU time of the process (s):")
    print(head.replace("wall clock (s)", "CPU (s)"))
    for n, load in rows:
        print(_row(n, load, cpu, args.limit))
    print("\ngrowth exponent p (time ~ n^p, least squares over the n that finished):")
    for label, table in (("wall", wall), ("CPU", cpu)):
        parts = []
        for p in PIPELINES:
            e = exponent(ns, [table[p][n] for n in ns])
            done = [n for n in ns if table[p][n] is not None]
            parts.append(f"{p} {'-' if e is None else f'{e:.2f}'} (n = "
                         f"{', '.join(map(str, done))})")
        print(f"  {label:4s}: " + "; ".join(parts))
    print("\ntargets (issue 5), wall | CPU:")
    for line in targets(ns, wall, cpu):
        print("  " + line)
    print(f"load average at the end: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


def targets(ns: list, wall: dict, cpu: dict) -> list[str]:
    """Each target of issue 5 judged on both clocks: ``met``, ``NOT met`` or ``not run``."""
    def verdict(ok) -> str:
        return "not run" if ok is None else ("met" if ok else "NOT met")

    def both(test) -> str:
        return " | ".join(verdict(test(t)) for t in (wall, cpu))

    def le(a, b, factor=1.0):
        if a is None:
            return None if b is None else False
        return True if b is None else a <= factor * b

    out = []
    for n in (10, 20):
        if n not in ns:
            continue
        out.append(f"n = {n}: ours <= Kane's derivation: "
                   + both(lambda t: le(t["ours"][n], t["kane"][n])))
        out.append(f"n = {n}: ours <= 1/10 of LagrangesMethod's: "
                   + both(lambda t: le(t["ours"][n], t["lagrange"][n], 0.1)))
    if 20 in ns:
        out.append("n = 20 under a minute: " + both(
            lambda t: None if t["ours"][20] is None else t["ours"][20] < 60))

    def slower(t):
        e = [exponent([n for n in ns if t[p][n] is not None and t["kane"][n] is not None],
                      [t[p][n] for n in ns if t[p][n] is not None and t["kane"][n] is not None])
             for p in ("ours", "kane")]
        return None if None in e else e[0] <= e[1]
    out.append("growth exponent <= Kane's (over the n both finished): " + both(slower))
    return out


def _row(n: int, load: float, table: dict, limit: float) -> str:
    o, k, lg = (table[p][n] for p in PIPELINES)
    return (f"{n:3d} {load:5.2f} | {_fmt(o, limit):>9s} {_fmt(k, limit):>9s} "
            f"{_fmt(lg, limit):>9s} | {_ratio(o, k, limit):>9s} {_ratio(o, lg, limit):>9s} |")


if __name__ == "__main__":
    raise SystemExit(main())
