"""One-sided reactions and declared bounds as CVODE event functions compiled to C
(:func:`dualmech.numeric.contacts.watch` with ``method="auto"``), against scipy's route (Python
event functions on ``solve_ivp``'s dense output) and against results derived by hand.

Independent results used here (by hand, not by dualmech):

* ladder on a smooth floor and wall (tests/corpus/teacher_problems/sliding_ladder.py, m = 10,
  L = 4, g = 9.81), released from rest at theta0 = 0.3 from the wall: energy gives
  theta'^2 = (3 g / L)(cos theta0 - cos theta); the centre's horizontal acceleration gives the
  wall's push N_w = (3 m g / 4) sin(theta) (3 cos(theta) - 2 cos(theta0)), zero where
  cos(theta) = (2/3) cos(theta0) (the top at 2/3 of its initial height); the time to get
  there is the integral of d(theta) / theta', by quadrature in u = sqrt(cos theta0 - cos theta):
  t* = integral_0^sqrt(c0/3) of 2 du / (sqrt(3 g / L) sin(arccos(c0 - u^2)));
* simple pendulum (M = 1, a = 0.8, g = 9.81) released at rest from theta0: energy gives
  T = M g (3 cos(theta) - 2 cos(theta0)) >= M g cos(theta0) > 0 for |theta0| < pi/2, equal at
  the turning points: the string never goes slack;
* toy car at rest (m = 0.2, g = 9.81), the source's k_B balance: F_r = m g cos(theta) cos(phi),
  negative with the track tilted past the horizontal (phi = 2.4).

Tolerances: each route's error at the tight tolerance is bounded by its own distance from the
loose run (the error shrinks with the tolerance), plus rounding.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

from dualmech import problems
from dualmech.numeric import cvode
from dualmech.numeric.contacts import scene_span, watch
from dualmech.numeric.cvode import CvodeUnavailable
from dualmech.numeric.phases import simulate_phases

FILE = Path(__file__).resolve().parent / "corpus" / "teacher_problems" / "sliding_ladder.py"
M, L, G = 10.0, 4.0, 9.81      # the ladder file's defaults
THETA0 = 0.3
EPS = np.finfo(float).eps
LOOSE, TIGHT = (1e-9, 1e-11), (1e-12, 1e-14)
ROUTES = ("CVODE-Adams", "DOP853")

pytestmark = pytest.mark.skipif(cvode.available() is not None,
                                reason=f"CVODE cannot run here: {cvode.available()}")


def hand_switch_time(theta0=THETA0):
    c0 = np.cos(theta0)
    k = np.sqrt(3 * G / L)
    value, _ = quad(lambda u: 2 / (k * np.sin(np.arccos(c0 - u * u))), 0, np.sqrt(c0 / 3),
                    epsabs=1e-13, epsrel=1e-13)
    return value


@pytest.fixture(scope="module")
def ladder():
    return problems.load(f"{FILE}:WallLadder")


@pytest.fixture(scope="module")
def breaks(ladder):
    """``{(route, tolerance): report}`` of the ladder run on both routes at both tolerances."""
    return {(r, tol): watch(ladder, (0, 3), rtol=tol[0], atol=tol[1], method=r)
            for r in ROUTES for tol in (LOOSE, TIGHT)}


@pytest.mark.parametrize("route", ROUTES)
def test_ladder_leaves_the_wall_when_the_hand_quadrature_says(breaks, route):
    loose, tight = breaks[route, LOOSE], breaks[route, TIGHT]
    assert tight.method == route and tight.fallback == ""
    assert tight.first.reaction == "N_w" and not tight.first.at_start
    assert "the ladder leaves the wall" in str(tight.first)
    hand = hand_switch_time()
    assert abs(tight.first.time - hand) <= abs(loose.first.time - tight.first.time) \
        + 8 * EPS * hand
    # where: the top at 2/3 of its initial height, as cos(theta) / cos(theta0)
    ratio = np.cos(tight.first.state["theta"]) / np.cos(THETA0)
    loose_ratio = np.cos(loose.first.state["theta"]) / np.cos(THETA0)
    assert abs(ratio - 2 / 3) <= abs(loose_ratio - ratio) + 8 * EPS
    assert tight.t_end == tight.first.time


def test_compiled_and_scipy_event_times_agree_within_their_own_errors(breaks):
    c, s = breaks["CVODE-Adams", TIGHT], breaks["DOP853", TIGHT]
    spread = (abs(breaks["CVODE-Adams", LOOSE].first.time - c.first.time)
              + abs(breaks["DOP853", LOOSE].first.time - s.first.time))
    assert abs(c.first.time - s.first.time) <= spread + 8 * EPS
    # the wall's push at the compiled route's break state, by the hand formula: zero there
    theta = c.first.state["theta"]
    push = 0.75 * M * G * np.sin(theta) * (3 * np.cos(theta) - 2 * np.cos(THETA0))
    assert abs(push) <= 1e-9 * M * G
    # the floor still pushes at the break (only N_w let go), on both routes alike
    assert c.minimum["N_f"][0] > 0 and s.minimum["N_f"][0] > 0


def test_auto_takes_the_compiled_route_and_times_it(ladder, breaks):
    auto = watch(ladder, (0, 3), rtol=LOOSE[0], atol=LOOSE[1])
    assert auto.method == "CVODE-Adams" and auto.fallback == ""
    assert auto.first.time == breaks["CVODE-Adams", LOOSE].first.time
    assert 0 < auto.cpu < 1


@pytest.mark.parametrize("route", ROUTES)
def test_a_string_that_never_slackens_runs_to_the_end(route):
    pendulum = problems.get("simple_pendulum")
    theta0 = 1.1
    report = watch(pendulum, (0, 5), y0=[theta0, 0.0], method=route)
    assert report.first is None and report.stopped is None and report.method == route
    assert report.t_end == 5.0
    value, _ = report.minimum["T"]
    floor = 1.0 * 9.81 * np.cos(theta0)         # M g cos(theta0), at the turning points
    assert value >= floor * (1 - 1e-9) and value == pytest.approx(floor, rel=1e-3)
    assert str(report).startswith("every one-sided contact holds up to t = 5 s")


@pytest.mark.parametrize("route", ROUTES)
def test_a_contact_pulling_from_the_start_is_reported_not_integrated(route):
    car = problems.get("toy_car")
    report = watch(car, (0, 3), y0=[0.3, 2.4, 0.0, 0.0], method=route)
    assert report.first.at_start and report.first.reaction == "F_r" and report.t_end == 0.0
    assert report.method == "" and report.cpu == 0.0          # nothing was integrated
    assert report.minimum["F_r"][0] == pytest.approx(0.2 * 9.81 * np.cos(0.3) * np.cos(2.4),
                                                     rel=1e-12)
    assert "from the start" in str(report)


def test_fallback_when_cvode_is_unavailable_gives_the_scipy_answer(ladder, breaks,
                                                                  monkeypatch):
    monkeypatch.setattr(cvode, "available", lambda: "no SUNDIALS here (test)")
    report = watch(ladder, (0, 3), rtol=TIGHT[0], atol=TIGHT[1])
    assert report.method == "DOP853" and report.fallback == "no SUNDIALS here (test)"
    assert report.first.time == breaks["DOP853", TIGHT].first.time
    run = simulate_phases(ladder, (0, 1.2), samples=60)
    assert run.method == "DOP853" and run.fallback == "no SUNDIALS here (test)"
    assert run.switches[0].time == pytest.approx(hand_switch_time(), rel=1e-8)


def test_a_cvode_method_by_name_is_refused_where_it_cannot_run(ladder, monkeypatch):
    def no_driver():
        raise CvodeUnavailable("no SUNDIALS here (test)")
    monkeypatch.setattr(cvode, "driver", no_driver)
    with pytest.raises(CvodeUnavailable, match="no SUNDIALS here"):
        watch(ladder, (0, 3), method="CVODE-Adams")
    # auto: the driver failing after the check falls back too, saying why
    monkeypatch.setattr(cvode, "available", lambda: None)
    report = watch(ladder, (0, 3))
    assert report.method == "DOP853" and report.fallback == "no SUNDIALS here (test)"


def test_python_events_and_bad_methods_are_refused_or_routed_to_scipy(ladder):
    def python_event(t, y):
        return y[0] - 1.0
    python_event.terminal, python_event.direction, python_event.what = True, 1, "theta = 1"
    with pytest.raises(CvodeUnavailable, match="event function in Python"):
        watch(ladder, (0, 3), method="CVODE-BDF", extra_events=[python_event])
    report = watch(ladder, (0, 3), extra_events=[python_event])
    assert report.method == "DOP853" and "event function in Python" in report.fallback
    with pytest.raises(ValueError, match="`method` must be one of"):
        watch(ladder, (0, 3), method="Euler")


@pytest.mark.parametrize("route", ROUTES)
def test_a_declared_range_ends_the_scene_on_both_routes(route, monkeypatch):
    """Block on wedge (m = 1, M = 3, alpha = 0.6, g = 9.81) released 1.2 m down its 2 m
    incline: q1'' = (M + m) g sin(a) / (M + m sin^2(a)) is constant, so it reaches the end at
    t = sqrt(2 (2 - 1.2) / q1'') -- a parabola both methods follow to rounding."""
    if route == "DOP853":
        monkeypatch.setattr(cvode, "available", lambda: "scipy's route (test)")
    m, Mw, g, al = 1.0, 3.0, 9.81, 0.6
    acc = (Mw + m) * g * np.sin(al) / (Mw + m * np.sin(al)**2)
    span = scene_span(problems.get("block_on_wedge"), 5.0)
    assert span.t_end == pytest.approx(np.sqrt(2 * 0.8 / acc), abs=64 * EPS)
    assert "q1 leaves its declared range [0, 2]" in span.reason


def test_cli_phases_reports_the_method_and_its_cpu_time(capsys, tmp_path, monkeypatch):
    from dualmech.cli.main import main
    args = ["simulate", f"{FILE}:WallLadder", "--duration", "1.2", "--phases",
            str(tmp_path / "ladder.png"), "--json"]
    assert main(args) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["method"] == "CVODE-Adams" and doc["fallback"] is None
    assert 0 < doc["cpu_seconds"] < 1
    assert doc["switches"][0]["time"] == pytest.approx(hand_switch_time(), rel=1e-8)
    monkeypatch.setattr(cvode, "available", lambda: "no SUNDIALS here (test)")
    assert main(args) == 0
    out = capsys.readouterr()
    doc = json.loads(out.out)
    assert doc["method"] == "DOP853" and doc["fallback"] == "no SUNDIALS here (test)"
    assert "CVODE cannot run here (no SUNDIALS here (test))" in out.err
    assert doc["switches"][0]["time"] == pytest.approx(hand_switch_time(), rel=1e-8)


def test_single_phase_simulate_warns_where_the_ladder_would_have_to_pull_the_wall(capsys):
    """Phases turned off (``--single-phase``; by default plain simulate follows the declared
    phases, tests/test_simulate_phases.py): the run goes on holding the ladder to the wall,
    and says where the wall would have to pull (the hand quadrature's time), on the route
    that ran."""
    from dualmech.cli.main import main
    base = ["simulate", f"{FILE}:WallLadder", "--duration", "1.5", "--json", "--single-phase"]
    times = {}
    for tol in (LOOSE, TIGHT):
        assert main(base + ["--rtol", str(tol[0]), "--atol", str(tol[1])]) == 0
        out = capsys.readouterr()
        contact = json.loads(out.out)["contact"]
        assert contact["reaction"] == "N_w" and not contact["at_start"]
        assert contact["method"] == "CVODE-Adams" and 0 < contact["cpu_seconds"] < 1
        assert f"warning: {contact['message']}" in out.err
        times[tol] = contact["time"]
    hand = hand_switch_time()
    assert abs(times[TIGHT] - hand) <= abs(times[LOOSE] - times[TIGHT]) + 8 * EPS * hand
    assert main(["simulate", "simple_pendulum", "--duration", "2", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["contact"] is None    # T > 0 all the way


@pytest.mark.parametrize("route", ROUTES)
def test_car_thrown_over_the_pivot_axis_leaves_the_track_where_the_hand_balance_says(route):
    """Toy car (m = 0.2, R = 0.5, g = 9.81), track at rest (phi = phi' = 0, so phi stays 0),
    thrown from theta = 1.2 at 5 rad/s: it passes theta = pi/2, where the mass matrix
    diag(m R^2, m R^2 cos^2 theta) is singular (the declared singular set, which a watch does
    not stop at: with phi at rest the car's motion is regular there), and goes on.  By hand, the k_B balance
    F_r = m (g cos(theta) + R theta'^2) and energy theta'^2 = 25 + 2 (g/R)(cos theta - cos 1.2)
    give F_r = 0 at cos(theta) = (2 g cos(1.2) - 25 R) / (3 g); the time by quadrature."""
    g, R = 9.81, 0.5
    angle = np.arccos((2 * g * np.cos(1.2) - 25 * R) / (3 * g))
    rate = lambda th: np.sqrt(25 + 2 * g / R * (np.cos(th) - np.cos(1.2)))  # noqa: E731
    hand = quad(lambda th: 1 / rate(th), 1.2, angle, epsabs=1e-14, epsrel=1e-13)[0]
    car = problems.get("toy_car")
    runs = [watch(car, (0, 2), y0=[1.2, 0.0, 5.0, 0.0], rtol=tol[0], atol=tol[1],
                  method=route).first for tol in (LOOSE, TIGHT)]
    loose, tight = runs
    assert tight.reaction == "F_r" and tight.state["phi"] == 0.0
    assert abs(tight.time - hand) <= abs(loose.time - tight.time) + 8 * EPS * hand
    assert abs(tight.state["theta"] - angle) <= \
        abs(loose.state["theta"] - tight.state["theta"]) + 8 * EPS * angle


def test_a_reaction_through_a_pole_is_decided_exactly_and_stops_with_a_clear_error(
        monkeypatch):
    """A made-up direct model whose reaction is lam = c / x (its system [[1, 0], [0, x]] is
    singular at x = 0), watched along x = 2 - t^2 / 2: near x = 0 the compiled solve flags the
    states, the driver hands them to Python (decided exactly), and the run stops with
    SingularityError at t = 2 -- never a sign change located on garbage."""
    import sympy as sp

    from dualmech import EquationSet, coordinate, t
    from dualmech.numeric import NumericModel
    from dualmech.numeric.cvode import integrate_until
    from dualmech.numeric.cvode_events import ReactionEvent, Stops
    from dualmech.numeric.model import SingularityError
    x, g, c, lam = coordinate("x"), *sp.symbols("g c lam", positive=True)
    ref = NumericModel(EquationSet("fall", (x,), (x.diff(t, 2) + g,)), {g: 1.0})
    direct = NumericModel(EquationSet("fall_r", (x,), (x.diff(t, 2) + g, x * lam - c),
                                      unknowns=(lam,)), {g: 1.0, c: 1.0})
    assert direct.solve(0.0, [2.0], [0.0]).tolist() == [-1.0, 0.5]
    exact = []
    values = Stops.values
    monkeypatch.setattr(Stops, "values",
                        lambda self, time, y: exact.append(time) or values(self, time, y))
    with pytest.raises(SingularityError, match=r"the system of `fall_r` is singular at t=2, "):
        integrate_until(ref, (0, 5), [2.0, 0.0],
                        Stops(ref, reactions=[ReactionEvent("lam", direct, 1)]))
    assert exact and all(abs(time - 2.0) < 1e-6 for time in exact)   # flagged near x = 0 only
