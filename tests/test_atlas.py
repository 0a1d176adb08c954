"""The stability atlas (dualmech.numeric.studies.singularities, .regimes, .atlas): the detections.

Hand references: the toy car's mass matrix diag(m R^2, m R^2 cos^2 theta) (problems/toy_car.py),
the two-rod linkage's x form M + m l^2 / D with D = 4 l^2 sin^2 theta, the falling container's
relative mode lambda = -c/(2 mu) +- i sqrt(k/mu - (c/(2 mu))^2), mu = m1 m2/(m1 + m2), and the
pendulum's exact motion in Jacobi elliptic functions.
"""
import numpy as np
import pytest
from scipy.special import ellipj, ellipk

from dualmech.numeric.studies.atlas import atlas
from dualmech.numeric.studies.regimes import (chaos, dae_drift, growth_exponent, linearisation,
                                             stability_radius, stiffness)
from dualmech.numeric.studies.singularities import GARBAGE, WRONG, probe, scan, verdict_word
from dualmech.numeric.scene import scene
from dualmech.problems import get

EPS = np.finfo(float).eps


def _points(s, form):
    return sorted((p for p in s.points if p.formulation == form), key=lambda p: p.value)


# -- coordinate singularities -------------------------------------------------------------------
def test_toy_car_mass_matrix_vanishes_at_the_pivot_axis():
    s = scan(get("toy_car"))
    lag = _points(s, "lagrange")
    # det M = m^2 R^4 cos^2(theta): zero at theta = +-pi/2, smallest singular value ~ d^2
    assert [p.value for p in lag] == pytest.approx([-np.pi / 2, np.pi / 2], abs=1e-6)
    assert all(p.kind == "det M = 0" and round(p.order) == 2 for p in lag)
    assert all(p.declared == "cos(theta)" for p in lag)
    # the direct form's j_B row holds m R cos(theta) phi'': one power of the distance
    assert all(round(p.order) == 1 for p in _points(s, "newton_euler"))


def test_two_rod_x_form_mass_is_unbounded_at_the_fold_and_bar_forces_undetermined_upright():
    s = scan(get("two_rod_linkage"))
    x_form = _points(s, "lagrange_x")
    assert [p.value for p in x_form] == pytest.approx([-np.pi, 0.0, np.pi], abs=1e-6)
    assert all(p.kind == "M unbounded" and round(p.order) == 2 and p.declared == "sin(theta)"
               for p in x_form)
    # theta = pi/2: the right bar is vertical, its force parallel to the shaft's -- the motion
    # is regular (the Lagrangian in theta does not notice) but F_R and N are not separable
    dae = _points(s, "multiplier (DAE, index 1)")
    assert [p.value for p in dae] == pytest.approx([-np.pi / 2, np.pi / 2], abs=1e-6)
    assert all(p.kind == "reactions undetermined" and not p.declared for p in dae)
    assert not _points(s, "lagrange")


def test_euler_angles_lock_where_the_nutation_is_zero_or_pi():
    s = scan(get("rigid_body_euler_angles"))
    lag = _points(s, "lagrange")
    assert [p.value for p in lag] == pytest.approx([-np.pi, 0.0, np.pi], abs=1e-6)
    assert all(p.declared == "sin(theta)" and p.coordinate == "theta" for p in lag)


@pytest.fixture(scope="module")
def fold():
    return probe(get("two_rod_linkage"), methods=("RK45", "BDF"))


def test_running_into_the_fold_in_x(fold):
    runs = {(r.method, r.mode): r for r in fold.runs}
    # RK45 evaluates past the fold and stops, naming the state (x = 2 l - l0 = 1.4)
    assert not runs["RK45", "unguarded"].success
    assert "x=1.4" in runs["RK45", "unguarded"].message
    # BDF steps over it and reports success with wrong coordinates: detected, its error
    # beyond 1 % of the state's own size
    assert runs["BDF", "unguarded"].verdict.startswith("wrong")
    assert runs["BDF", "unguarded"].error > WRONG
    # guarded runs keep the last good state, and the theta form continues from it; the
    # degeneracy at the switch is below GARBAGE, so the error is at most GARBAGE x rtol
    for m in ("RK45", "BDF"):
        assert not runs[m, "guarded"].success
        assert runs[m, "switched"].success
        assert runs[m, "switched"].error <= GARBAGE * fold.rtol


