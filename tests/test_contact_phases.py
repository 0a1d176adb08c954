"""Contact phases chained (``Problem.phases``): a ladder on a smooth floor and wall
(tests/corpus/teacher_problems/sliding_ladder.py), released from rest at theta0 from the wall.

Independent results used here (by hand, not by dualmech):

* on the wall, energy gives theta'^2 = (3 g / L)(cos theta0 - cos theta), and the wall's push
  is N_w = m x_C'' = (3 m g / 4) sin(theta) (3 cos(theta) - 2 cos(theta0)): it reaches zero
  when cos(theta) = (2/3) cos(theta0) -- the classical result that the ladder leaves the wall
  when its top has fallen to 2/3 of its initial height;
* the time it takes, t* = integral of d(theta) / theta', computed here by quadrature with
  u = sqrt(cos theta0 - cos theta) (a smooth integrand): t* = integral_0^sqrt(c0/3) of
  2 du / (sqrt(3 g / L) sin(arccos(c0 - u^2)));
* off the wall no horizontal force acts: the centre's x' stays at its value at the switch,
  and T + V = m g L/2 cos(theta0) throughout (no impact: the wall's push went to zero).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad

from dualmech import Phase, problems
from dualmech.model.problem import ProblemError
from dualmech.numeric.phases import phase_chart, phase_series, simulate_phases

FILE = Path(__file__).resolve().parent / "corpus" / "teacher_problems" / "sliding_ladder.py"
M, L, G = 10.0, 4.0, 9.81      # the file's defaults
THETA0 = 0.3


@pytest.fixture(scope="module")
def run():
    ladder = problems.load(f"{FILE}:WallLadder")
    return simulate_phases(ladder, (0, 1.2), samples=240)


def hand_switch_time(theta0=THETA0):
    c0 = np.cos(theta0)
    k = np.sqrt(3 * G / L)
    value, _ = quad(lambda u: 2 / (k * np.sin(np.arccos(c0 - u * u))), 0, np.sqrt(c0 / 3),
                    epsabs=1e-13, epsrel=1e-13)
    return value


def test_the_ladder_leaves_the_wall_at_two_thirds_of_its_height(run):
    assert [ph.problem for ph in run.phases] == ["wall_ladder", "free_ladder"]
    (switch,) = run.switches
    assert switch.reaction == "N_w" and switch.target == "free_ladder"
    assert switch.time == pytest.approx(hand_switch_time(), rel=1e-8)
    wall = run.phases[0].trajectory
    assert np.cos(wall.q[0, -1]) / np.cos(THETA0) == pytest.approx(2 / 3, rel=1e-8)
    assert run.ended == ""


def test_the_wall_push_on_the_way_matches_the_hand_formula(run):
    wall = run.phases[0].trajectory
    theta = wall.q[0]
    hand = 0.75 * M * G * np.sin(theta) * (3 * np.cos(theta) - 2 * np.cos(THETA0))
    assert np.abs(wall.reactions["N_w"] - hand).max() < 1e-6 * M * G


def test_off_the_wall_momentum_and_energy_carry_on(run):
    wall, free = run.phases[0].trajectory, run.phases[1].trajectory
    th, w = wall.q[0, -1], wall.qd[0, -1]
    x, theta = free.q
    xd, thd = free.qd
    # the state mapped: the wall phase's last sample is the state carried (one run), so the
    # map holds to rounding (it held to 1e-9 when the samples came from a second run)
    assert x[0] == pytest.approx(L / 2 * np.sin(th), rel=1e-15, abs=0)
    assert np.abs(xd - L / 2 * np.cos(th) * w).max() < 1e-8            # x' conserved
    energy = (M / 2 * (xd**2 + (L / 2 * np.sin(theta) * thd)**2) + M * L**2 / 24 * thd**2
              + M * G * L / 2 * np.cos(theta))
    assert np.abs(energy - M * G * L / 2 * np.cos(THETA0)).max() < 1e-6
    assert (free.reactions["N_f"] > 0).all()


def hand_floor_time(theta0=THETA0):
    """Off the wall, x' stays v_s (its value at the switch) and energy holds:
    m v_s^2/2 + m L^2 (sin^2 theta / 4 + 1/12) theta'^2 / 2 + m g L cos(theta)/2
    = m g L cos(theta0)/2; the time from the switch to theta = pi/2 (the top on the floor)
    is the integral of d(theta) / theta' (theta' > 0 all the way: a smooth integrand)."""
    c0 = np.cos(theta0)
    cs = 2 * c0 / 3
    ths = np.arccos(cs)
    w_s = np.sqrt(3 * G / L * (c0 - cs))
    v_s = L / 2 * cs * w_s
    def rate(th):
        top = G * L / 2 * (c0 - np.cos(th)) - v_s**2 / 2
        return np.sqrt(top / (L**2 * (np.sin(th) ** 2 / 4 + 1 / 12) / 2))
    value, _ = quad(lambda th: 1 / rate(th), ths, np.pi / 2, epsabs=1e-13, epsrel=1e-13)
    return hand_switch_time(theta0) + value


def test_the_run_ends_where_the_ladder_leaves_its_declared_domain():
    """The teacher declares the angle's domain (0, pi/2): past it the top would sink through
    the floor, which the free ladder's model does not know.  The phased run stops there, at
    the time the hand quadrature gives, and says why."""
    ladder = problems.load(f"{FILE}:WallLadder")
    run = simulate_phases(ladder, (0, 3.0), samples=300)
    assert [ph.problem for ph in run.phases] == ["wall_ladder", "free_ladder"]
    free = run.phases[1].trajectory
    assert free.t[-1] == pytest.approx(hand_floor_time(), rel=1e-7)
    assert free.q[1, -1] == pytest.approx(np.pi / 2, abs=1e-9)
    assert "theta leaves its declared domain" in run.ended and "free_ladder" in run.ended


def test_the_chart_shows_both_phases_and_the_switch(run, tmp_path):
    series = phase_series(run)
    t, theta = series["theta"]
    assert np.isnan(theta).sum() == 1                     # one gap: the two phases' curves
    assert series["switches"] == [run.switches[0].time]
    t_x, _ = series["x"]
    assert t_x.min() == pytest.approx(run.switches[0].time)   # x exists after the switch only
    t_w, _ = series["N_w"]
    assert t_w.max() == pytest.approx(run.switches[0].time)
    path = phase_chart(run, tmp_path / "ladder.png")
    assert Path(path).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_break_with_no_next_phase_ends_the_run_and_says_why():
    run = simulate_phases(problems.get("toy_car"), (0, 3), y0=[0.3, 2.4, 0.0, 0.0])
    assert run.phases == [] and "F_r is negative from the start" in run.ended


def test_phase_declaration_mistakes_are_refused():
    ladder = problems.load(f"{FILE}:WallLadder")
    mod = __import__(type(ladder).__module__, fromlist=["x"])
    Free, theta, x, Lsym = mod.FreeLadder, mod.theta, mod.x, mod.L

    class NotOneSided(type(ladder)):
        phases = {"N_f": Phase(Free, {x: theta, theta: theta})}
        unilateral = {"N_w": "leaves the wall"}
    with pytest.raises(ProblemError, match="'N_f' is not a one-sided reaction"):
        NotOneSided().validate()

    class Missing(type(ladder)):
        phases = {"N_w": Phase(Free, {theta: theta})}
    with pytest.raises(ProblemError, match="coordinate x\\(t\\) has no expression"):
        Missing().validate()

    class Stray(type(ladder)):
        phases = {"N_w": Phase(Free, {x: sp.Symbol("h") * Lsym, theta: theta})}
    with pytest.raises(ProblemError, match="uses \\['h'\\]"):
        Stray().validate()
    with pytest.raises(TypeError, match="must be a problem class"):
        Phase("FreeLadder", {})


def test_cli_simulate_phases(capsys, tmp_path):
    import json
    from dualmech.cli.main import main
    chart = tmp_path / "ladder.png"
    status = main(["simulate", f"{FILE}:WallLadder", "--duration", "1.2", "--phases",
                   str(chart), "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert status == 0 and doc["phases"] == ["wall_ladder", "free_ladder"]
    assert doc["switches"][0]["time"] == pytest.approx(hand_switch_time(), rel=1e-8)
    assert chart.read_bytes()[:4] == b"\x89PNG"
