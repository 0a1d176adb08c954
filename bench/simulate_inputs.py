"""Given inputs on the compiled route: CVODE + generated C against scipy with Python inputs.

The teacher's driven cart pendulum (tests/corpus/teacher_problems/driven_cart_pendulum.py:
a push F(t), a motor torque tau(t) and a wind force Fx(t) O.x + Fy(t) O.y), 10 s from its
initial state at rtol 1e-8, atol 1e-10, driven by its declared default histories
(F = 2 sin 3t, tau = 1/2, Fx = 3t/10, Fy = -1/5), each route timed in the same run
(interleaved rounds, medians of the integration's CPU time, ``Run.cpu``):

* C closed form: CVODE-Adams, the histories printed into the generated C right-hand side;
* C table: CVODE-Adams, each history a 10001-row table interpolated in C;
* scipy closed form: DOP853 on the Python right-hand side with the inputs bound per call
  (the route every problem with inputs took before the compiled one);
* scipy callable: DOP853 with the inputs as Python functions (what a callable still gets).

Prints each route's CPU time, its ratio to the C closed form, and each route's largest
difference from DOP853 at rtol 1e-11 with the closed forms (all must agree to within their
tolerance, or the timing compares different work; the tables differ from the closed forms
by their interpolation error, ~1e-6 in the state here).

A script, not a test: ``python bench/simulate_inputs.py`` (``--rounds N``, default 20).
"""
from __future__ import annotations

import argparse
import statistics
from pathlib import Path

import numpy as np
import sympy as sp

from dualmech import t
from dualmech.numeric import NumericModel
from dualmech.numeric.cvode import integrate
from dualmech.numeric.inputs import input_functions
from dualmech.numeric.simulation import default_initial_state, problem_parameters
from dualmech.problems import load

FILE = Path(__file__).resolve().parents[1] / "tests" / "corpus" / "teacher_problems" / \
    "driven_cart_pendulum.py"
SPAN, RTOL, ATOL = (0.0, 10.0), 1e-8, 1e-10
CLOSED = {"F": 2 * sp.sin(3 * t), "tau": sp.Rational(1, 2), "F_x": 3 * t / 10,
          "F_y": -sp.Rational(1, 5)}


def histories(kind: str) -> dict:
    if kind == "closed":
        return dict(CLOSED)
    fns = {k: sp.lambdify(t, v, "math") for k, v in CLOSED.items()}
    if kind == "callable":
        return fns
    T = np.linspace(*SPAN, 10001)
    return {k: (T, np.array([f(x) for x in T], dtype=float)) for k, f in fns.items()}


def model(problem, values, kind: str, backend: str = "auto") -> NumericModel:
    drive = input_functions(problem, histories(kind), SPAN, values)
    return NumericModel(problem.model(problem.reference), values, inputs=drive,
                        backend=backend)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=20)
    rounds = ap.parse_args().rounds
    problem = load(str(FILE))
    values = problem_parameters(problem, None)
    q0, qd0 = default_initial_state(problem)
    y0 = np.array(q0 + qd0, dtype=float)
    routes = {"C closed form": (model(problem, values, "closed"), "auto"),
              "C table": (model(problem, values, "table"), "auto"),
              "scipy closed form": (model(problem, values, "closed", "python"), "DOP853"),
              "scipy callable": (model(problem, values, "callable"), "DOP853")}
    ref = integrate(routes["scipy closed form"][0], SPAN, y0, rtol=1e-11, atol=1e-13,
                    method="DOP853").y[:, -1]
    cpu: dict = {name: [] for name in routes}
    last: dict = {}
    for _ in range(rounds):
        for name, (m, method) in routes.items():
            run = integrate(m, SPAN, y0, rtol=RTOL, atol=ATOL, method=method)
            cpu[name].append(run.cpu)
            last[name] = run
    base = statistics.median(cpu["C closed form"])
    print(f"{problem.name}: t = {SPAN[0]:g} .. {SPAN[1]:g} s, rtol {RTOL:g}, atol {ATOL:g}, "
          f"{rounds} rounds (medians)")
    print(f"{'route':20} {'method':12} {'CPU s':>10} {'/ C closed':>10} {'rhs':>8} "
          f"{'|y - ref|':>10}")
    for name, (m, _) in routes.items():
        run, c = last[name], statistics.median(cpu[name])
        err = float(np.abs(run.y[:, -1] - ref).max())
        print(f"{name:20} {run.method:12} {c:10.5f} {c / base:10.1f} {run.evaluations:8d} "
              f"{err:10.2e}")


if __name__ == "__main__":
    main()
