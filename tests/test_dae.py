"""Maximal-coordinate DAE forms and the integrators (dualmech.numeric.dae, .integrators, .energy).

The model case is the particle pendulum of source 003 (problems/pendulum_particle.py): the
bob in (x, y) with the rod as a constraint (index 3), the rod force S as the multiplier.
Reference values are the hand formula ``S = m (g cos(theta) + l theta'^2)`` (the body-axes
balance, solved by hand in the problem module) and the minimal-coordinate ODE.
"""
import numpy as np
import pytest
import sympy as sp

from dualmech import Lagrangian, coordinate, t
from dualmech.model.equations import ModelError
from dualmech.numeric.dae import constraints_of
from dualmech.numeric.energy import EnergyFunction, conservative_reason
from dualmech.numeric.formulations import formulations
from dualmech.numeric.integrators import METHODS, integrate
from dualmech.problems import get
from dualmech.problems.pendulum_particle import l, x, y

EPS = np.finfo(float).eps
M_, L_, G_ = 1.0, 1.0, 9.81          # the problem's default m, l, g
THETA0 = 1.0                          # released at rest from 1 rad


@pytest.fixture(scope="module")
def pendulum():
    forms, skipped = formulations(get("pendulum_particle"), y0=[THETA0, 0.0])
    assert skipped == {}
    return {f.name: f for f in forms}


@pytest.fixture(scope="module")
def reference(pendulum):
    """The minimal-coordinate ODE at DOP853's tightest useful tolerance, 20 s."""
    te = np.linspace(0.0, 20.0, 401)
    run = pendulum["lagrange"].run("DOP853", (0.0, 20.0), te, rtol=1e-13)
    return te, run


def _theta(y):
    """The hand inverse of the map x = l sin(theta), y = l cos(theta)."""
    th = np.arctan2(y[0], y[1])
    thd = (y[2] * y[1] - y[0] * y[3]) / (y[0]**2 + y[1]**2)
    return th, thd


# -- constraints recovered from the acceleration rows -------------------------------------
def test_rod_constraint_is_recovered_from_the_acceleration_row():
    c = constraints_of(get("pendulum_particle").model("cartesian"))
    g = c.expressions[0]
    # the model wrote (l^2 - x^2 - y^2)/(2 l): the recovered g differs by a constant only
    assert sp.expand(g.diff(x) + x / l) == 0 and sp.expand(g.diff(y) + y / l) == 0
    assert [u.name for u in c.multipliers] == ["S"]


def test_direct_inertial_form_borrows_the_multiplier_models_constraint(pendulum):
    f = pendulum["newton_euler_inertial (DAE, index 1)"]
    assert f.kind == "dae" and f.reaction_names == ("S",)
    assert [str(e) for e in f.constrained.constraints.expressions] == \
        [str(e) for e in constraints_of(get("pendulum_particle").model("cartesian")).expressions]


# -- reactions: both routes ---------------------------------------------------------------
@pytest.mark.parametrize("name", ["cartesian (DAE, index 1)", "cartesian (DAE, Baumgarte)",
                                  "newton_euler_inertial (DAE, index 1)"])
def test_multiplier_at_a_state_on_the_rod_is_the_hand_rod_force(pendulum, reference, name):
    """At states on the manifold every DAE form gives S = m (g cos + l theta'^2) to rounding:
    a few dozen operations on terms no larger than m g + m l theta'^2."""
    te, run = reference
    f = pendulum[name]
    th, thd = run.y
    Y = f.from_reference(te, run.y[:1], run.y[1:])
    S = f.reactions(te, Y)["S"]
    hand = M_ * (G_ * np.cos(th) + L_ * thd**2)
    scale = M_ * G_ + M_ * L_ * thd**2
    assert np.abs(S - hand).max() <= 64 * EPS * scale.max()


