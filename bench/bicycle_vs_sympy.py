"""The benchmark bicycle: dualmech's derive + verdict + linearise against sympy.physics.mechanics'
own route (KanesMethod on the same bicycle, then its ``linearize``), in one run.

Usage::

    python bench/bicycle_vs_sympy.py                # everything
    python bench/bicycle_vs_sympy.py --no-verdict   # skip the two-model verdict
    python bench/bicycle_vs_sympy.py --referee      # also the Kane referee's own cost

Both routes get the same bicycle: the geometry of Meijaard et al. (2007), Table 1, as exact
numbers (the steer-axis tilt through the rational half-angle tangent of
``problems/whipple_bicycle.py``), masses and inertias symbolic until the numbers go in.
sympy's route is Kane's method as its documentation's bicycle does it: yaw, roll, pitch and
steer coordinates (the wheel angles and the rear contact's position are ignorable and left
out), the front contact's height as the configuration constraint (with ``normalize``, a
square root), its velocity as three velocity constraints, ``KanesMethod.linearize`` at the
upright steady motion, the state matrix reduced to roll, steer and their rates.  Ours:
``lagrange`` and ``newton_euler`` derived, the verdict that they agree (``--no-verdict``
skips it), and the steady motion linearised with its eigenvalues at ``v = 0..10`` m/s.

Each route's eigenvalues are compared with Table 2 (largest difference printed); the times
are CPU seconds of one run, and the ratio is ours over sympy's (below 1: ours is faster).
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))


def _cpu(fn):
    start = time.process_time()
    out = fn()
    return out, time.process_time() - start


def sympy_route(W):
    """KanesMethod on the benchmark bicycle; returns ``(A(v) as a function, derive s,
    linearise s)``."""
    import sympy as sp
    from sympy.physics.mechanics import (KanesMethod, Point, ReferenceFrame, RigidBody,
                                         dynamicsymbols, inertia)
    q1, q2, q3, q4 = dynamicsymbols("q1:5")            # yaw, roll, pitch, steer
    u1, u2, u3, u4, u5, u6 = dynamicsymbols("u1:7")    # their rates, rear and front spin
    start = time.process_time()
    N = ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [q1, N.z])
    L = Y.orientnew("L", "Axis", [q2, Y.x])
    B = L.orientnew("B", "Axis", [q3, L.y])
    S = B.orientnew("S", "DCM", W._tilt())            # the steer axis S.z leans back
    H = S.orientnew("H", "Axis", [q4, S.z])
    H0 = H.orientnew("H0", "DCM", W._tilt().T)        # upright axes, fixed in H
    WR, WF = ReferenceFrame("WR"), ReferenceFrame("WF")
    Y.set_ang_vel(N, u1 * N.z)
    L.set_ang_vel(Y, u2 * Y.x)
    B.set_ang_vel(L, u3 * L.y)
    H.set_ang_vel(B, u4 * S.z)
    WR.set_ang_vel(B, u5 * B.y)
    WF.set_ang_vel(H, u6 * H.y)
    (f1, f3), (h1, h3) = W._offsets()
    P = Point("P")
    P.set_vel(N, 0)
    CR = P.locatenew("CR", W.rR * L.z)
    A = CR.locatenew("A", (W.w + W.c) * B.x - W.rR * B.z)
    CF = A.locatenew("CF", f1 * H.x + f3 * H.z)
    GB = CR.locatenew("GB", W.xB * B.x + (-W.zB - W.rR) * B.z)
    GH = A.locatenew("GH", h1 * H.x + h3 * H.z)
    PF = CF.locatenew("PF", W.rF * ((H.y & N.z) * H.y - N.z).normalize())
    CR.v2pt_theory(P, N, WR)
    A.v2pt_theory(CR, N, B)
    GB.v2pt_theory(CR, N, B)
    CF.v2pt_theory(A, N, H)
    GH.v2pt_theory(A, N, H)
    PF.v2pt_theory(CF, N, WF)
    bodies = [
        RigidBody("R", CR, WR, W.mR, (inertia(B, W.IRxx, W.IRyy, W.IRxx), CR)),
        RigidBody("B", GB, B, W.mB, (inertia(B, W.IBxx, W.IByy, W.IBzz, 0, 0, -W.IBxz), GB)),
        RigidBody("H", GH, H, W.mH, (inertia(H0, W.IHxx, W.IHyy, W.IHzz, 0, 0, -W.IHxz), GH)),
        RigidBody("F", CF, WF, W.mF, (inertia(H, W.IFxx, W.IFyy, W.IFxx), CF))]
    loads = [(b.masscenter, -b.mass * W.g * N.z) for b in bodies]
    kd = [q1.diff() - u1, q2.diff() - u2, q3.diff() - u3, q4.diff() - u4]
    KM = KanesMethod(N, q_ind=[q1, q2, q4], q_dependent=[q3],
                     configuration_constraints=[PF.pos_from(P) & N.z],
                     u_ind=[u2, u4, u5], u_dependent=[u1, u3, u6],
                     velocity_constraints=[PF.vel(N) & N.x, PF.vel(N) & N.y, PF.vel(N) & N.z],
                     kd_eqs=kd, constraint_solver="CRAMER")
    KM.kanes_equations(bodies, loads)
    derive = time.process_time() - start
    v = sp.Symbol("v")
    op = {q1: 0, q2: 0, q3: 0, q4: 0, u1: 0, u2: 0, u3: 0, u4: 0, u5: v / W.rR, u6: v / W.rF}
    op.update({u.diff(): 0 for u in (u1, u2, u3, u4, u5, u6)})
    start = time.process_time()
    Amat, _, _ = KM.linearize(A_and_B=True, op_point=op, linear_solver="CRAMER")
    linearise = time.process_time() - start
    # the linearised state is the independent coordinates then the independent speeds
    return Amat, v, [q1, q2, q4, u2, u4, u5], (q2, q4, u2, u4), derive, linearise


def main(argv=None) -> int:
    import numpy as np
    import sympy as sp

    import inspect

    from dualmech.problems import get
    from dualmech.verify.stability_claims import _Spectra

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--no-verdict", action="store_true", help="skip the two-model verdict")
    ap.add_argument("--referee", action="store_true",
                    help="also time the Kane referee: its derivation from the direct model's "
                         "declarations and its pair verdict against newton_euler (not in the "
                         "ratio: sympy's route has no second derivation)")
    args = ap.parse_args(argv)
    speeds = list(range(11))

    def table(speed):
        out = []
        for e in W.TABLE_2[speed]:
            out += [e, e.conjugate()] if isinstance(e, complex) else [e]
        return np.sort_complex(np.array(out, dtype=complex))

    # -- ours ------------------------------------------------------------------------------
    problem = get("whipple_bicycle")
    W = inspect.getmodule(type(problem))     # the file's constants (Table 2, Table 1)
    _, t_derive = _cpu(lambda: (problem.model("lagrange"), problem.model("newton_euler")))
    t_verdict = 0.0
    if not args.no_verdict:
        from dualmech.verify.check import compare_models
        from dualmech.verify.sampling import Context
        ref = problem.model(problem.reference)
        other = problem.in_reference_coordinates(problem.model("newton_euler"))
        ctx = Context(ref.coordinates, problem.parameter_symbols, problem)
        result, t_verdict = _cpu(lambda: compare_models(ref, other, context=ctx))
        print(f"ours: verdict {str(result).splitlines()[0]}")
    if args.referee:
        from dualmech.model.direct import declarations_of
        from dualmech.model.kane import kane_equations
        from dualmech.verify.check import compare_models
        direct = problem.model("newton_euler")
        kane, t_kane = _cpu(lambda: kane_equations(declarations_of(direct)))
        pair, t_pair = _cpu(lambda: compare_models(kane, direct, explain=False))
        print(f"referee: derive {t_kane:7.2f} s ({len(kane.equations)} rows)  pair verdict "
              f"against newton_euler {t_pair:7.2f} s: "
              f"{'equivalent' if pair.equivalent else 'DIFFERENT'} ({pair.method})")
    spectra, t_lin = _cpu(lambda: _Spectra(problem))
    eig, t_eig = _cpu(lambda: {s: spectra.nontrivial(s) for s in speeds})
    ours_gap = max(float(np.max(np.abs(np.sort_complex(np.array([complex(z) for z in eig[s]]))
                                       - table(s)))) for s in speeds)
    ours = t_derive + t_verdict + t_lin + t_eig
    print(f"ours : derive {t_derive:7.2f} s  verdict {t_verdict:7.2f} s  linearise "
          f"{t_lin:7.2f} s  eigenvalues v=0..10 {t_eig:6.2f} s  total {ours:7.2f} s; "
          f"Table 2 within {ours_gap:.1e}")

    # -- sympy.physics.mechanics ---------------------------------------------------------------
    (Amat, v, order, keep, s_derive, s_lin), _ = _cpu(lambda: sympy_route(W))
    start = time.process_time()
    rows = [order.index(x) for x in keep]
    A4 = Amat.extract(rows, rows).xreplace({s: sp.Float(val, 20)
                                            for s, val in problem.defaults().items()})
    f = sp.lambdify(v, A4, "numpy")
    gap = max(float(np.max(np.abs(np.sort_complex(np.linalg.eigvals(np.array(f(s), dtype=float)))
                                  - table(s)))) for s in speeds)
    s_eig = time.process_time() - start
    theirs = s_derive + s_lin + s_eig
    print(f"sympy: derive {s_derive:7.2f} s  linearise {s_lin:7.2f} s  eigenvalues v=0..10 "
          f"{s_eig:6.2f} s  total {theirs:7.2f} s; Table 2 within {gap:.1e}")
    print(f"ratio ours / sympy: {ours / theirs:.2f}x"
          + ("" if args.no_verdict else f"  (without the verdict: "
             f"{(ours - t_verdict) / theirs:.2f}x)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
