"""Velocity-level (nonholonomic) constraints in the DAE forms (dualmech.numeric.dae, .formulations).

The model case is the catalogue's rolling disk (problems/rolling_disk.py): the Lagrange model
holds the two rolling rows ``x' - r phi' cos(psi) = 0``, ``y' - r phi' sin(psi) = 0`` as
velocity constraints (multipliers ``F_x``, ``F_y``); the ``multiplier`` model adds the
position-level ``h = 0`` (multiplier ``F_z``).  The disk has no minimal (reaction-free) model:
the independent reference is the problem's direct model -- the free-body diagram with the
contact force as three unknowns, derived separately (Newton-Euler) and square, so an ODE --
integrated by DOP853 at ``rtol = 1e-12``: a different model and a different route (no
constraint is held as a DAE there; its rolling rows are acceleration-level equations).
"""
import dataclasses

import numpy as np
import pytest
import sympy as sp

from dualmech import Lagrangian, coordinate, t
from dualmech.model.equations import ModelError
from dualmech.numeric.dae import ALPHA, BETA, constraints_of, index1_equations
from dualmech.numeric.formulations import dae_refusal, formulations
from dualmech.problems import get
from dualmech.problems.rolling_disk import phi, psi, r

EPS = np.finfo(float).eps
ALL = ("none", "baumgarte", "projection", "index3", "ggl")
#: rolling along O.x at 1.8 m/s (above the critical 1 m/s), leaning 0.05 rad: every rolling
#: row is active (x' = r phi' cos(psi) = 0.3 * 6 * 1)
Y0 = [0.0, 0.05, 0.0, 0.0, 0.0, 0.0, 0.0, 6.0, 1.8, 0.0]
SPAN = (0.0, 3.0)
TE = np.linspace(*SPAN, 31)


@pytest.fixture(scope="module")
def disk():
    forms, skipped = formulations(get("rolling_disk"), y0=Y0, stabilisations=ALL)
    return {f.name: f for f in forms}, skipped


@pytest.fixture(scope="module")
def reference(disk):
    forms, _ = disk
    run = forms["newton_euler"].run("DOP853", SPAN, TE, rtol=1e-12)
    assert run.success
    return run


def test_declared_velocity_constraints_are_kept_at_velocity_level():
    c = constraints_of(get("rolling_disk").model("lagrange"))
    assert c.levels == ("velocity", "velocity")
    assert [u.name for u in c.multipliers] == ["F_x", "F_y"]
    # the coefficients of q'' in the acceleration rows are the declared a(q): the problem's
    # [0, 0, -r cos(psi), 1, 0] and [0, 0, -r sin(psi), 0, 1] (psi, theta, phi, x, y)
    assert [sp.simplify(a - b) for a, b in zip(c.gradients[0], [0, 0, -r * sp.cos(psi), 1, 0])] \
        == [0] * 5
    assert [sp.simplify(a - b) for a, b in zip(c.gradients[1], [0, 0, -r * sp.sin(psi), 0, 1])] \
        == [0] * 5
    mixed = constraints_of(get("rolling_disk").model("multiplier"))
    assert mixed.levels == ("velocity", "velocity", "position")


def test_an_undeclared_velocity_row_is_still_refused_with_what_to_do():
    # knife edge: sin(th) x' - cos(th) y' = 0 cannot be written as g(x, y, th) = 0; with its
    # declaration removed the row alone cannot say which level it is
    X, Y, th = coordinate("X"), coordinate("Y"), coordinate("th")
    m = sp.Symbol("m", positive=True)
    lg = Lagrangian("knife", coordinates=[X, Y, th])
    lg.kinetic("T", m * (X.diff(t)**2 + Y.diff(t)**2 + th.diff(t)**2) / 2)
    lg.velocity_constraint("F", [sp.sin(th), -sp.cos(th), 0])
    eqs = lg.equations()
    assert constraints_of(eqs).levels == ("velocity",)
    bare = dataclasses.replace(eqs, constraints=())
    with pytest.raises(ModelError, match="velocity-level constraint.*velocity_constraint"):
        constraints_of(bare)


def test_baumgarte_row_of_a_velocity_constraint_has_the_first_order_term_only():
    eqs = get("rolling_disk").model("lagrange")
    c = constraints_of(eqs)
    stab = index1_equations(eqs, c, stabilised=True)
    for row, g in zip(stab.equations[-2:], c.expressions):
        assert not row.has(BETA)
        assert sp.expand(row - (g.diff(t) + 2 * ALPHA * g)) == 0


def test_a_constrained_model_refuses_a_form_it_cannot_take_with_the_reason():
    from dualmech.numeric.dae import ConstrainedModel
    from dualmech.numeric.simulation import problem_parameters
    p = get("rolling_disk")
    with pytest.raises(ModelError, match="index-3 form: every constraint is at velocity level"):
        ConstrainedModel(p.model("lagrange"), problem_parameters(p), anchor=Y0[:5],
                         stabilisation="index3")


def test_the_forms_that_cannot_take_the_constraints_say_why(disk):
    forms, skipped = disk
    assert set(skipped) == {"lagrange (DAE, index 3)", "multiplier (DAE, GGL index 2)"}
    assert "every constraint is at velocity level" in skipped["lagrange (DAE, index 3)"]
    assert "F_x, F_y have no position level" in skipped["multiplier (DAE, GGL index 2)"]
    assert {"lagrange (DAE, index 2)", "multiplier (DAE, index 3)"} <= set(forms)
    assert dae_refusal("projection", forms["lagrange (DAE, index 2)"].constrained.constraints) \
        == ""