def test_reactions_along_the_dae_and_the_ode_converge_to_one_another(pendulum):
    """Each route's error is estimated against its own run at 1/1000 of the tolerance; the
    routes' disagreement at the loose tolerance must fit inside the sum of the two."""
    te = np.linspace(0.0, 5.0, 101)
    ode, dae = pendulum["lagrange"], pendulum["cartesian (DAE, Baumgarte)"]

    def rod_force(f, rtol):
        run = f.run("DOP853", (0.0, 5.0), te, rtol=rtol)
        return f.reactions(te, run.y)["S"] if f is dae else \
            M_ * (G_ * np.cos(run.y[0]) + L_ * run.y[1]**2)
    loose = {f.name: rod_force(f, 1e-6) for f in (ode, dae)}
    tight = {f.name: rod_force(f, 1e-9) for f in (ode, dae)}
    estimate = sum(np.abs(loose[k] - tight[k]).max() for k in loose)
    assert np.abs(loose[ode.name] - loose[dae.name]).max() <= estimate


# -- drift ----------------------------------------------------------------------------------
def _growth(te, g):
    """Exponent p of |g| ~ t^p: least squares on the running maximum, t in [1, end]."""
    envelope = np.maximum.accumulate(np.abs(g))
    keep = te >= 1.0
    return np.polyfit(np.log(te[keep]), np.log(envelope[keep]), 1)[0]


@pytest.fixture(scope="module")
def drifts(pendulum):
    te = np.linspace(0.0, 20.0, 401)
    out = {}
    for stab in ("index 1", "Baumgarte", "projection"):
        f = pendulum[f"cartesian (DAE, {stab})"]
        run = f.run("RK45", (0.0, 20.0), te, rtol=1e-6)
        assert run.success
        out[stab] = f.drift(run.y)[0][0]
    return te, out


def test_index_one_drift_grows_faster_than_linearly(drifts):
    te, g = drifts
    # g'' = 0 is all the index-1 form holds: errors in g' add up, g integrates them (~t^2)
    assert _growth(te, g["index 1"]) > 1


def test_baumgarte_keeps_the_drift_bounded(drifts):
    te, g = drifts
    assert _growth(te, g["Baumgarte"]) < 1
    assert np.abs(g["Baumgarte"][-100:]).max() < np.abs(g["index 1"][-100:]).max()


def test_projection_holds_the_rod_length_to_its_own_stopping_rule(drifts):
    te, g = drifts
    assert np.abs(g["projection"]).max() <= 1e-13 * L_   # ConstrainedModel.project's test


# -- integrators ----------------------------------------------------------------------------
@pytest.mark.parametrize("method", [m for m in METHODS if m != "midpoint"])
def test_scipy_methods_solve_the_harmonic_oscillator(method):
    """y = sin t: each run's error is within the error it estimated for itself (tolerances
    times the solution's size, summed over the steps it took)."""
    te = np.linspace(0, 2 * np.pi, 9)
    run = integrate(lambda s, y: np.array([y[1], -y[0]]) if np.ndim(y) == 1
                    else np.vstack([y[1], -y[0]]), (0, 2 * np.pi), [0.0, 1.0], method,
                    t_eval=te, rtol=1e-8, atol=1e-10)
    assert run.success and run.steps > 0 and run.calls >= run.steps
    assert np.abs(run.y[0] - np.sin(te)).max() <= run.steps * (1e-8 + 1e-10)


def test_a_run_says_what_it_reached_and_cannot_be_changed():
    """y' = -y: the samples' shapes, the work counted (RK45 spends six right-hand sides on
    each accepted step, first-same-as-last), the exact solution 2 exp(-t) within the
    tolerances, and a Run is read-only."""
    import dataclasses
    te = np.linspace(0, 1, 5)
    run = integrate(lambda s, y: -y, (0, 1), [1.0, 2.0], "RK45", t_eval=te, rtol=1e-8,
                    atol=1e-10)
    assert run.t.shape == (5,) and run.y.shape == (2, 5) and run.t_end == 1.0
    assert run.success and run.steps > 0 and run.calls >= 6 * run.steps
    assert run.evaluations == run.calls and run.jacobians == 0 and run.cpu >= 0
    assert np.abs(run.y[1] - 2 * np.exp(-te)).max() <= run.steps * (1e-8 * 2 + 1e-10)
    with pytest.raises(dataclasses.FrozenInstanceError):
        run.steps = 0


