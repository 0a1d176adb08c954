"""Right-hand side of the equations of motion: dualmech's generated code against the peers.

For the toy car (2 DOF) and a planar n-link pendulum of point masses (n = 2 and 10; the
catalogue's ``n_link_pendulum``, or the same chain written here with dualmech's Lagrangian API),
time in the same run:

* ``rhs(t, y)`` per call (µs, median over repeats): ours (the compiled C backend, which
  ``backend="auto"`` picks from 3 unknowns on, and the Python backend, its choice below);
  hand-written NumPy (M, f, then
  ``numpy.linalg.solve``); sympy ``lambdify`` of M and f (cse) + ``numpy.linalg.solve``;
  PyDy's generated ODE function (backend lambdify, and cython when Cython is installed and
  compiles); Pinocchio's ABA when ``import pinocchio`` works (n-link only);
* vectorised evaluation, states per second: ours ``rhs(t, Y)`` with ``Y`` of shape
  ``(2n, K)``; hand-written NumPy on stacked states with a batched solve;

and print ratios ours / peer (below 1: ours is faster per call; above 1 for states per second:
ours is faster), with wall-clock and CPU-time medians.  Every peer's result is checked against
ours at the timed state first.
A script, not a test: ``python bench/rhs.py`` (``--quick`` fewer repeats).

Targets (issue 5): per call <= hand-written NumPy at n = 2 and n = 10; >= 1e7 states/s
vectorised for a 2-DOF problem.
"""
from __future__ import annotations

import argparse
import os
import statistics
import time
import timeit

import numpy as np
import sympy as sp

from dualmech import Lagrangian, coordinate, t
from dualmech.model.equations import to_plain
from dualmech.numeric import NumericModel
from dualmech.numeric.cbackend import compiler

#: States per vectorised call: 100 000 for the 2-DOF problems, 200 000 / n beyond.
def k_states(n: int) -> int:
    return 100_000 if n <= 2 else 200_000 // n


# -- the problems -------------------------------------------------------------------------
def n_link(n: int):
    """The catalogue's ``n_link_pendulum`` (its Lagrange model), else the chain built here."""
    try:
        from dualmech import get
        p = get("n_link_pendulum", n=n)
    except (ImportError, KeyError):
        return n_link_here(n)
    values = {s: float(v) for s, v in p.defaults().items()}
    mv = np.array([values[s] for s in p.m])
    lv = np.array([values[s] for s in p.l])
    return p.model("lagrange"), values, _hand_n_link(mv, lv, values[sp.Symbol("g", positive=True)])


def n_link_here(n: int):
    """Planar chain of n point masses on massless rods, angles from the downward vertical."""
    th = [coordinate(f"theta{i + 1}") for i in range(n)]
    m = sp.symbols(f"m1:{n + 1}", positive=True)
    lengths = sp.symbols(f"l1:{n + 1}", positive=True)
    g = sp.Symbol("g", positive=True)
    lg = Lagrangian(coordinates=th)
    x = y = 0
    for i in range(n):
        x += lengths[i] * sp.sin(th[i])
        y -= lengths[i] * sp.cos(th[i])
        lg.kinetic(f"T{i + 1}", m[i] * (x.diff(t) ** 2 + y.diff(t) ** 2) / 2)
        lg.potential(f"V{i + 1}", m[i] * g * y)
    rng = np.random.default_rng(n)
    values = {g: 9.81}
    values.update({s: float(v) for s, v in zip(m, rng.uniform(0.5, 2.0, n))})
    values.update({s: float(v) for s, v in zip(lengths, rng.uniform(0.5, 1.5, n))})
    mv = np.array([values[s] for s in m])
    lv = np.array([values[s] for s in lengths])
    return lg.equations(), values, _hand_n_link(mv, lv, 9.81)