def _spherical_pendulum(span, te, y0, R=0.5, g=9.81):
    """The toy car's motion in Cartesian components, derived independently: a point on a
    sphere of radius R under gravity, ``r'' = g + lam r`` with ``lam = -(v.v + g.r)/R^2``
    (from differentiating ``r.r = R^2`` twice), started where the angles put it
    (``r = -R Rx(phi) Ry(theta) k``, the track frames of problems/toy_car.py)."""
    from scipy.integrate import solve_ivp
    th, ph, thd, phd = y0

    def Rx(a):
        return np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])

    def Ry(a):
        return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])

    def dRy(a):
        return np.array([[-np.sin(a), 0, np.cos(a)], [0, 0, 0], [-np.cos(a), 0, -np.sin(a)]])
    k = np.array([0.0, 0.0, -R])
    dRx = np.array([[0, 0, 0], [0, -np.sin(ph), -np.cos(ph)], [0, np.cos(ph), -np.sin(ph)]])
    r0 = Rx(ph) @ Ry(th) @ k
    v0 = Rx(ph) @ dRy(th) @ k * thd + dRx @ Ry(th) @ k * phd
    gv = np.array([0.0, 0.0, -g])

    def rhs(t, y):
        r, v = y[:3], y[3:]
        lam = -(v @ v + gv @ r) / R**2
        return np.concatenate([v, gv + lam * r])
    sol = solve_ivp(rhs, span, np.concatenate([r0, v0]), method="DOP853", rtol=1e-13,
                    atol=1e-15, t_eval=te)
    return sol.y[:3], sol.y[3:]


def test_toy_car_runs_over_its_pole_are_judged_in_cartesian_components():
    # regression: errors were measured on the angles, where a move of the car by 1e-5 of the
    # track's size near the pole (cos theta = 3e-3) is a large change of phi -- BDF and
    # LSODA were called "wrong" (0.22 of the state's size) while every run stays within
    # ~1e-5 of the motion's size of the Cartesian reference below
    from dualmech.numeric.formulations import formulations
    problem = get("toy_car")
    pr = probe(problem)
    declared = problem.probes[0]
    span, te = pr.span, np.linspace(*pr.span, 101)
    r_ref, v_ref = _spherical_pendulum(span, te, declared.state)
    size_r = np.sqrt(((r_ref - r_ref.mean(axis=1, keepdims=True))**2).sum(axis=0).mean())
    size_v = np.sqrt(((v_ref - v_ref.mean(axis=1, keepdims=True))**2).sum(axis=0).mean())
    f = formulations(problem, y0=list(declared.state), stabilisations=("none",))[0][0]
    s = scene(problem)
    car = s.names.index("car")
    for r in pr.runs:
        if r.mode != "unguarded":
            continue
        assert r.verdict.startswith("right"), r.verdict
        run = f.run(r.method, span, te, rtol=pr.rtol)
        P, V = s.positions(te, run.y)[car], s.velocities(te, run.y)[car]
        mine = max(np.linalg.norm(P - r_ref, axis=0).max() / size_r,
                   np.linalg.norm(V - v_ref, axis=0).max() / size_v)
        assert mine <= GARBAGE * pr.rtol                        # right, independently
        assert r.error == pytest.approx(mine, rel=0.05, abs=1e-7)   # and the same measure


def test_verdict_words_follow_their_definitions():
    assert verdict_word(1e-4, 1e-6) == "right"          # 100 x rtol
    assert verdict_word(5e-3, 1e-6) == "degraded"       # 5000 x rtol, 0.5 %
    assert verdict_word(0.02, 1e-6) == "wrong"          # 2 % of the state's size
    assert verdict_word(float("nan"), 1e-6) == "wrong"


# -- stiffness ----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def stiff():
    return stiffness(get("falling_container"), values=(1e5, 1e6, 1e7),
                     methods=("RK45", "DOP853", "Radau"))


