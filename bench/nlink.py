"""Planar n-link pendulum: derive both + verdict + reactions, against the sympy.physics.mechanics
derivations alone, with fitted growth exponents.

For each ``n`` (default 2, 5, 10, 15, 20), time in the same run, every measurement in a fresh
Python process (so sympy's and symengine's caches start empty each repeat) killed at a hard
wall-clock limit (then printed ``> s``, the wall and CPU seconds it had spent: lower bounds):

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

* **full**: what ``dualmech check n_link_pendulum --n N`` does -- ``compare`` of the
  catalogue's chain (three derivations: Newton--Euler, Lagrange, and Cartesian coordinates with
  the rods as multipliers), the reactions compared, the dimension audit, and ``str()`` of the
  result (the report it prints);

Targets: ours <= Kane's derivation alone at n = 10 and n = 20, <= 1/10 of
LagrangesMethod's; n = 20 under a minute; growth exponent no worse than Kane's; and the full
check (compare + report) <= Kane's derivation alone at n = 10 and 20, with a growth exponent
over n = 2 ... 20 no worse than Kane's.

Usage (from the repository root)::

    python bench/nlink.py [--ns 2 5 10 15 20] [--repeat 3] [--limit 120] [--no-check]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import random
import resource
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PIPELINES = ("ours", "full", "kane", "lagrange")


# -- the pipelines (run in a child process) --------------------------------------------------
def ours(n: int):
    """Derive both models, judge them, solve the tensions at the sampled points."""
    from dualmech.verify.check import claims_of
    from dualmech.verify.sampling import Context
    from dualmech.verify.verdicts import judge
    from dualmech.problems.n_link_pendulum import NLinkPendulum

    p = NLinkPendulum(n, cartesian=False)
    models = p.models()                      # newton_euler() and lagrange()
    ref = models[p.reference]
    ctx = Context(ref.coordinates, p.parameter_symbols, p)
    mapped = {name: p.in_reference_coordinates(m) for name, m in models.items()}
    j = judge(mapped, context=ctx, reference=p.reference, claims=claims_of(p))
    if not j.equivalent:
        raise AssertionError(f"n = {n}: the derivations disagree: {j.summary()}")
    return j


def full(n: int):
    """What ``dualmech check n_link_pendulum --n N`` does: ``compare`` of the catalogue's chain
    (its three derivations: Newton--Euler, Lagrange, Cartesian coordinates with multipliers)
    and the report it prints."""
    from dualmech import compare, get

    c = compare(get("n_link_pendulum", n=n))
    if not c.equivalent:
        raise AssertionError(f"n = {n}: the derivations disagree")
    return str(c)


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
    from dualmech.problems.n_link_pendulum import NLinkPendulum

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
    """Run one pipeline once: print ``{"start": ...}`` when the timing starts, then
    ``{"wall": s, "cpu": s}`` (or the check's message)."""
    sys.path.insert(0, str(ROOT))
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10_000))
    import sympy  # noqa: F401  (imports outside the timing)
    import sympy.physics.mechanics  # noqa: F401
    import dualmech.verify.verdicts  # noqa: F401
    import dualmech.problems.n_link_pendulum  # noqa: F401
    import dualmech.verify.check  # noqa: F401
    from sympy.core.cache import clear_cache
    if which == "check":
        print(json.dumps({"message": check(n)}))
        return
    fn = {"ours": ours, "full": full, "kane": kane, "lagrange": lagrange}[which]
    clear_cache()
    print(json.dumps({"start": time.time(), "cpu0": time.process_time()}), flush=True)
    w0, c0 = time.perf_counter(), time.process_time()
    fn(n)
    print(json.dumps({"wall": time.perf_counter() - w0, "cpu": time.process_time() - c0}))


# -- the parent: processes, medians, table ---------------------------------------------------
@dataclass(frozen=True)
class Figure:
    """Seconds; ``exact=False``: the run was killed, ``value`` is a lower bound."""

    value: float
    exact: bool = True

    def __str__(self) -> str:
        return f"{self.value:.3f}" if self.exact else f"> {self.value:.1f}"