def _hand_n_link(m, lengths, g):
    """Hand-written NumPy: M_ij = mu_ij l_i l_j cos(th_i - th_j), mu_ij = sum_{k>=max(i,j)} m_k."""
    n = len(m)
    tail = np.cumsum(m[::-1])[::-1]
    idx = np.arange(n)
    mu = tail[np.maximum.outer(idx, idx)]
    W = mu * np.outer(lengths, lengths)
    G = g * tail * lengths

    def rhs(_t, y):
        th, w = y[:n], y[n:]
        d = th[:, None] - th[None, :]
        M = W * np.cos(d)
        f = -(W * np.sin(d)) @ (w * w) - G * np.sin(th)
        return np.concatenate((w, np.linalg.solve(M, f)))

    def many(_t, Y):
        th, w = Y[:n].T, Y[n:].T                     # (K, n)
        d = th[:, :, None] - th[:, None, :]
        M = W * np.cos(d)
        f = -np.einsum("kij,kj->ki", W * np.sin(d), w * w) - G * np.sin(th)
        return np.concatenate((Y[n:], np.linalg.solve(M, f[..., None])[..., 0].T))

    return rhs, many


def toy_car():
    from dualmech import get
    p = get("toy_car")
    values = {s: float(v) for s, v in p.defaults().items()}
    R, g, m = (values[sp.Symbol(name, positive=True)] for name in ("R", "g", "m"))

    def rhs(_t, y):
        th, ph, thd, phd = y
        s, c = np.sin(th), np.cos(th)
        M = np.array([[m * R * R, 0.0], [0.0, m * R * R * c * c]])
        f = np.array([-m * R * R * s * c * phd * phd - m * g * R * s * np.cos(ph),
                      2 * m * R * R * s * c * thd * phd - m * g * R * c * np.sin(ph)])
        return np.concatenate((y[2:], np.linalg.solve(M, f)))

    def many(_t, Y):
        th, ph, thd, phd = Y
        s, c = np.sin(th), np.cos(th)
        M = np.zeros((Y.shape[1], 2, 2))
        M[:, 0, 0] = m * R * R
        M[:, 1, 1] = m * R * R * c * c
        f = np.stack([-m * R * R * s * c * phd * phd - m * g * R * s * np.cos(ph),
                      2 * m * R * R * s * c * thd * phd - m * g * R * c * np.sin(ph)], -1)
        return np.concatenate((Y[2:], np.linalg.solve(M, f[..., None])[..., 0].T))

    return p.model(p.reference), values, (rhs, many)


# -- peers ----------------------------------------------------------------------------------
def _plain_matrices(eqs):
    A, b = eqs.matrix()
    n = eqs.n
    M = A[:, :n].applyfunc(lambda e: to_plain(e, eqs.coordinates))
    f = b.applyfunc(lambda e: to_plain(e, eqs.coordinates))
    states = eqs.states
    return M, f, [s.q for s in states] + [s.qd for s in states]


def lambdify_peer(eqs, values):
    M, f, args = _plain_matrices(eqs)
    params = sorted(values, key=str)
    fn = sp.lambdify([args, params], [M, f], modules="numpy", cse=True)
    p = [values[s] for s in params]
    n = eqs.n

    def rhs(_t, y):
        Mn, fn_ = fn(y, p)
        return np.concatenate((y[n:], np.linalg.solve(Mn, np.ravel(fn_))))

    return rhs


def pydy_peer(eqs, values, generator: str):
    from pydy.codegen.ode_function_generators import generate_ode_function
    import sympy.physics.mechanics as me
    n = eqs.n
    us = [me.dynamicsymbols(f"u{i}") for i in range(n)]
    A, b = eqs.matrix()
    rules = {q.diff(t): u for q, u in zip(eqs.coordinates, us)}
    M = A[:, :n].xreplace(rules)
    f = b.xreplace(rules)
    params = sorted(values, key=str)
    fn = generate_ode_function(f, list(eqs.coordinates), us, params, mass_matrix=M,
                               coordinate_derivatives=sp.Matrix(us), generator=generator,
                               constants_arg_type="array")
    p = np.array([values[s] for s in params])
    return lambda _t, y: fn(y, _t, p)