def _rounding_bound(k, m1, m2, c, g, l0, y0):
    """First-order bound on the eigenvalue error of a central-difference Jacobian of the
    (linear) falling container: the difference quotient is exact but for the rounding of the
    right-hand side, at most eps times the sum T_i of its terms' magnitudes per evaluation
    (here k (|x1| + |x2| + l0)/m_i + g: the spring terms cancel to the small result), so
    |dJ_ij| <= eps T_i / h_j with regimes.jacobian's step h_j = 1e-6 max(1, |y_j|); an
    eigenvalue moves by sum_ij |w_i v_j| |dJ_ij| / |w^H v| (w, v its left and right
    eigenvectors of the hand Jacobian)."""
    from scipy.linalg import eig
    J = np.array([[0, 0, 1, 0], [0, 0, 0, 1], [-k / m1, k / m1, -c / m1, c / m1],
                  [k / m2, -k / m2, c / m2, -c / m2]])
    lam, left, right = eig(J, left=True, right=True)
    i = np.argmax(np.abs(lam))
    w, v = left[:, i], right[:, i]
    sens = np.abs(np.outer(w.conj(), v)) / abs(w.conj() @ v)
    spring = k * (abs(y0[0]) + abs(y0[1]) + l0)
    T = np.array([0.0, 0.0, spring / m1 + g, spring / m2 + g])
    h = 1e-6 * np.maximum(1.0, np.abs(y0))
    return float((sens * EPS * np.outer(T, 1 / h)).sum())


def test_fastest_eigenvalue_is_the_hand_relative_mode(stiff):
    m1, m2, c, g, l0 = 3.0, 1.0, 4.0, 9.81, 0.3
    mu = m1 * m2 / (m1 + m2)
    y0 = np.array([2.2, 2.5, 0.0, 0.0])  # FallingContainer.stiff_scene: at rest, l0 apart
    for r in stiff.rows:
        hand = complex(-c / (2 * mu), np.sqrt(r["value"] / mu - (c / (2 * mu))**2))
        # the finite differences' rounding (7e-4 at k = 1e6, 7e-3 at 1e7): under 1 % of the
        # damping's share c/(2 mu) = 2.7 of the eigenvalue, so a wrong term still shows
        bound = _rounding_bound(r["value"], m1, m2, c, g, l0, y0)
        assert bound < 1e-2 * c / (2 * mu)
        assert abs(complex(*r["lambda"]) - hand) <= bound


def test_explicit_steps_follow_the_stability_boundary_implicit_ones_do_not_grow(stiff):
    for m in ("RK45", "DOP853"):
        rows = [r for r in stiff.rows if r["method"] == m]
        lam = [r["lambda_max"] for r in rows]
        assert round(np.polyfit(np.log(lam), np.log([r["steps"] for r in rows]), 1)[0]) == 1
        # same order of magnitude as T |lambda| / (the tableau's stability radius)
        assert all(round(np.log10(r["steps"] / r["min_steps"])) == 0 for r in rows)
    radau = [r["steps"] for r in stiff.rows if r["method"] == "Radau"]
    assert max(radau) == min(radau)
    assert stiff.crossover(implicit="Radau") == 1e5


def test_stability_radius_of_dormand_prince_on_the_negative_axis():
    # Hairer-Norsett-Wanner, Solving ODEs I, fig. IV.2.1: DOPRI5 reaches about -3.3
    assert round(stability_radius("RK45", np.pi), 1) == 3.3


# -- linearisation ------------------------------------------------------------------------------
def test_small_angle_model_errs_by_1_and_10_percent_where_the_elliptic_solution_says():
    lin = linearisation(get("simple_pendulum"), levels=(0.01, 0.1))
    w0 = np.sqrt(9.81 / 0.8)
    e_w = abs(lin.frequency - w0) / w0       # the finite-difference Jacobian's own error
    assert e_w <= 1e-8
    te = lin.times

    def hand_error(a):
        k = np.sin(a / 2)
        sn = ellipj(ellipk(k**2) - w0 * te, k**2)[0]
        return np.abs(2 * np.arcsin(k * sn) - a * np.cos(w0 * te)).max() / a
    from scipy.optimize import brentq
    for level, found in lin.thresholds.items():
        hand = brentq(lambda a: hand_error(a) - level, 0.01, 2.0, xtol=1e-12)
        # the two errors differ by at most 2 pi e_w (the linear phase over one period) plus
        # the nonlinear run's (rtol 1e-11); the error grows like a^2, so a moves by half that
        assert found == pytest.approx(hand, rel=(2 * np.pi * e_w + 1e-11) / (2 * level))


