"""Plain ``dualmech simulate`` follows the contact phases a problem declares (issue 25,
point 7): the teacher's ladder on a smooth floor and wall
(tests/corpus/teacher_problems/sliding_ladder.py), released at rest at theta0 = 0.3 from the
wall, leaves the wall and slides on the floor alone.

Hand references (derived in tests/test_contact_phases.py, by quadrature, not by dualmech):
the switch where cos(theta) = (2/3) cos(theta0), at ``hand_switch_time()``; the free ladder's
top reaching the floor (theta = pi/2, the end of its declared domain) at ``hand_floor_time()``;
off the wall no horizontal force acts, so the centre's x' keeps its value at the switch,
(L/2) cos(theta_s) theta_s'.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from dualmech.cli.main import main
from test_contact_phases import L, THETA0, hand_floor_time, hand_switch_time

LADDER = str(Path(__file__).resolve().parent / "corpus" / "teacher_problems"
             / "sliding_ladder.py") + ":WallLadder"
TIGHT = ["--rtol", "1e-10", "--atol", "1e-12"]


def simulate(capsys, *argv):
    status = main(["simulate", LADDER, *argv])
    out = capsys.readouterr()
    return status, out.out, out.err


def test_plain_simulate_runs_both_phases_and_says_when_it_switched(capsys):
    status, out, err = simulate(capsys, "--duration", "1.2", "--json", *TIGHT)
    doc = json.loads(out)
    assert status == 0 and err == "" and doc["success"] and doc["ended"] == ""
    assert [ph["problem"] for ph in doc["phases"]] == ["wall_ladder", "free_ladder"]
    (switch,) = doc["switches"]
    assert switch["reaction"] == "N_w" and switch["target"] == "free_ladder"
    assert switch["time"] == pytest.approx(hand_switch_time(), rel=1e-8)
    wall, free = doc["phases"]
    assert wall["t_end"] == free["t_start"] == switch["time"] and free["t_end"] == 1.2
    assert np.cos(wall["final_state"][0]) / np.cos(THETA0) == pytest.approx(2 / 3, rel=1e-8)
    # the run's final state is the free ladder's, in its coordinates
    assert doc["final_coordinates"] == ["x", "theta", "x'", "theta'"] == free["coordinates"]
    assert doc["final_state"] == free["final_state"] and doc["t_final"] == 1.2
    assert doc["coordinates"] == ["theta", "theta'"] and doc["initial_state"] == [THETA0, 0]
    assert doc["contact"] is None            # the wall's letting go is a switch, not a warning


def test_the_samples_cover_every_phase(capsys):
    status, out, _ = simulate(capsys, "--duration", "1.2", "--json", "--samples", "121",
                              *TIGHT)
    doc = json.loads(out)
    rows = doc["samples"]
    t, phase, states = np.array(rows["t"]), np.array(rows["phase"]), rows["states"]
    assert status == 0 and t[0] == 0 and t[-1] == 1.2 and (np.diff(t) >= 0).all()
    switch = doc["switches"][0]["time"]
    assert set(phase[t < switch]) == {0} and set(phase[t > switch]) == {1}
    assert {len(s) for s, p in zip(states, phase) if p == 0} == {2}      # theta, theta'
    assert {len(s) for s, p in zip(states, phase) if p == 1} == {4}      # x, theta, x', theta'
    assert 100 <= len(t) <= 125                # 121 shared among the phases, >= 2 each
    wall_end = [s for s, p in zip(states, phase) if p == 0][-1]
    x_rate = np.array([s[2] for s, p in zip(states, phase) if p == 1])
    hand = L / 2 * np.cos(wall_end[0]) * wall_end[1]      # x' at the switch, then constant
    assert np.abs(x_rate - hand).max() < 1e-8


def test_the_run_stops_where_the_free_ladder_leaves_its_domain(capsys):
    status, out, err = simulate(capsys, "--json", *TIGHT)            # 10 s asked
    doc = json.loads(out)
    assert status == 1 and "stopped early" in err and "leaves its declared domain" in err
    assert not doc["success"] and doc["final_state"] is None
    assert doc["t_final"] == pytest.approx(hand_floor_time(), rel=1e-7)
    assert doc["phases"][-1]["final_state"][1] == pytest.approx(np.pi / 2, abs=1e-9)


def test_single_phase_keeps_the_old_warning(capsys):
    status, out, err = simulate(capsys, "--duration", "1.2", "--json", "--single-phase",
                                *TIGHT)
    doc = json.loads(out)
    assert status == 0 and "phases" not in doc and "switches" not in doc
    assert doc["coordinates"] == ["theta", "theta'"] and len(doc["final_state"]) == 2
    assert doc["contact"]["reaction"] == "N_w"
    assert doc["contact"]["time"] == pytest.approx(hand_switch_time(), rel=1e-8)
    assert "warning: N_w changes sign" in err


def test_text_output_names_each_phase_and_the_switch(capsys):
    status, out, _ = simulate(capsys, "--duration", "1.2", *TIGHT)
    assert status == 0 and out.startswith("wall_ladder -> free_ladder: ")
    assert "switch: t = 0.920034 s: N_w reaches zero; `wall_ladder` -> `free_ladder`" in out
    assert "phase 1, wall_ladder, t = 0 .. 0.920034 s" in out
    assert "phase 2, free_ladder, t = 0.920034 .. 1.2 s" in out


def test_a_problem_without_phases_is_simulated_as_before(capsys):
    assert main(["simulate", "simple_pendulum", "--duration", "1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert "phases" not in doc and doc["steps"] is not None and doc["contact"] is None


def test_phases_chart_and_single_phase_do_not_go_together(capsys, tmp_path):
    status, _, err = simulate(capsys, "--single-phase", "--phases", str(tmp_path / "a.png"))
    assert status == 2 and "give one of them" in err


def test_chart_draws_both_phases_beside_the_work_precision_diagrams(capsys, tmp_path):
    status = main(["chart", LADDER, "--out", str(tmp_path), "--quick", "--repeats", "1",
                   "--duration", "1.2", "--json", "--jobs", "1"])
    doc = json.loads(capsys.readouterr().out)
    assert status == 0 and doc["phases"] == ["wall_ladder", "free_ladder"]
    assert doc["switches"][0]["time"] == pytest.approx(hand_switch_time(), rel=1e-8)
    png = Path(doc["phases_chart"])
    assert png.name == "wall_ladder_phases.png" and str(png) in doc["files"]
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_an_input_the_phased_problem_does_not_declare_is_refused(capsys):
    status, out, err = simulate(capsys, "--input", "F=1")
    assert status == 2 and out == ""
    assert "'F' is not a given input of problem `wall_ladder`" in " ".join(err.split())