def pinocchio_peer(n, values):
    """ABA of the same chain: revolute joints about y, point masses hanging along -z.

    Pinocchio's joint angles are relative and turn the other way (x = -l sin(phi)):
    phi_1 = -theta_1, phi_i = -(theta_i - theta_{i-1}).  Returns the timed function (ABA in
    Pinocchio's own coordinates) and the right-hand side in ours (for the result check).
    """
    import pinocchio as pin
    model = pin.Model()
    parent = 0
    for i in range(n):
        li = values[sp.Symbol(f"l{i + 1}", positive=True)]
        mi = values[sp.Symbol(f"m{i + 1}", positive=True)]
        above = values[sp.Symbol(f"l{i}", positive=True)] if i else 0.0
        parent = model.addJoint(parent, pin.JointModelRY(),
                                pin.SE3(np.eye(3), np.array([0.0, 0.0, -above])), f"j{i}")
        model.appendBodyToJoint(parent, pin.Inertia(mi, np.array([0.0, 0.0, -li]),
                                                    np.zeros((3, 3))), pin.SE3.Identity())
    model.gravity.linear = np.array([0.0, 0.0, -values[sp.Symbol("g", positive=True)]])
    data = model.createData()
    tau = np.zeros(n)

    def aba(_t, x):
        return np.concatenate((x[n:], pin.aba(model, data, x[:n], x[n:], tau)))

    def ours(_t, y):
        rel = lambda a: -np.diff(a, prepend=0.0)  # noqa: E731
        phidd = pin.aba(model, data, rel(y[:n]), rel(y[n:]), tau)
        return np.concatenate((y[n:], -np.cumsum(phidd)))

    return aba, ours


# -- timing ---------------------------------------------------------------------------------
def _median(fn, arg, number: int, repeats: int) -> tuple[float, float]:
    """Median seconds per call: wall clock, and this process's CPU time (less inflated when
    other processes share the cores)."""
    wall = timeit.Timer(lambda: fn(0.0, arg)).repeat(repeat=repeats, number=number)
    cpu = timeit.Timer(lambda: fn(0.0, arg), timer=time.process_time).repeat(
        repeat=repeats, number=number)
    return statistics.median(wall) / number, statistics.median(cpu) / number


def per_call_us(fn, y, repeats: int) -> tuple[float, float]:
    wall, cpu = _median(fn, y, 2000, repeats)
    return wall * 1e6, cpu * 1e6


def states_per_s(fn, Y, repeats: int) -> tuple[float, float]:
    wall, cpu = _median(fn, Y, 3, repeats)
    return Y.shape[1] / wall, Y.shape[1] / cpu


def _check(name, ours, theirs, y, failures):
    a, b = ours(0.0, y), np.asarray(theirs(0.0, y), dtype=float).ravel()
    if not np.allclose(a, b, rtol=1e-9, atol=1e-9 * np.max(np.abs(a))):
        failures.append(f"{name}: max difference {np.max(np.abs(a - b)):.3g}")
        return False
    return True


