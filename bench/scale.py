"""Bicycle scale as a normal size: derive, exact verdict and code generation, against peers.

For the planar n-link chain of point masses (``NLinkPendulum(n, cartesian=False)`` from
``problems/n_link_pendulum.py``), n = 5, 10, 20 by default, each measurement in a fresh
Python process (imports excluded, sympy's cache cleared):

* **derive**: both models (``newton_euler()`` with the rod tensions, ``lagrange()``); peer:
  ``sympy.physics.mechanics.KanesMethod.kanes_equations`` of the same chain (as in
  ``bench/nlink.py``);
* **verdict**: :func:`dualmech.verify.verdicts.judge` of the two, as ``compare()`` calls it
  (exact, tensions solved at the sampled points);
* **codegen**: the reference model's generated Python (``NumericModel(..., backend="python")``,
  generation + import); peer: ``sympy.lambdify(..., cse=True)`` of the *same* matrices
  ``A``, ``b``; **C**: the generated C compiled and loaded; **simulate**: one second of motion
  under CVODE on the generated C.

And a bicycle-size model with square roots: the Whipple bicycle of sympy's own test suite
(``sympy/physics/mechanics/tests/test_kane3.py``, Meijaard et al. 2007, the front contact
through ``normalize()``, a square root of a trigonometric polynomial of roll, pitch and steer):

* **derive** (peer only): its ``KanesMethod.kanes_equations``;
* **codegen**: our generator on its mass matrix and forcing vector (the six speeds); peer:
  ``sympy.lambdify(cse=True)`` of the same two matrices;
* **verdict**: the front contact's velocity written two ways -- ``d/dt`` in the ground frame,
  and ``d/dt`` in the yaw frame plus ``omega x r``, with its radicand expanded (the same root
  written differently, the case that used to refuse) -- decided exactly (8 points), and the
  same with one term wrong (a certain counter-example expected at the first point).

Prints seconds and the ratios ours / peer (below 1: ours takes less time).  The machine may be
shared: the load average is printed.  Nothing is asserted about speed.

Usage (from the repository root)::

    python bench/scale.py [--ns 5 10 20] [--limit 900] [--no-bicycle]
"""
from __future__ import annotations

import argparse
import inspect
import json
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


# -- measurements (in a child process) -------------------------------------------------------
def _timed(fn):
    w0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - w0, out


def chain_ours(n: int) -> dict:
    import numpy as np
    from dualmech.numeric import NumericModel
    from dualmech.numeric.cvode import integrate
    from dualmech.problems.n_link_pendulum import NLinkPendulum
    from dualmech.verify.check import claims_of
    from dualmech.verify.sampling import Context
    from dualmech.verify.verdicts import judge

    p = NLinkPendulum(n, cartesian=False)
    derive, models = _timed(p.models)
    ref = models[p.reference]

    def verdict():
        ctx = Context(ref.coordinates, p.parameter_symbols, p)
        mapped = {name: p.in_reference_coordinates(m) for name, m in models.items()}
        j = judge(mapped, context=ctx, reference=p.reference, claims=claims_of(p))
        if not j.equivalent:
            raise AssertionError(j.summary())

    decide, _ = _timed(verdict)
    params = p.defaults()
    codegen, _ = _timed(lambda: NumericModel(ref, params, backend="python"))
    c_model = NumericModel(ref, params, backend="c")
    compile_c, ok = _timed(lambda: c_model.compiled)
    y0 = np.concatenate([np.full(n, 0.3), np.zeros(n)])
    simulate, _ = _timed(lambda: integrate(c_model, (0.0, 1.0), y0))
    return {"derive": derive, "verdict": decide, "codegen": codegen,
            "C": compile_c if ok else None, "simulate": simulate}


def chain_peer(n: int) -> dict:
    import sympy as sp
    from dualmech.problems.n_link_pendulum import NLinkPendulum
    sys.path.insert(0, str(ROOT / "bench"))
    from nlink import kane

    derive, _ = _timed(lambda: kane(n))
    ref = NLinkPendulum(n, cartesian=False).model("lagrange")
    A, b = ref.plain_matrix()
    args = sorted(set().union(*[e.free_symbols for e in list(A) + list(b)]), key=str)
    codegen, _ = _timed(lambda: sp.lambdify(args, [A, b], modules="numpy", cse=True))
    return {"derive": derive, "codegen": codegen}


