"""Ball in a sphere (problems/ball_in_sphere.py): normal force twice, first integrals, simulation."""
import dataclasses

import numpy as np
import pytest
import sympy as sp

from dualmech import t
from dualmech.model.equations import to_plain
from dualmech.numeric import NumericModel, simulate
from dualmech.verify.published import check_published
from dualmech.problems.ball_in_sphere import (BallInSphere, a, g, hand_normal_force, m, phi,
                                     printed_energy, printed_momentum, theta, theta0, v)

problem = BallInSphere()
D = lambda q: q.diff(t)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("ball_in_sphere")


def test_mass_matrix_is_singular_only_at_the_poles():
    det = problem.model("lagrange").mass_matrix().det()
    assert sp.simplify(det - m**2 * a**4 * sp.sin(theta)**2) == 0
    assert problem.singular == (sp.sin(theta),)
    lo, hi = problem.coordinate_info(theta).range
    assert 0 < lo < hi < np.pi


def test_moment_about_the_vertical_axis_is_the_printed_momentum_balance():
    # tau_O . Z = 0 (weight parallel to Z, N through O): the equation is -d/dt (m a^2 sin^2 th ph')
    eq = problem.model("angular_momentum").equations[0]
    assert sp.simplify(eq + printed_momentum().diff(t)) == 0


def test_normal_force_from_both_derivations_is_the_hand_one(comparison):
    # hand (module docstring): N = m a (th'^2 + sin^2 th ph'^2) - m g cos th
    assert sp.simplify(comparison.reactions["N"] - hand_normal_force()) == 0
    assert comparison.reaction_derivations == {"N": ["newton_euler", "multiplier"]}
    # at rest at the bottom (theta = pi) the sphere carries the weight
    rest = comparison.reactions["N"].subs({D(theta): 0, D(phi): 0}).subs(theta, sp.pi)
    assert sp.simplify(rest - m * g) == 0


def test_a_wrong_first_integral_is_judged_wrong():
    # the judging has teeth: m a^2 sin(theta) phi' (one power of sin short) is not conserved,
    # and the energy with the extraction's theta' in place of phi' is not the energy
    class Misprinted(BallInSphere):
        def published(self):
            keep = {"momentum is conserved": (m * a**2 * sp.sin(theta) * D(phi)).diff(t),
                    "energy T + V": printed_energy().subs(D(phi), D(theta))}
            return [dataclasses.replace(p, printed=(keep[p.label],))
                    for p in super().published() if p.label in keep]
    verdicts = {v.label: v.verdict for v in check_published(Misprinted())}
    assert verdicts == {"momentum is conserved": "wrong", "energy T + V": "wrong"}


# -- the first integrals along a simulated motion ----------------------------------------
RTOL, ATOL = 1e-9, 1e-11          # the run that is checked
RTOL_FINE, ATOL_FINE = 1e-12, 1e-14   # the run that estimates its global error
_STATE = [theta, phi, D(theta), D(phi)]


def _function_and_gradient(expr, values):
    plain = to_plain(expr.subs(values), (theta, phi))
    args = [to_plain(s, (theta, phi)) for s in _STATE]
    f = sp.lambdify(args, plain, "numpy")
    grad = sp.lambdify(args, [plain.diff(s) for s in args], "numpy")
    return (lambda y: np.asarray(f(*y), dtype=float)), \
        (lambda y: np.array([np.broadcast_to(gi, y[0].shape) for gi in grad(*y)], dtype=float))


@pytest.fixture(scope="module")
def runs():
    values = problem.defaults()
    th0 = values[theta0]
    y0 = [th0, 0.0, 0.0, values[v] / (values[a] * np.sin(th0))]   # the source's start
    span = (0.0, 4.0)   # about three swings of a 0.5 m sphere
    coarse = simulate(problem, t_span=span, y0=y0, params=values, samples=80,
                      rtol=RTOL, atol=ATOL)
    fine = simulate(problem, t_span=span, y0=y0, params=values, samples=80,
                    rtol=RTOL_FINE, atol=ATOL_FINE)
    return values, coarse, fine


def _allowed_drift(grad, coarse, fine):
    """Bound on |H(y(t)) - H(y0)| from the integrator's own error control.

    DOP853 accepts a step when the RMS over the 2n components of ``e_i / (atol + rtol |y_i|)``
    is at most 1, so one step (or one dense-output sample) errs by at most
    ``sqrt(2n) (atol + rtol |y_i|)`` in each component.  The global error of the checked run
    is estimated by its difference from a run 1000 times tighter, whose own error is smaller
    by ``1000^(8/9)`` (global error ~ Tol^(p/(p+1)) for order p = 8).  To first order,
    ``|dH| <= sum_i |dH/dy_i| |e_i|``.
    """
    y = np.vstack([coarse.q, coarse.qd])
    y_fine = np.vstack([fine.q, fine.qd])
    ratio = (RTOL_FINE / RTOL) ** (8 / 9)
    local = np.sqrt(y.shape[0]) * (ATOL + RTOL * np.abs(y))
    error = (1 + ratio) * np.abs(y - y_fine) + local
    return np.sum(np.abs(grad(y)) * error, axis=0)


@pytest.mark.parametrize("which", ["momentum", "energy"])
def test_first_integral_stays_at_its_printed_value_along_a_simulated_motion(runs, which):
    values, coarse, fine = runs
    expr = printed_momentum() if which == "momentum" else printed_energy()
    H, grad = _function_and_gradient(expr, values)
    vv, aa, mm, gg, th0 = (values[s] for s in (v, a, m, g, theta0))
    # the source's constants: m a v sin(theta0) and m v^2/2 + m g a cos(theta0)
    printed = mm * aa * vv * np.sin(th0) if which == "momentum" else \
        mm * vv**2 / 2 + mm * gg * aa * np.cos(th0)
    drift = np.abs(H(np.vstack([coarse.q, coarse.qd])) - printed)
    allowed = _allowed_drift(grad, coarse, fine)
    assert np.all(drift <= allowed), float(np.max(drift / allowed))
    assert np.ptp(coarse.q[0]) > 0.1   # the motion is not trivial: theta really swings


def test_the_drift_bound_catches_a_quantity_that_is_not_conserved(runs):
    values, coarse, fine = runs
    H, grad = _function_and_gradient(m * a**2 * sp.sin(theta) * D(phi), values)
    y = np.vstack([coarse.q, coarse.qd])
    drift = np.abs(H(y) - H(y[:, :1]))
    assert np.any(drift > _allowed_drift(grad, coarse, fine))


def test_normal_force_along_the_motion_is_the_hand_one(runs):
    values, coarse, _ = runs
    N = sp.lambdify([to_plain(s, (theta, phi)) for s in _STATE],
                    to_plain(hand_normal_force().subs(values), (theta, phi)), "numpy")
    hand = N(*np.vstack([coarse.q, coarse.qd]))
    direct = NumericModel(problem.model("newton_euler"), values)
    for k, tk in enumerate(coarse.t):
        A, b = direct.system(tk, coarse.q[:, k], coarse.qd[:, k])
        # the same formula at the same state: the linear solve's rounding bound only
        tol = 64 * np.finfo(float).eps * np.linalg.cond(A) * max(1.0, np.max(np.abs(b)))
        assert abs(coarse.reactions["N"][k] - hand[k]) <= tol
