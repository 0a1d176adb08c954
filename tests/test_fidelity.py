"""Fidelity ladders (dualmech.numeric.studies.fidelity): what each simplification costs, measured.

Hand references: the mobile robot with f = T = 0 conserves the horizontal momentum
(M + m) x' - m L cos(phi) phi' (problems/mobile_robot.py), so the detailed base moves by
x - x0 = m L (sin(phi) - sin(phi0)) / (M + m) while the simplified base stays put; the base's
balance M x'' = f - H gives the neglected reaction.  The pendulum's exact motion is in Jacobi
elliptic functions.
"""
import numpy as np
import pytest
from scipy.special import ellipj, ellipk

from dualmech.numeric import NumericModel, problem_parameters
from dualmech.numeric.studies.fidelity import has_ladder, ladder
from dualmech.numeric.integrators import integrate
from dualmech.problems import get

RTOL = 1e-10   # the ladder's default


@pytest.fixture(scope="module")
def robot():
    return ladder(get("mobile_robot"))


def _detailed_run(L):
    p = get("mobile_robot")
    nm = NumericModel(p.model("lagrange"), problem_parameters(p))
    te = np.linspace(*L.span, 201)
    y0 = [3.2, 0.6, 0.0, 0.0]           # 60 % into the declared ranges, at rest
    scales = np.array([7.0, 6.0, 6.0, 6.0])
    run = integrate(nm.rhs, L.span, y0, "DOP853", t_eval=te, rtol=RTOL, atol=RTOL * scales)
    return nm, run


def test_simplified_robot_misses_the_base_motion_the_momentum_balance_predicts(robot):
    simplified, detailed = robot.rungs
    assert detailed.error_path == 0 and simplified.neglects == "the pivot reaction H"
    _, run = _detailed_run(robot)
    m, M, L = 40.0, 100.0, 7 / 8       # m1 + m2, base, centre of arm + hand from the pivot
    gap = m * L * np.abs(np.sin(run.y[1]) - np.sin(0.6)) / (M + m)
    # both runs at rtol 1e-10, atol 1e-10 x the 7 m range: a few times that, accumulated
    assert simplified.by_coordinate["x"] * 7.0 == pytest.approx(gap.max(), abs=10 * RTOL * 7.0)


def test_neglected_pivot_reaction_is_what_the_base_balance_needs(robot):
    nm, run = _detailed_run(robot)
    xdd = nm.accelerations(run.t, run.y[:2], run.y[2:])[0]
    H = -100.0 * xdd                   # M x'' = f - H with f = 0
    # the same trajectory, H by two routes (the direct model's solve, the base balance)
    assert robot.rungs[0].neglected["H"] == pytest.approx(np.abs(H).max(), rel=1e-12)


def test_small_angle_rung_of_the_pendulum_against_the_elliptic_solution():
    lad = ladder(get("simple_pendulum"))
    linear = lad.rungs[0]
    assert linear.label.startswith("linearised") and linear.model == "linearised"
    a, w0 = 0.5, np.sqrt(9.81 / 0.8)   # released at rest 60 % into (-2.5, 2.5)
    t = np.linspace(*lad.span, 201)
    k = np.sin(a / 2)
    exact = 2 * np.arcsin(k * ellipj(ellipk(k**2) - w0 * t, k**2)[0])
    hand = np.abs(a * np.cos(w0 * t) - exact).max() / 5.0      # range of theta: 5 rad
    # the runs' local tolerance (rtol 1e-10 of the range), a few times over
    assert linear.by_coordinate["theta"] == pytest.approx(hand, abs=10 * RTOL)


def test_point_masses_below_rigid_rods_and_every_rung_costs_something():
    lad = ladder(get("n_link_pendulum"))
    labels = [r.label for r in lad.rungs]
    assert labels[1:] == ["point masses on massless rods", "uniform rigid rods"]
    assert lad.rungs[-1].error_path == 0 < lad.rungs[0].error_path < lad.rungs[1].error_path
    assert all(r.derivation_s > 0 and r.rhs_us > 0 for r in lad.rungs)
    assert "point masses on massless rods" in str(lad)


def test_which_problems_have_a_ladder():
    assert has_ladder(get("simple_pendulum")) and has_ladder(get("mobile_robot"))
    assert not has_ladder(get("falling_container"))   # falls: no equilibrium, no ladder


# -- the `fidelity` command (dualmech.cli.studies) ----------------------------------------
def _cli():
    import argparse
    from dualmech.cli.studies import register
    parser = argparse.ArgumentParser(prog="dualmech")
    register(parser.add_subparsers(dest="command"))
    return parser


def test_fidelity_command_without_a_ladder_says_where_to_look(capsys):
    args = _cli().parse_args(["fidelity", "falling_container"])
    assert args.func(args) == 2
    assert "has no fidelity ladder" in capsys.readouterr().err


def test_fidelity_command_prints_the_ladder(tmp_path, capsys):
    args = _cli().parse_args(["fidelity", "simple_pendulum", "--out", str(tmp_path)])
    assert args.func(args) == 0
    out = capsys.readouterr().out
    assert "linearised" in out and "RHS [us/call]" in out
    assert (tmp_path / "simple_pendulum_fidelity.png").stat().st_size > 0


def test_restrained_pendulum_ladder_shows_what_horizontal_elements_add():
    # the source's model (elements along the arcs) below the horizontal variant; hand ODEs
    # (problems/restrained_pendulum.py): m l^2 th'' = -c a^2 th' w(th)^2 - k b^2 s(th) w(th)
    # - m g l sin th, with (s, w) = (th, 1) along the arcs and (sin th, cos th) horizontal
    from scipy.integrate import solve_ivp
    lad = ladder(get("restrained_pendulum"))
    assert [r.problem for r in lad.rungs] == ["restrained_pendulum_horizontal",
                                              "restrained_pendulum",
                                              "restrained_pendulum_horizontal"]
    source = lad.rungs[1]
    assert source.label.startswith("source") and "b sin th" in source.neglects
    m, l, k, c, a, b, g = 1.0, 1.0, 40.0, 2.0, 0.4, 0.6, 9.81      # the declared values

    def ode(horizontal):
        def f(t, y):
            s, w = (np.sin(y[0]), np.cos(y[0])) if horizontal else (y[0], 1.0)
            return [y[1], -(c * a**2 * y[1] * w**2 + k * b**2 * s * w
                            + m * g * l * np.sin(y[0])) / (m * l**2)]
        return f
    y0 = [-1.4 + 0.6 * 2.8, 0.0]        # 60 % into the declared range, at rest
    te = np.linspace(*lad.span, 201)
    runs = [solve_ivp(ode(h), lad.span, y0, "DOP853", t_eval=te, rtol=1e-12, atol=1e-13).y
            for h in (False, True)]
    gap = np.abs(runs[0][0] - runs[1][0]).max() / 2.8      # theta's declared range is 2.8 wide
    assert gap > 1e-3                   # a real difference, far above the integration error
    # both ladder runs at rtol 1e-10 (atol 1e-10 x the range): a few hundred times that
    assert source.by_coordinate["theta"] == pytest.approx(gap, abs=300 * RTOL)


def test_helicopter_ladder_has_the_weight_as_its_top_rung():
    lad = ladder(get("helicopter_blade"))
    assert [r.problem for r in lad.rungs][1:] == ["helicopter_blade", "helicopter_blade_weighted"]
    assert lad.rungs[1].neglects.startswith("the blade's weight") and lad.rungs[1].error_path > 0