def _bicycle():
    """sympy's Whipple bicycle (test_kane3), run up to ``kanes_equations``; its locals."""
    from sympy.physics.mechanics.tests import test_kane3
    src = inspect.getsource(test_kane3.test_bicycle)
    body = src[src.index("def test_bicycle"):src.index("    # This is the start of entering")]
    space = dict(vars(test_kane3))
    exec(body.replace("def test_bicycle():", "def _derive():") + "    return locals()\n",
         space)
    return space["_derive"]()


def _plain(exprs, q, u):
    """Derivatives of ``q`` by ``u``-free names, then every ``q(t)``, ``u(t)`` a symbol."""
    import sympy as sp
    from sympy.physics.mechanics import dynamicsymbols
    t = dynamicsymbols._t
    rule = {x.diff(t): sp.Symbol(f"{x.func}_d") for x in q}
    rule.update({x: sp.Symbol(str(x.func)) for x in list(q) + list(u)})
    return [sp.sympify(e).subs(rule) for e in exprs], rule


def bicycle_ours(_: int) -> dict:
    import random
    import sympy as sp
    from dualmech.exact.form import ExactForm, is_zero
    from dualmech.numeric import codegen as cg

    w = _bicycle()
    km = w["KM"]
    (M, f), rule = _plain([km.mass_matrix, km.forcing], km.q, km.u)
    states = [rule[x] for x in km.q]
    speeds = [rule[x] for x in km.u]
    params = sorted(set().union(*[e.free_symbols for e in list(M) + list(f)])
                    - set(states) - set(speeds), key=str)

    def generate():
        prog = cg.program(list(M) + list(f), t=sp.Symbol("t"), q=states, qd=speeds,
                          params=params, scale_of=M.rows * M.cols)
        space: dict = {}
        exec(compile(cg.python_source(prog, "bicycle", params), "bicycle", "exec"), space)

    codegen, _ = _timed(generate)
    # the front contact's velocity, two ways (transport theorem), radicand rewritten
    N, Y = w["N"], w["Y"]
    r = w["WF_cont"].pos_from(w["WR_cont"])
    one = r.dt(N).to_matrix(Y)
    two = (r.dt(Y) + (Y.ang_vel_in(N) ^ r)).to_matrix(Y)
    roots = {a: sp.sqrt(sp.expand(a.base)) ** (2 * a.exp) for a in two.atoms(sp.Pow)
             if a.exp.is_Rational and a.exp.q == 2}
    two = two.xreplace(roots)
    (one, two), _ = _plain([one, two], km.q, km.u)
    symbols = sorted(set().union(*[e.free_symbols for e in list(one) + list(two)]), key=str)
    out = {"codegen": codegen, "roots rewritten": len(roots)}
    for label, wrong in (("verdict", 0), ("verdict (wrong)", 1)):
        exprs = [a - b for a, b in zip(one, two)]
        if wrong:
            exprs[0] += sp.sin(symbols[0]) * one[1] / 97

        def decide(exprs=exprs, wrong=wrong):
            form = ExactForm.build(exprs, symbols)
            rng = random.Random(1)
            zero, certain = True, True
            for _ in range(1 if wrong else 8):
                point = form.sample(rng)
                zero &= all(is_zero(v) for v in form.evaluate(point))
                certain &= form.certain(point)
            return form, zero, certain

        out[label], (form, zero, certain) = _timed(decide)
        twins = len(form._world.twins) if form._world else 0
        out[label + " says"] = (f"{form.method}, {'equal' if zero else 'differs'}"
                                f"{'' if zero or not certain else ' (certain)'}, "
                                f"{twins} root(s) shared by proportional radicands"
                                + (f", bound {form.false_equal_bound(8):.1e}" if zero else ""))
    return out