def test_midpoint_rule_is_second_order_in_energy():
    lag = formulations(get("pendulum_particle"), y0=[THETA0, 0.0],
                       models=["lagrange"])[0][0]
    te = np.linspace(0, 2.0, 21)
    errs = []
    for h in (0.04, 0.02, 0.01):
        run = lag.run("midpoint", (0, 2.0), te, step=h)
        errs.append(np.abs(lag.energy_change(run.y)).max())
    order = np.polyfit(np.log([0.04, 0.02, 0.01]), np.log(errs), 1)[0]
    assert round(order) == 2


def test_midpoint_energy_error_is_bounded_where_rk45_drifts():
    """Growth exponent of the energy error's envelope over 40 small-angle periods: 0 for the
    symplectic rule (bounded), 1 for RK45 (a drift linear in time)."""
    lag = formulations(get("pendulum_particle"), y0=[THETA0, 0.0],
                       models=["lagrange"])[0][0]
    end = 40 * 2 * np.pi * np.sqrt(L_ / G_)
    te = np.linspace(0, end, 2001)
    mid = lag.run("midpoint", (0, end), te, step=0.02)
    rk = lag.run("RK45", (0, end), te, rtol=1e-6)
    assert round(_growth(te, lag.energy_change(mid.y))) == 0
    assert round(_growth(te, lag.energy_change(rk.y))) == 1


def test_energy_of_a_damped_model_is_refused_with_the_reason():
    p = get("falling_container")
    assert "dissipation" in conservative_reason(p.model("lagrange"))
    with pytest.raises(ModelError, match="no conserved energy"):
        EnergyFunction(p.model("lagrange"), p.defaults())


# -- one-sided contacts and the span that fits the scene ---------------------------------------
def test_string_goes_slack_where_the_hand_energy_balance_says():
    """Simple pendulum (string length a = 0.8, g = 9.81) thrown from theta0 = 2 at 4 rad/s.
    By hand: T = M (g cos + a theta'^2) and theta'^2 = theta0'^2 + 2 g/a (cos - cos theta0), so
    T = 0 at cos(theta) = (2 g cos(theta0) - a theta0'^2) / (3 g) -- no integration."""
    from dualmech.numeric.contacts import watch
    a, g, th0, w0 = 0.8, 9.81, 2.0, 4.0
    hand = np.arccos((2 * g * np.cos(th0) - a * w0**2) / (3 * g))
    p = get("simple_pendulum")
    loose = watch(p, (0, 5), y0=[th0, w0], rtol=1e-9, atol=1e-11).first
    tight = watch(p, (0, 5), y0=[th0, w0], rtol=1e-11, atol=1e-13).first
    assert tight.reaction == "T" and "slack" in str(tight) and not tight.at_start
    assert abs(tight.state["theta"] - hand) <= abs(loose.state["theta"] - tight.state["theta"]) \
        + 8 * EPS * hand


def test_contact_that_would_have_to_pull_from_the_start_is_named():
    from dualmech.numeric.contacts import watch
    # track tilted past the horizontal (phi = 2.4), car at rest: F_r = m g cos(phi) cos(theta) < 0
    report = watch(get("toy_car"), (0, 1), y0=[0.3, 2.4, 0.0, 0.0])
    assert report.first.at_start and report.first.reaction == "F_r"
    assert "leaves the track" in str(report)


def test_scene_ends_where_the_block_reaches_the_end_of_the_incline():
    """Block on wedge (m = 1, M = 3, alpha = 0.6, g = 9.81), released at rest 1.2 m down a
    2 m incline (60 % into the declared range): q1'' = (M + m) g sin(a) / (M + m sin^2(a))
    is constant, so t = sqrt(2 (2 - 1.2) / q1'') -- and the integrator is exact on a parabola:
    only the root finder's rounding remains."""
    from dualmech.numeric.contacts import scene_span
    m, M, g, al = 1.0, 3.0, 9.81, 0.6
    acc = (M + m) * g * np.sin(al) / (M + m * np.sin(al)**2)
    span = scene_span(get("block_on_wedge"), 5.0)
    assert span.t_end == pytest.approx(np.sqrt(2 * 0.8 / acc), abs=64 * EPS)
    assert "q1 leaves its declared range [0, 2]" in span.reason