# -- DAE drift and chaos ----------------------------------------------------------------------------
def test_dae_drift_per_stabilisation():
    d = dae_drift(get("pendulum_particle"), duration=10.0)
    assert d.growth["none"] > 1 and d.growth["baumgarte"] < 1
    assert np.abs(d.residual["projection"]).max() <= 1e-13
    assert d.unit == "m" and not d.stopped


@pytest.mark.slow
def test_two_formulations_of_a_chaotic_pendulum_part_later_at_tighter_tolerance():
    c = chaos(get("compound_double_pendulum"), y0=[2.0, 2.5, 0.0, 0.0], duration=9.0,
              tolerances=(1e-4, 1e-6))
    horizons = [r["horizon"] for r in c.rows]
    assert all(r["diverged"] for r in c.rows) and horizons == sorted(horizons)
    assert not c.regular and c.lyapunov > 0


def test_growth_exponent_of_a_power_law():
    t = np.linspace(0, 10, 101)
    assert growth_exponent(t, 3 * t**2) == pytest.approx(2.0, abs=1e-12)


def test_atlas_says_why_a_section_does_not_apply():
    a = atlas(get("falling_container"), sections=("dae_drift", "chaos"), progress=False)
    assert "no DAE formulation" in a.skipped["dae_drift"]
    assert "does not conserve energy" in a.skipped["chaos"]
    assert "[chaos] not applicable" in str(a)


# -- the `atlas` command (dualmech.cli.studies) ------------------------------------------
def _cli():
    import argparse
    from dualmech.cli.studies import register
    parser = argparse.ArgumentParser(prog="dualmech")
    register(parser.add_subparsers(dest="command"))
    return parser


def test_atlas_command_prints_and_writes_a_section(tmp_path, capsys):
    args = _cli().parse_args(["atlas", "pendulum_particle", "--section", "dae_drift",
                              "--out", str(tmp_path)])
    assert args.func(args) == 0
    out = capsys.readouterr().out
    assert "[dae_drift]" in out and "|g| ~ t^" in out
    assert (tmp_path / "pendulum_particle_atlas_dae_drift.svg").stat().st_size > 0


def test_atlas_command_refuses_an_unknown_section(capsys):
    args = _cli().parse_args(["atlas", "toy_car", "--section", "gimbal"])
    assert args.func(args) == 2
    assert "unknown section(s) gimbal; choose from singularities" in capsys.readouterr().err


def test_atlas_charts_state_their_parameters_and_start(tmp_path):
    # the toy car's declared values (problems/toy_car.py: m 0.2 kg, R 0.5 m, g 9.81 m/s^2)
    # and its default start, 60 % into each declared range (theta in [-1.2, 1.2] -> 0.24)
    a = atlas(get("toy_car"), sections=("singularities",), progress=False)
    text = a.conditions["singularities"]
    assert text.startswith(r"$m$ = 0.2 kg, $R$ = 0.5 m, $g$ = 9.81 m/s^2; from $\theta$ = "
                           r"0.24 rad, $\phi$ = 0.6 rad, $\dot{\theta}$ = 0 rad/s, "
                           r"$\dot{\phi}$ = 0 rad/s")
    from dualmech.numeric.charts import conditions
    assert conditions(get("toy_car"), {"R": 2.0}, [0.1, 0.2, 0.3, 0.4]).startswith(
        "m = 0.2 kg, R = 2 m, g = 9.81 m/s^2; from theta = 0.1 rad, phi = 0.2 rad, "
        "theta' = 0.3 rad/s, phi' = 0.4 rad/s")