def bicycle_peer(_: int) -> dict:
    import sympy as sp
    derive, w = _timed(_bicycle)
    print(json.dumps({"derive": derive}), flush=True)   # kept if lambdify is killed
    km = w["KM"]
    (M, f), _ = _plain([km.mass_matrix, km.forcing], km.q, km.u)
    args = sorted(set().union(*[e.free_symbols for e in list(M) + list(f)]), key=str)
    codegen, _ = _timed(lambda: sp.lambdify(args, [M, f], modules="numpy", cse=True))
    return {"derive": derive, "codegen": codegen}


KINDS = {"chain": chain_ours, "chain-peer": chain_peer, "bicycle": bicycle_ours,
         "bicycle-peer": bicycle_peer}


def child(kind: str, n: int) -> None:
    sys.path.insert(0, str(ROOT))
    os.environ["DUALMECH_CACHE_DIR"] = "off"
    import sympy  # noqa: F401  (imports outside the timing)
    import sympy.physics.mechanics  # noqa: F401
    import dualmech.verify.verdicts  # noqa: F401
    import dualmech.numeric  # noqa: F401
    from sympy.core.cache import clear_cache
    clear_cache()
    print(json.dumps(KINDS[kind](n)))


# -- the parent ------------------------------------------------------------------------------
def measure(kind: str, n: int, limit: float) -> dict:
    try:
        proc = subprocess.run([sys.executable, __file__, "--child", kind, str(n)], cwd=ROOT,
                              capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired as exc:
        out = exc.stdout.decode() if isinstance(exc.stdout, bytes) else (exc.stdout or "")
        done = [json.loads(x) for x in out.splitlines() if x.startswith("{")]
        return {**(done[-1] if done else {}), "failed": f"killed at the limit, {limit:g} s"}
    if proc.returncode != 0:
        return {"failed": proc.stderr.strip().splitlines()[-1][:200]}
    return json.loads(proc.stdout.strip().splitlines()[-1])


def _s(x) -> str:
    return "-" if x is None else (f"{x:.2f}" if isinstance(x, float) else str(x))


def _ratio(a, b) -> str:
    return "-" if not a or not b else f"{a / b:.2f}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ns", type=int, nargs="*", default=[5, 10, 20])
    ap.add_argument("--limit", type=float, default=900.0)
    ap.add_argument("--no-bicycle", action="store_true")
    ap.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        child(args.child[0], int(args.child[1]))
        return 0
    print(f"load average {os.getloadavg()[0]:.1f} (seconds are wall clock)")
    print(f"{'chain n':>8} {'derive':>8} {'Kane':>8} {'ratio':>6} {'verdict':>8} "
          f"{'codegen':>8} {'lambdify':>8} {'ratio':>6} {'C':>7} {'sim 1 s':>8}")
    for n in args.ns:
        ours, peer = measure("chain", n, args.limit), measure("chain-peer", n, args.limit)
        if "failed" in ours or "failed" in peer:
            print(f"{n:>8} failed: {ours.get('failed') or peer.get('failed')}")
            continue
        print(f"{n:>8} {_s(ours['derive']):>8} {_s(peer['derive']):>8} "
              f"{_ratio(ours['derive'], peer['derive']):>6} {_s(ours['verdict']):>8} "
              f"{_s(ours['codegen']):>8} {_s(peer['codegen']):>8} "
              f"{_ratio(ours['codegen'], peer['codegen']):>6} {_s(ours['C']):>7} "
              f"{_s(ours['simulate']):>8}")
    if not args.no_bicycle:
        ours, peer = measure("bicycle", 0, args.limit), measure("bicycle-peer", 0, args.limit)
        print("\nWhipple bicycle (sympy's test_kane3), square roots in the front contact:")
        peer = {k.replace("failed", "codegen (lambdify)"): v for k, v in peer.items()}
        for key, value in {**{f"peer {k}": v for k, v in peer.items()}, **ours}.items():
            print(f"  {key:<24} {_s(value)}")
        if "codegen" in ours and "codegen" in peer:
            print(f"  codegen ratio ours / lambdify(cse=True): "
                  f"{_ratio(ours['codegen'], peer['codegen'])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
