"""A problem's default input histories (``Input(..., history=...)``): what simulate, charts,
atlases and work-precision studies drive a problem with when nobody gives a history, and
say so in their stated conditions.  Problems: the teacher files driven_cart_pendulum.py
(every input declares a default) and forced_block.py (none does).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from dualmech import FORCE, Input, problems, simulate, t
from dualmech.model.problem import ProblemError
from dualmech.numeric import NumericModel
from dualmech.numeric.charts import conditions
from dualmech.numeric.inputs import default_histories, driven_problem
from dualmech.numeric.simulation import problem_parameters

HERE = Path(__file__).resolve().parent / "corpus" / "teacher_problems"
CART = HERE / "driven_cart_pendulum.py"
BLOCK = HERE / "forced_block.py"
STATED = "F(t) = default: 2*sin(3*t), tau(t) = default: 1/2, F_x(t) = default: 3*t/10, " \
         "F_y(t) = default: -1/5"


@pytest.fixture(scope="module")
def cart():
    return problems.load(str(CART))


def test_conditions_state_the_default_histories(cart):
    assert STATED in conditions(cart)
    assert STATED in conditions(driven_problem(cart))
    assert default_histories(cart, {"F": 0 * t}) == ["tau", "F_x", "F_y"]


def test_the_driven_problem_has_the_defaults_in_its_equations(cart):
    """Its reference model, free of inputs, gives the accelerations of the original model
    with the default values bound at that time (t = 0.7: F = 2 sin 2.1, Fx = 0.21)."""
    values = problem_parameters(cart, None)
    driven = driven_problem(cart)
    assert driven.inputs == () and cart.inputs != ()
    q, qd = [0.1, 0.4], [0.2, 1.3]
    got = NumericModel(driven.model(driven.reference), values).accelerations(0.7, q, qd)
    fixed = {"F": 2 * np.sin(2.1), "tau": 0.5, "F_x": 0.21, "F_y": -0.2}
    by_name = {s.name: s for s in cart.input_symbols}
    want = NumericModel(cart.model(cart.reference), {**values, **{by_name[k]: v for k, v in
                                                                 fixed.items()}}
                        ).accelerations(0.7, q, qd)
    assert got == pytest.approx(want, rel=1e-13)
    assert driven_problem(driven) is not None and driven.validate() is None


def test_simulate_without_histories_takes_the_defaults(cart):
    run = simulate(cart, (0, 1), samples=3)
    same = simulate(cart, (0, 1), samples=3,
                    inputs={"F": 2 * sp.sin(3 * t), "tau": sp.Rational(1, 2),
                            "F_x": 3 * t / 10, "F_y": -sp.Rational(1, 5)})
    other = simulate(cart, (0, 1), samples=3, inputs={"F": 0 * t})
    assert np.array_equal(run.q, same.q)
    assert np.abs(run.q - other.q).max() > 1e-3      # the push matters


def test_a_problem_without_defaults_says_what_to_declare():
    block = problems.load(str(BLOCK))
    with pytest.raises(ValueError, match="input F has no default history; a study drives it"):
        driven_problem(block)
    from dualmech.report.charts import trajectory_chart
    chart = trajectory_chart(block, Path("/nonexistent"), 1.0)
    assert "Input(..., history=expression of t)" in chart.error


def test_the_work_precision_chart_runs_and_states_the_inputs(cart):
    from dualmech.numeric.studies.workprecision import work_precision
    wp = work_precision(cart, duration=0.5, tolerances=(1e-6,), methods=("DOP853",),
                        repeats=1, progress=False, budget=None)
    assert STATED in wp.scene
    # before the defaults, every formulation was skipped (no value for F): no run at all
    assert wp.runs and all(r.success for r in wp.runs)
    assert all(r.final_error < 1e-4 for r in wp.runs)   # tolerance 1e-6 against the reference


def test_bad_default_histories_are_refused(cart):
    with pytest.raises(TypeError, match="must be a sympy expression of t or a table"):
        Input(sp.Symbol("F"), FORCE, "push", "2*sin(t)")
    mod_F = next(x for x in cart.inputs if x.name == "F")

    class Wrong(type(cart)):
        inputs = (Input(mod_F.symbol, FORCE, "push", sp.Symbol("w") * t),) + cart.inputs[1:]
    with pytest.raises(ProblemError, match="its default history t\\*w names w"):
        Wrong().validate()