def _children_cpu() -> float:
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def measure(which: str, n: int, limit: float) -> dict:
    """One fresh process: ``{"wall": Figure, "cpu": Figure}``, or ``{"message": ...}``.

    Past ``limit`` seconds the process is killed and the figures are lower bounds: the wall
    clock and the CPU time it had spent since its timing started (its imports excluded).
    """
    cpu_before = _children_cpu()
    proc = subprocess.Popen([sys.executable, __file__, "--child", which, str(n)], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        out, err = proc.communicate(timeout=limit)
    except subprocess.TimeoutExpired:
        proc.kill()
        killed = time.time()
        out, err = proc.communicate()
        lines = [json.loads(x) for x in out.split("\n") if x.startswith("{")]
        if not lines:
            raise RuntimeError(f"{which} at n = {n} did not start within {limit:g} s") from None
        start = lines[0]
        spent = _children_cpu() - cpu_before - start["cpu0"]
        return {"wall": Figure(killed - start["start"], False), "cpu": Figure(spent, False)}
    if proc.returncode != 0:
        raise RuntimeError(f"{which} at n = {n} failed:\n{err[-3000:]}")
    last = json.loads(out.strip().splitlines()[-1])
    if "message" in last:
        return last
    return {"wall": Figure(last["wall"]), "cpu": Figure(last["cpu"])}


def exponent(ns: list, times: list) -> float | None:
    """Least-squares slope of ``log time`` against ``log n`` over the exact figures."""
    pts = [(math.log(n), math.log(t.value)) for n, t in zip(ns, times)
           if t is not None and t.exact]
    if len(pts) < 2:
        return None
    mx = statistics.fmean(x for x, _ in pts)
    my = statistics.fmean(y for _, y in pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


def _ratio(a: Figure | None, b: Figure | None) -> str:
    """ours / peer; a bound when one side was killed."""
    if a is None or b is None or (not a.exact and not b.exact):
        return "?"
    if not a.exact:
        return f"> {a.value / b.value:.3g}"
    if not b.exact:
        return f"< {a.value / b.value:.3g}"
    return f"{a.value / b.value:.3f}"


def _median(runs: list, key: str) -> Figure:
    if any(not r[key].exact for r in runs):
        return next(r[key] for r in runs if not r[key].exact)
    return Figure(statistics.median(r[key].value for r in runs))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ns", type=int, nargs="+", default=[2, 5, 10, 15, 20])
    ap.add_argument("--repeat", type=int, default=3, help="processes per figure (median)")
    ap.add_argument("--limit", type=float, default=120.0,
                    help="wall-clock seconds before a run is killed")
    ap.add_argument("--no-check", action="store_true", help="skip the peers' correctness check")
    ap.add_argument("--child", nargs=2, metavar=("WHICH", "N"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        child(args.child[0], int(args.child[1]))
        return 0
    if not args.no_check:
        print(measure("check", min(args.ns), max(args.limit, 300.0))["message"])
    print(f"medians over {args.repeat} fresh processes; a run is killed after {args.limit:g} s "
          f"(then '> s': what it had spent); load = 1-minute load average before the row "
          f"({os.cpu_count()} CPUs)")
    ns = sorted(args.ns)
    wall = {p: {} for p in PIPELINES}
    cpu = {p: {} for p in PIPELINES}
    gave_up = set()
    head = (f"{'n':>3s} {'load':>5s} | {'ours':>9s} {'full':>9s} {'Kane':>9s} {'Lagrange':>9s}"
            f" | {'ours/Kane':>9s} {'full/Kane':>9s} {'ours/Lagr':>9s} |")
    print(head + " wall clock (s)")
    rows = []
    for n in ns:
        load = os.getloadavg()[0]
        for p in PIPELINES:
            wall[p][n] = cpu[p][n] = None
            if p in gave_up:
                continue                 # killed at a smaller n: larger n only run longer
            runs = []
            for _ in range(args.repeat):
                runs.append(measure(p, n, args.limit))
                if not runs[-1]["wall"].exact:
                    gave_up.add(p)
                    break
            wall[p][n], cpu[p][n] = _median(runs, "wall"), _median(runs, "cpu")
        rows.append((n, load))
        print(_row(n, load, wall), flush=True)
    print("\nsame runs, CPU time of the process (s):")
    print(head + " CPU (s)")
    for n, load in rows:
        print(_row(n, load, cpu))
    print("\ngrowth exponent p (time ~ n^p, least squares over the n that finished):")
    for label, table in (("wall", wall), ("CPU", cpu)):
        parts = []
        for p in PIPELINES:
            e = exponent(ns, [table[p][n] for n in ns])
            done = [n for n in ns if table[p][n] is not None and table[p][n].exact]
            parts.append(f"{p} {'-' if e is None else f'{e:.2f}'} (n = "
                         f"{', '.join(map(str, done))})")
        print(f"  {label:4s}: " + "; ".join(parts))
    print("\ntargets (issue 5), wall | CPU:")
    for line in targets(ns, wall, cpu):
        print("  " + line)
    print(f"load average at the end: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


def _le(a: Figure | None, b: Figure | None, factor: float = 1.0) -> bool | None:
    """Is ``a <= factor * b``?  ``None`` when a killed run leaves it open."""
    if a is None or b is None:
        return None
    if a.exact and b.exact:
        return a.value <= factor * b.value
    if a.exact:                            # b is at least b.value
        return True if a.value <= factor * b.value else None
    if b.exact:                            # a is at least a.value
        return False if a.value > factor * b.value else None
    return None


def targets(ns: list, wall: dict, cpu: dict) -> list[str]:
    """Each target of issue 5 judged on both clocks: ``met``, ``NOT met`` or ``open``."""
    def both(test) -> str:
        return " | ".join({True: "met", False: "NOT met", None: "open"}[test(t)]
                          for t in (wall, cpu))

    out = []
    for n in (10, 20):
        if n not in ns:
            continue
        out.append(f"n = {n}: ours <= Kane's derivation: "
                   + both(lambda t: _le(t["ours"][n], t["kane"][n])))
        out.append(f"n = {n}: full check (compare + report) <= Kane's derivation: "
                   + both(lambda t: _le(t["full"][n], t["kane"][n])))
        out.append(f"n = {n}: ours <= 1/10 of LagrangesMethod's: "
                   + both(lambda t: _le(t["ours"][n], t["lagrange"][n], 0.1)))
    if 20 in ns:
        out.append("n = 20 under a minute: "
                   + both(lambda t: _le(t["ours"][20], Figure(60.0))))

    def flatter(t, ours="ours") -> bool | None:
        both_done = [n for n in ns if all(t[p][n] is not None and t[p][n].exact
                                          for p in (ours, "kane"))]
        e = [exponent(both_done, [t[p][n] for n in both_done]) for p in (ours, "kane")]
        return None if None in e else e[0] <= e[1]
    out.append("growth exponent <= Kane's (over the n both finished): " + both(flatter))
    out.append("full check's growth exponent <= Kane's: "
               + both(lambda t: flatter(t, "full")))
    return out


def _row(n: int, load: float, table: dict) -> str:
    o, fu, k, lg = (table[p][n] for p in PIPELINES)
    cell = lambda f: "not run" if f is None else str(f)  # noqa: E731
    return (f"{n:3d} {load:5.2f} | {cell(o):>9s} {cell(fu):>9s} {cell(k):>9s} {cell(lg):>9s}"
            f" | {_ratio(o, k):>9s} {_ratio(fu, k):>9s} {_ratio(o, lg):>9s} |")


if __name__ == "__main__":
    raise SystemExit(main())
