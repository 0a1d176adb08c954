"""Satellite in polar coordinates (problems/satellite_polar.py): momentum, circular orbits."""
import numpy as np
import sympy as sp

from dualmech import t
from dualmech.numeric import simulate
from dualmech.model.steady import steady_rates
from dualmech.problems.satellite_polar import SatellitePolar, angular_momentum, frames, m, mu, r, theta

problem = SatellitePolar()
D = lambda q, n=1: q.diff(t, n)  # noqa: E731


def _zero(expr) -> bool:
    return sp.simplify(sp.expand(expr)) == 0


def test_polar_acceleration_from_the_frames():
    # hand: a = (r'' - r theta'^2) e_r + (r theta'' + 2 r' theta') e_theta
    f = frames()
    a = f.sat.acc(f.O).express(f.E).components
    hand = [D(r, 2) - r * D(theta)**2, r * D(theta, 2) + 2 * D(r) * D(theta), 0]
    assert all(_zero(x - y) for x, y in zip(a, hand))


def test_centre_is_the_declared_singular_set():
    assert _zero(problem.model("lagrange").mass_matrix().det() - m**2 * r**2)
    assert problem.singular == (r,)
    assert problem.coordinate_info(r).range[0] > 0


def test_angular_momentum_rate_is_r_times_the_direct_transverse_equation():
    # theta is ignorable (section 3.1), so m r^2 theta' is conserved; on the direct side its
    # rate is -r x (sum F - m a) . e_theta, which vanishes on the motion
    transverse = problem.model("newton_euler").equations[1]
    assert _zero(D(angular_momentum()) + r * transverse)
    lag_theta = problem.model("lagrange").equations[1]
    assert _zero(lag_theta - D(angular_momentum()))


def test_circular_orbit_rate_from_the_verified_equations():
    # hand: m r theta'^2 = m mu / r^2, i.e. theta'^2 = mu / r^3 (period 2 pi sqrt(r^3 / mu))
    for model in ("lagrange", "newton_euler"):
        rates = steady_rates(problem.model(model), [r], D(theta))
        assert len(rates) == 2
        assert all(_zero(w**2 - mu / r**3) for w in rates)


def _radius_wander(rate_factor: float) -> float:
    """Largest |r - r0| over one period, started on the library's circular-orbit rate."""
    values = problem.defaults()
    r0 = 2.0
    rate = max(float(w.subs(values).subs(r, r0))
               for w in steady_rates(problem.model("lagrange"), [r], D(theta)))
    period = 2 * np.pi / rate
    traj = simulate(problem, t_span=(0.0, period), y0=[r0, 0.3, 0.0, rate * rate_factor],
                    rtol=1e-11, atol=1e-13)
    return float(np.max(np.abs(traj.q[0] - r0)))


def test_simulated_orbit_stays_circular_at_the_library_rate():
    # started on the computed rate, r must wander less than with a start one part in a
    # million off it: the rate is right to better than 1e-6 of itself
    assert _radius_wander(1.0) < _radius_wander(1.0 + 1e-6)


def test_simulated_angular_momentum_is_conserved_to_the_integration_error():
    # an elliptic orbit; the energy drift of the same run measures the integration error
    values = problem.defaults()
    traj = simulate(problem, t_span=(0.0, 12.0), y0=[2.0, 0.0, 0.3, 0.6], rtol=1e-10,
                    atol=1e-12)
    rr, rd, thd = traj.q[0], traj.qd[0], traj.qd[1]
    M_, MU = values[m], values[mu]
    p = M_ * rr**2 * thd
    E = M_ * (rd**2 + rr**2 * thd**2) / 2 - M_ * MU / rr
    assert rr.min() < 1.2 and rr.max() > 2.1    # a real ellipse (r from 1.08 to 2.16), not a circle
    drift_p = np.max(np.abs(p - p[0])) / abs(p[0])
    drift_E = np.max(np.abs(E - E[0])) / abs(E[0])
    assert drift_p <= max(10 * drift_E, 10 * np.finfo(float).eps)
