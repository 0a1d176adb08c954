"""Reaction values at a state (``dualmech show NAME --at ...``) when the formulas are past the
display budget: the direct form's value and the Kane referee's, checked against two routes
that share nothing with dualmech:

* by hand, a straight chain hanging down and turning with one rate ``w`` (all angles zero,
  every rate ``w``): no angular acceleration at that instant (gravity is along the chain and
  every ``sin(q_i - q_j)`` vanishes), so bead ``j`` at depth ``r_j`` only has the centripetal
  ``r_j w^2`` towards the pivot and ``T_i = sum_{j >= i} m_j (g + r_j w^2)``;
* at any other state, the chain in Cartesian coordinates written here in plain NumPy: each bead
  free in the plane, ``m_i a_i = weight + T_i u_i - T_(i+1) u_(i+1)`` (``u_i`` the unit vector
  from bead ``i`` to the joint above), and each rod's length held at the acceleration level,
  ``d_i . (a_i - a_(i-1)) + |v_i - v_(i-1)|^2 = 0``: 3n equations, solved by ``numpy.linalg``.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from dualmech import problems
from dualmech.cli.main import main

TEACHER = Path(__file__).resolve().parent / "corpus" / "teacher_problems" / "triple_pendulum.py"


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return status, out, err


def cartesian_tensions(m, l, g, q, qd) -> np.ndarray:
    """The rod tensions of a chain of point masses at ``(q, qd)``, by the Cartesian route."""
    n = len(m)
    p, v = np.zeros((n + 1, 2)), np.zeros((n + 1, 2))
    for i in range(n):
        p[i + 1] = p[i] + l[i] * np.array([np.sin(q[i]), -np.cos(q[i])])
        v[i + 1] = v[i] + l[i] * qd[i] * np.array([np.cos(q[i]), np.sin(q[i])])
    A, b = np.zeros((3 * n, 3 * n)), np.zeros(3 * n)     # unknowns: a_1..a_n (x, y), T_1..T_n
    for i in range(n):
        u = (p[i] - p[i + 1]) / l[i]               # from bead i+1 (0-based i) to the joint above
        A[2 * i: 2 * i + 2, 2 * i: 2 * i + 2] = m[i] * np.eye(2)
        A[2 * i: 2 * i + 2, 2 * n + i] = -u
        if i:                                     # the rod pulls the bead above the other way
            A[2 * i - 2: 2 * i, 2 * n + i] = u
        b[2 * i: 2 * i + 2] = [0.0, -m[i] * g]
        d = p[i + 1] - p[i]
        A[2 * n + i, 2 * i: 2 * i + 2] = d
        if i:
            A[2 * n + i, 2 * i - 2: 2 * i] = -d
        b[2 * n + i] = -np.dot(v[i + 1] - v[i], v[i + 1] - v[i])
    return np.linalg.solve(A, b)[2 * n:]


def _values(problem):
    d = {str(k): float(v) for k, v in problem.defaults().items()}
    n = len(problem.reactions)
    return [d[f"m{i}"] for i in range(1, n + 1)], [d[f"l{i}"] for i in range(1, n + 1)], d["g"]


def _show_at(capsys, spec, at=None):
    status, out, err = run(capsys, "show", spec, "--json", *(["--at", at] if at else []))
    assert status == 0, err
    return json.loads(out)["values_at_state"]


def test_teacher_file_straight_chain_turning_matches_the_hand_derivation(capsys):
    w = 2.0
    got = _show_at(capsys, TEACHER, f"a=0, b=0, c=0, a_dot={w}, b_dot={w}, c_dot={w}")
    m, l, g = _values(problems.load(str(TEACHER)))
    depth = np.cumsum(l)
    hand = [sum(m[j] * (g + depth[j] * w**2) for j in range(i, 3)) for i in range(3)]
    assert hand[2] == pytest.approx(9.705)        # 0.5 (9.81 + 2.4 * 4), by hand
    for i, expected in enumerate(hand, 1):
        value = got["values"][f"T{i}"]
        assert value["direct"] == pytest.approx(expected, rel=1e-12)
        assert value["referee"] == pytest.approx(expected, rel=1e-12)
        assert value["referee_model"] == "referee"
    assert got["default_state"] is False and sorted(got["given"]) == sorted(
        ["a", "b", "c", "a_dot", "b_dot", "c_dot"])


def test_teacher_file_at_a_general_state_matches_the_cartesian_route(capsys):
    q, qd = [0.4, -0.7, 0.9], [1.3, -0.5, 2.2]
    got = _show_at(capsys, TEACHER, "a=0.4, b=-0.7, c=0.9, a_dot=1.3, b_dot=-0.5, c_dot=2.2")
    expected = cartesian_tensions(*_values(problems.load(str(TEACHER))), q, qd)
    for i, value in enumerate(expected, 1):
        assert got["values"][f"T{i}"]["direct"] == pytest.approx(value, rel=1e-10)
        assert got["values"][f"T{i}"]["referee"] == pytest.approx(value, rel=1e-10)
    assert abs(expected[2] - expected[0]) > 1.0      # a state that tells the tensions apart


def test_catalogue_problem_over_budget_gets_values_at_the_default_state(capsys):
    status, out, _ = run(capsys, "show", "n_link_pendulum")
    assert status == 0
    assert "reactions not solved symbolically" in out
    assert "the problem's default state inside its declared ranges" in out
    got = _show_at(capsys, "n_link_pendulum")
    assert got["default_state"] is True and got["given"] == []
    state = got["state"]
    q = [state[f"theta{i}"] for i in (1, 2, 3)]
    qd = [state[f"theta{i}_dot"] for i in (1, 2, 3)]
    expected = cartesian_tensions(*_values(problems.get("n_link_pendulum")), q, qd)
    for i, value in enumerate(expected, 1):
        assert got["values"][f"T{i}"]["direct"] == pytest.approx(value, rel=1e-10)
        assert got["values"][f"T{i}"]["referee"] == pytest.approx(value, rel=1e-10)


def test_unnamed_coordinates_keep_the_default_state(capsys):
    got = _show_at(capsys, "n_link_pendulum", "theta2_dot=3")
    assert got["state"]["theta2_dot"] == 3.0 and got["given"] == ["theta2_dot"]
    assert got["state"]["theta1"] == _show_at(capsys, "n_link_pendulum")["state"]["theta1"]


def test_a_formula_within_budget_gets_values_only_when_asked(capsys):
    status, out, _ = run(capsys, "show", "simple_pendulum", "--json")
    assert status == 0 and "values_at_state" not in json.loads(out)
    got = _show_at(capsys, "simple_pendulum", "theta=0, theta_dot=2")
    d = {str(k): float(v) for k, v in problems.get("simple_pendulum").defaults().items()}
    # the string pull at the lowest point, by hand: M (g + a theta'^2)
    assert got["values"]["T"]["direct"] == pytest.approx(d["M"] * (d["g"] + 4 * d["a"]),
                                                         rel=1e-12)



def test_at_sets_the_time_of_a_driven_problem(capsys):
    """The Kapitza pendulum's rod pull depends on the pivot's drive a cos(Omega t); by hand
    (the bob's radial balance in the pivot's accelerating frame, at rest):
    T = -m (Omega^2 a cos(Omega t) cos(theta) - g cos(theta))."""
    d = {str(k): float(v) for k, v in problems.get("kapitza_pendulum").defaults().items()}
    for when in (0.0, 0.001, 0.0037):
        at = f"theta=0.3, t={when}" if when else "theta=0.3"
        got = _show_at(capsys, "kapitza_pendulum", at)
        hand = -d["m"] * (d["Omega"] ** 2 * d["a"] * np.cos(d["Omega"] * when) * np.cos(0.3)
                          - d["g"] * np.cos(0.3))
        assert got["values"]["T"]["direct"] == pytest.approx(hand, rel=1e-12)
        assert got["time"] == when

HOSTILE = {
    "theta=": "is not a number",
    "theta": "has no '='",
    "": "is empty",
    ",,,": "is empty",
    "theta=nan": "is not a number",
    "theta=inf": "is not a number",
    "theta=1e999": "is not finite",
    "theta=__import__('os').system('true')": "is not a number",
    "theta=1+1": "is not a number",
    "theta=0x10": "is not a number",
    "thta=0.3": "is not a coordinate of `simple_pendulum`",
    "T=3": "is not a coordinate of `simple_pendulum`",
    "theta=0.1, theta=0.2": "is given twice",
    "theta=0.1; exec=1": "is not a coordinate of `simple_pendulum`",
    "1theta=0": "is not a coordinate name",
    "theta=" + "9" * 5000: "characters long",
    "theta=1\x00": "is not a number",
}


@pytest.mark.parametrize("text", sorted(HOSTILE), ids=lambda s: repr(s[:30]))
def test_hostile_at_is_refused_with_what_to_fix(capsys, text):
    status, out, err = run(capsys, "show", "simple_pendulum", "--at", text)
    assert status == 2
    assert HOSTILE[text] in err and "`--at`" in err
    assert "Traceback" not in err and out == ""     # refused before anything is shown


def test_check_gives_the_same_values_in_text_and_json(capsys):
    at = "a=0.4, b=-0.7, c=0.9, a_dot=1.3, b_dot=-0.5, c_dot=2.2"
    status, out, _ = run(capsys, "check", TEACHER, "--at", at)
    assert status == 0 and "reaction values at a state" in out
    expected = cartesian_tensions(*_values(problems.load(str(TEACHER))), [0.4, -0.7, 0.9],
                                  [1.3, -0.5, 2.2])
    assert f"T3 = {expected[2]:.10g}"[:12] in out
    status, out, _ = run(capsys, "check", TEACHER, "--at", at, "--json")
    got = json.loads(out)["values_at_state"]["values"]
    assert got["T1"]["referee"] == pytest.approx(expected[0], rel=1e-10)


def test_check_refuses_at_with_several_problems(capsys):
    status, _, err = run(capsys, "check", "simple_pendulum", "toy_car", "--at", "theta=0")
    assert status == 2 and "one problem" in err


def test_report_json_holds_the_values_of_reactions_past_the_budget(capsys, tmp_path):
    status, _, _ = run(capsys, "report", "n_link_pendulum", "--out", tmp_path, "--duration",
                       "0.5")
    assert status == 0
    got = json.loads((tmp_path / "n_link_pendulum.json").read_text())["values_at_state"]
    q = [got["state"][f"theta{i}"] for i in (1, 2, 3)]
    qd = [got["state"][f"theta{i}_dot"] for i in (1, 2, 3)]
    expected = cartesian_tensions(*_values(problems.get("n_link_pendulum")), q, qd)
    assert [got["values"][f"T{i}"]["direct"] for i in (1, 2, 3)] == pytest.approx(expected,
                                                                                 rel=1e-10)
    # the HTML page shows the same values (10 digits), and the referee's beside them
    page = (tmp_path / "report.html").read_text()
    assert "<h3>Reaction values at a state</h3>" in page
    for i in (1, 2, 3):
        v = got["values"][f"T{i}"]
        assert f"<td>T{i}</td><td>{v['direct']:.10g}</td><td>{v['referee']:.10g} (" in page


def test_reactions_no_referee_derives_get_the_other_derivations_beside(capsys, tmp_path):
    """The rolling disk with its referee declared away (``referee = False``): its contact
    forces are derived again by its multiplier model(s), a different route, shown beside."""
    path = tmp_path / "disk_no_referee.py"
    path.write_text("from dualmech.problems.rolling_disk import RollingDisk\n\n\n"
                    "class NoReferee(RollingDisk):\n"
                    "    name = 'disk_no_referee'\n"
                    "    referee = False\n"
                    "    referee_note = 'declared away for this test'\n\n\n"
                    "PROBLEMS = (NoReferee,)\n")
    got = _show_at(capsys, str(path), "theta=0.3, phi_dot=2, psi_dot=0.5")
    for name in ("F_x", "F_y", "F_z"):
        value = got["values"][name]
        assert value["referee"] is None and "multiplier" in value["others"]
        assert value["others"]["multiplier"] == pytest.approx(value["direct"], rel=1e-9)
    assert abs(got["values"]["F_z"]["direct"]) > 0.1


def test_the_rolling_disks_referee_gives_its_contact_forces_at_a_state(capsys):
    """The disk's referee reads its declared rolling: Kane's rows of all five speeds beside
    the three auxiliary ones and the two rolling rows, 10 rows for 8 unknowns, consistent
    (its exact verdict says so everywhere); solved by least squares, it gives the direct
    form's contact forces to rounding."""
    got = _show_at(capsys, "rolling_disk", "theta=0.3, phi_dot=2, psi_dot=0.5")
    for name in ("F_x", "F_y", "F_z"):
        value = got["values"][name]
        assert value["referee"] == pytest.approx(value["direct"], rel=1e-9)
    assert abs(got["values"]["F_z"]["direct"]) > 0.1