DAE_FORMS = ["lagrange (DAE, index 1)", "lagrange (DAE, Baumgarte)",
             "lagrange (DAE, projection)", "lagrange (DAE, index 2)",
             "multiplier (DAE, index 1)", "multiplier (DAE, Baumgarte)",
             "multiplier (DAE, projection)", "multiplier (DAE, index 3)"]


@pytest.mark.parametrize("name", DAE_FORMS)
def test_each_dae_form_follows_the_direct_models_motion_and_contact_force(disk, reference,
                                                                          name):
    forms, _ = disk
    f = forms[name]
    method = "IDA" if f.dae_solver is not None else "DOP853"
    run = f.run(method, SPAN, TE, rtol=1e-10)
    assert run.success, run.message
    want = f.from_reference(TE, reference.y[:5], reference.y[5:])
    err = np.abs(run.y - want) / f.scales[:, None]
    # DOP853 at 1e-10 keeps the scaled error near 1e-9; IDA (BDF, velocities of the
    # constrained coordinates out of its error test) near 1e-8 -- a wrong term is O(1)
    assert err.max() <= (1e-7 if method == "IDA" else 1e-8), (name, err.max())
    mine = f.reactions(TE, run.y)
    theirs = forms["newton_euler"].reactions(TE, reference.y)
    for k in ("F_x", "F_y"):
        scale = np.abs(theirs[k]).max()
        assert scale > 0.1   # the disk turns: the horizontal contact force is not zero
        assert np.abs(mine[k] - theirs[k]).max() <= (1e-6 if method == "IDA" else 1e-7) * scale


@pytest.fixture(scope="module")
def drifts(disk):
    """The rolling rows' residual ``|c|`` along 10 s at RK45's loose 1e-5, per form."""
    forms, _ = disk
    te = np.linspace(0.0, 10.0, 41)
    out = {}
    for stab in ("index 1", "Baumgarte", "projection"):
        f = forms[f"lagrange (DAE, {stab})"]
        run = f.run("RK45", (0.0, 10.0), te, rtol=1e-5)
        assert run.success, run.message
        out[stab] = np.abs(f.drift(run.y)[0]).max(axis=0)
    return out


def test_projection_keeps_the_rolling_rows_at_round_off(drifts):
    # the rates are projected onto a q' + a0 = 0, affine in q': one exact step
    assert drifts["projection"].max() <= 10 * EPS * 20.0      # |q'| up to r phi' ~ 2, x 10


def test_index_one_without_stabilisation_drifts_off_the_rolling_rows(drifts):
    d = drifts["index 1"]
    assert d[-1] > 1e4 * drifts["projection"].max() + 1e-9
    assert d[20:].max() > 1.5 * d[:10].max()                   # grows along the motion


def test_baumgarte_keeps_the_rolling_drift_below_the_unstabilised_one(drifts):
    assert drifts["Baumgarte"][20:].max() < 0.5 * drifts["index 1"][20:].max()


def test_projection_moves_rates_onto_the_rolling_rows_and_positions_only_onto_h(disk):
    forms, _ = disk
    rng = np.random.default_rng(26)
    for name, extra in (("lagrange", 0), ("multiplier", 1)):
        cm = forms[f"{name} (DAE, projection)"].constrained
        n = cm.n
        y = np.array(Y0[:5] + [0.01] * extra + Y0[5:] + [0.0] * extra)   # h = 0.01 off
        y[n:] += rng.uniform(-0.3, 0.3, n)                               # rates off every row
        out = cm.project(0.0, y)
        inv, vel = cm.residuals(out[:n], out[n:])
        assert np.abs(inv).max() <= 1e-13 and np.abs(vel).max() <= 1e-13, name
        assert np.abs(cm.residuals(y[:n], y[n:])[1]).max() > 0.01      # it was off them
    # no position-level constraint in `lagrange`: its configuration is not touched at all
    cm = forms["lagrange (DAE, projection)"].constrained
    y = np.array(Y0) + np.r_[np.zeros(5), rng.uniform(-0.3, 0.3, 5)]
    assert np.array_equal(cm.project(0.0, y)[:5], y[:5])


def test_no_symplectic_rule_is_offered_the_rolling_disks_constrained_motion(disk):
    """The direct model's energy is the Lagrange model's, whose motion keeps the rolling
    rows: the midpoint rule would integrate the free Hamiltonian flow of that energy -- the
    disk sliding, not rolling (an O(1) error on main's chart) -- so it is refused, saying why."""
    forms, _ = disk
    f = forms["newton_euler"]
    assert f.energy is not None                   # the energy drift is still measured
    with pytest.raises(ValueError, match="not that flow: its energy comes from model "
                                         "`lagrange`, whose motion keeps 2 constraint"):
        f.run("midpoint", SPAN, TE, step=0.01)
    from dualmech.numeric.studies.workprecision import work_precision
    wp = work_precision(get("rolling_disk"), duration=0.2, tolerances=(1e-6,), steps=(32,),
                        methods=("midpoint", "DOP853"), models=("newton_euler",),
                        progress=False, repeats=1, y0=Y0)
    assert [(r.formulation, r.method) for r in wp.runs] == [("newton_euler", "DOP853")]
