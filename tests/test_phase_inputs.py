"""Contact phases driven by given inputs, with the tolerances asked for, and one source for a
phase's last sample and the state carried across.

The teacher's file: tests/corpus/teacher_problems/pushed_ladder.py -- a uniform ladder (m, L)
on a smooth wall and floor, released at rest at theta0 = 0.3 from the wall while a rope pulls
its foot along +x with F(t) = P (1 - cos 3t) (its declared default history).

Independent references (hand equations, not dualmech's):

* on the wall (one coordinate theta; Lagrange with Q = F L cos(theta)):
  theta'' = 3 g sin(theta) / (2 L) + 3 F cos(theta) / (m L), and the wall's push is
  N_w = m x_C'' - F with x_C = L/2 sin(theta); the switch is the first zero of N_w, located
  by scipy's DOP853 with an event at rtol 1e-12 (``hand_switch``);
* off the wall the only horizontal force is the rope: m x'' = F(t), so
  x'(t) - x'(t_s) = (P/m) (t - t_s - (sin 3t - sin 3t_s)/3) -- time runs on across the
  switch (a history restarted at 0 would give another curve);
* the state carried: x = L/2 sin(theta), x' = L/2 cos(theta) theta' at the switch.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from dualmech import problems
from dualmech.cli.main import main
from dualmech.numeric.phases import phase_chart, phase_series, simulate_phases

HERE = Path(__file__).resolve().parent / "corpus" / "teacher_problems"
PULLED = f"{HERE / 'pushed_ladder.py'}:PulledWallLadder"
M, L, G, P = 10.0, 4.0, 9.81, 8.0          # the file's defaults
THETA0 = 0.3


def rope(t):
    return P * (1 - np.cos(3 * t))


def hand_switch(force=rope):
    """The switch time and state ``(theta, theta')`` from the hand equations on the wall."""
    def acc(t, th):
        return 3 * G * np.sin(th) / (2 * L) + 3 * force(t) * np.cos(th) / (M * L)

    def wall(t, y):
        th, w = y
        return M * L / 2 * (np.cos(th) * acc(t, th) - np.sin(th) * w * w) - force(t)
    wall.terminal, wall.direction = True, -1
    sol = solve_ivp(lambda t, y: [y[1], acc(t, y[0])], (0, 3), [THETA0, 0.0],
                    method="DOP853", rtol=1e-12, atol=1e-14, events=wall)
    return float(sol.t_events[0][0]), sol.y_events[0][0]


@pytest.fixture(scope="module")
def run():
    return simulate_phases(problems.load(PULLED), (0, 1.1), samples=111)


def test_the_rope_drives_both_phases_and_the_switch_is_the_hand_ones(run):
    assert [ph.problem for ph in run.phases] == ["pulled_wall_ladder", "pulled_free_ladder"]
    (switch,) = run.switches
    t_s, (th_s, w_s) = hand_switch()
    assert switch.reaction == "N_w" and switch.time == pytest.approx(t_s, rel=1e-7)
    wall = run.phases[0].trajectory
    assert wall.q[0, -1] == pytest.approx(th_s, rel=1e-7)
    assert wall.qd[0, -1] == pytest.approx(w_s, rel=1e-7)
    # the pull makes the ladder leave the wall sooner than unpulled (0.920 s, at 2/3 of its
    # initial height), while its top is still higher
    assert t_s < 0.85 and np.cos(th_s) > 2 / 3 * np.cos(THETA0)


def test_time_runs_on_across_the_switch(run):
    free = run.phases[1].trajectory
    t, xd = free.t, free.qd[0]
    t_s = run.switches[0].time
    hand = xd[0] + P / M * (t - t_s - (np.sin(3 * t) - np.sin(3 * t_s)) / 3)
    assert np.abs(xd - hand).max() < 1e-7 * np.abs(hand).max()
    restarted = xd[0] + P / M * (t - t_s - np.sin(3 * (t - t_s)) / 3)   # the wrong clock
    assert np.abs(xd - restarted).max() > 1e-2


def test_a_phase_s_last_sample_is_the_state_carried_across(run):
    wall, free = run.phases[0].trajectory, run.phases[1].trajectory
    th, w = wall.q[0, -1], wall.qd[0, -1]
    assert wall.t[-1] == free.t[0] == run.switches[0].time
    # one source: the mapped last sample is the next phase's first, to rounding
    assert free.q[:, 0] == pytest.approx([L / 2 * np.sin(th), th], rel=1e-15, abs=0)
    assert free.qd[:, 0] == pytest.approx([L / 2 * np.cos(th) * w, w], rel=1e-15, abs=0)


def test_a_phase_that_does_not_declare_the_input_is_refused():
    """The teacher forgot the rope on the free ladder (the plain one of sliding_ladder.py):
    refused before anything runs, naming the input and the phase."""
    pulled = problems.load(PULLED)
    mod = __import__(type(pulled).__module__, fromlist=["x"])
    plain = problems.load(f"{HERE / 'sliding_ladder.py'}:FreeLadder")
    Phase = type(pulled.phases["N_w"])

    class Forgot(type(pulled)):
        phases = {"N_w": Phase(type(plain), {mod.x: mod.L / 2 * sp.sin(mod.theta),
                                            mod.theta: mod.theta})}
    with pytest.raises(ValueError, match="driven by F, but the phase after "
                                         "`pulled_wall_ladder` .N_w reaching zero., problem "
                                         "`free_ladder`, does not declare it"):
        simulate_phases(Forgot(), (0, 1))


def simulate(capsys, *argv):
    status = main(["simulate", PULLED, *argv])
    out = capsys.readouterr()
    return status, out.out, out.err


def test_cli_input_drives_every_phase(capsys):
    status, out, err = simulate(capsys, "--duration", "1.0", "--json", "--input", "F=12*t",
                                "--rtol", "1e-10", "--atol", "1e-12")
    doc = json.loads(out)
    assert status == 0 and err == "" and doc["inputs"] == {"F": "12*t"}
    assert [ph["problem"] for ph in doc["phases"]] == ["pulled_wall_ladder",
                                                      "pulled_free_ladder"]
    t_s, _ = hand_switch(lambda t: 12 * t)
    assert doc["switches"][0]["time"] == pytest.approx(t_s, rel=1e-7)
    # off the wall m x'' = 12 t
    free = doc["phases"][1]
    ts, t1 = free["t_start"], free["t_end"]
    gain = free["final_state"][2] - free["initial_state"][2]
    assert gain == pytest.approx(12 / M * (t1**2 - ts**2) / 2, rel=1e-7)


def test_cli_default_history_is_said(capsys):
    status, out, _ = simulate(capsys, "--duration", "0.5")
    assert status == 0 and "inputs: F = default: P*(1 - cos(3*t))" in out
    assert out.startswith("pulled_wall_ladder: ") and "phase 1, pulled_wall_ladder" in out


@pytest.mark.parametrize("chart", [False, True], ids=["plain", "phases-png"])
def test_cli_tolerances_are_honoured_and_said(capsys, tmp_path, chart):
    extra = ["--phases", str(tmp_path / "c.png")] if chart else []
    status, out, _ = simulate(capsys, "--duration", "1.0", "--json", "--rtol", "1e-5",
                              "--atol", "1e-7", *extra)
    doc = json.loads(out)
    assert doc["rtol"] == 1e-5 and doc["atol"] == 1e-7
    loose = simulate_phases(problems.load(PULLED), (0, 1.0), samples=2, rtol=1e-5, atol=1e-7)
    tight = simulate_phases(problems.load(PULLED), (0, 1.0), samples=2)
    assert doc["switches"][0]["time"] == loose.switches[0].time
    assert loose.switches[0].time != tight.switches[0].time


def test_cli_phases_default_tolerances_stay(capsys, tmp_path):
    status, out, _ = simulate(capsys, "--duration", "1.0", "--json", "--phases",
                              str(tmp_path / "c.png"))
    doc = json.loads(out)
    assert status == 0 and (doc["rtol"], doc["atol"]) == (1e-10, 1e-12)
    status, out, _ = simulate(capsys, "--duration", "1.0", "--json")
    assert (json.loads(out)["rtol"], json.loads(out)["atol"]) == (1e-8, 1e-10)


def test_the_chart_shows_the_input_the_units_and_why_the_run_ended(tmp_path):
    run = simulate_phases(problems.load(PULLED), (0, 3.0), samples=301)
    series = phase_series(run)
    t, f = series["F"]
    assert np.isnan(t).sum() == 1                            # in both phases, split at the switch
    assert np.nanmax(np.abs(f - rope(t))) < 1e-12            # the absolute time's rope
    wall, free = run.phases
    assert wall.units == {"theta": "rad", "N_w": "N", "N_f": "N", "F": "N"}
    assert free.units == {"x": "m", "theta": "rad", "N_f": "N", "F": "N"}
    assert wall.title == "Ladder on a smooth wall, its foot pulled"
    # the free ladder's top reaches the floor: the run ends at the angle's declared domain
    assert run.end == "theta leaves its declared domain (0, 1.571) (ladder from the wall)"
    assert free.trajectory.q[1, -1] == pytest.approx(np.pi / 2, abs=1e-9)
    png = Path(phase_chart(run, tmp_path / "pulled.png"))
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_run_with_no_next_phase_says_so_in_few_words():
    run = simulate_phases(problems.get("toy_car"), (0, 3), y0=[0.3, 2.4, 0.0, 0.0])
    assert run.end.startswith("F_r is negative from the start (the car leaves the track")
    assert run.end.endswith("`toy_car` declares no next phase for it")


def test_chart_draws_the_driven_phases_beside_the_work_precision_diagrams(capsys, tmp_path):
    status = main(["chart", PULLED, "--out", str(tmp_path), "--quick", "--repeats", "1",
                   "--duration", "1.0", "--json", "--jobs", "1"])
    doc = json.loads(capsys.readouterr().out)
    assert status == 0 and doc["phases"] == ["pulled_wall_ladder", "pulled_free_ladder"]
    assert doc["switches"][0]["time"] == pytest.approx(hand_switch()[0], rel=1e-7)
    png = Path(doc["phases_chart"])
    assert png.name == "pulled_wall_ladder_phases.png" and str(png) in doc["files"]
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