def run(label, eqs, values, hand, repeats, pinocchio_n=None):
    n = eqs.n
    t0 = time.perf_counter()
    nm_py = NumericModel(eqs, values, backend="python")
    build = time.perf_counter() - t0
    compiled = compiler() is not None
    nm = NumericModel(eqs, values, backend="c" if compiled else "python")
    t0 = time.perf_counter()
    nm.rhs(0.0, np.zeros(2 * n))  # compile (or load) before timing
    build_c = time.perf_counter() - t0
    rng = np.random.default_rng(1)
    y = np.concatenate((rng.uniform(-0.7, 0.7, n), rng.uniform(-1, 1, n)))
    K = k_states(n)
    Y = np.concatenate((rng.uniform(-0.7, 0.7, (n, K)), rng.uniform(-1, 1, (n, K))))
    failures: list = []
    peers = {"hand-written NumPy": hand[0], "sympy lambdify": lambdify_peer(eqs, values)}
    for gen in ("lambdify", "cython"):
        try:
            peers[f"PyDy ({gen})"] = pydy_peer(eqs, values, gen)
        except Exception as exc:  # optional peer
            print(f"  [{label}] PyDy ({gen}) skipped: {type(exc).__name__}: "
                  f"{str(exc).splitlines()[0][:90] if str(exc) else ''}")
    pin_check = None
    if pinocchio_n:
        try:
            peers["Pinocchio ABA"], pin_check = pinocchio_peer(pinocchio_n, values)
        except ImportError:
            print(f"  [{label}] Pinocchio skipped: `import pinocchio` fails "
                  "(pip install pin)")
    ours_us = per_call_us(nm.rhs, y, repeats)
    py_us = per_call_us(nm_py.rhs, y, repeats)
    ours = "dualmech (compiled C)" if compiled else "dualmech (Python)"
    print(f"\n{label}: n = {n}; generated code: Python {build * 1e3:.0f} ms, "
          + (f"C {build_c * 1e3:.0f} ms" if compiled else "no C compiler: Python only")
          + " (build, or load from the cache)")
    print(f"  {'right-hand side per call':30s} {'wall µs':>9s} {'CPU µs':>9s} {'ours/peer':>10s} "
          f"{'(CPU)':>7s}")
    print(f"  {ours:30s} {ours_us[0]:9.2f} {ours_us[1]:9.2f}")
    if compiled:
        _check("Python backend", nm.rhs, nm_py.rhs, y, failures)
        print(f"  {'dualmech (Python backend)':30s} {py_us[0]:9.2f} {py_us[1]:9.2f} "
              f"{ours_us[0] / py_us[0]:10.2f} {ours_us[1] / py_us[1]:7.2f}")
    for name, fn in peers.items():
        check = pin_check if name == "Pinocchio ABA" else fn
        if not _check(name, nm.rhs, check, y, failures):
            continue
        us = per_call_us(fn, y, repeats)
        note = "  (its own relative angles)" if name == "Pinocchio ABA" else ""
        print(f"  {name:30s} {us[0]:9.2f} {us[1]:9.2f} {ours_us[0] / us[0]:10.2f} "
              f"{ours_us[1] / us[1]:7.2f}{note}")
    ours_sps = states_per_s(nm.rhs, Y, repeats)
    py_sps = states_per_s(nm_py.rhs, Y, repeats)
    hand_sps = states_per_s(hand[1], Y, repeats)
    same = np.allclose(nm.rhs(0.0, Y), hand[1](0.0, Y), rtol=1e-9, atol=1e-9)
    print(f"  {'vectorised, K = %d' % K:30s} {'states/s':>9s} {'CPU':>9s} "
          f"{'ours/peer':>10s} {'(CPU)':>7s}")
    print(f"  {ours:30s} {ours_sps[0]:9.3g} {ours_sps[1]:9.3g}")
    if compiled:
        print(f"  {'dualmech (NumPy backend)':30s} {py_sps[0]:9.3g} {py_sps[1]:9.3g} "
              f"{ours_sps[0] / py_sps[0]:10.2f} {ours_sps[1] / py_sps[1]:7.2f}")
    print(f"  {'hand-written NumPy (batched)':30s} {hand_sps[0]:9.3g} {hand_sps[1]:9.3g} "
          f"{ours_sps[0] / hand_sps[0]:10.2f} {ours_sps[1] / hand_sps[1]:7.2f}"
          + ("" if same else "  (RESULTS DIFFER)"))
    for f in failures:
        print(f"  WARNING result mismatch, not timed: {f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 repeats instead of 7")
    args = parser.parse_args()
    repeats = 3 if args.quick else 7
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"load average {load:.1f} on {os.cpu_count()} cores: wall-clock figures are "
          "inflated by other processes; ratios come from the same run (wall, and CPU time).")
    eqs, values, hand = toy_car()
    run("toy car", eqs, values, hand, repeats)
    for n in (2, 10):
        eqs, values, hand = n_link(n)
        run("n-link pendulum", eqs, values, hand, repeats, pinocchio_n=n)


if __name__ == "__main__":
    main()
