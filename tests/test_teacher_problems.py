"""Teachers' own problems (tests/corpus/teacher_problems/), each written as a new user writes
one: two models, reactions declared, parameters with ranges, and a printed answer derived by
hand in the file's docstring.

Asserted for each: the two models and the Kane referee agree (exact rational-point test),
nothing is diagnosed, every printed answer is judged correct, the reactions equal the hand
derivation written below (from each file's docstring, not from its code), and the commands a
teacher runs first (``check``, ``show --at``, ``grade``) take the file with the documented
exit status and report lines that fit 100 columns (output not a terminal).
"""
from __future__ import annotations

import functools
from pathlib import Path

import pytest
import sympy as sp

from dualmech import load
from dualmech.cli.main import main
from dualmech.model.kinematics import t
from dualmech.verify.check import compare

CORPUS = Path(__file__).parent / "corpus" / "teacher_problems"
MINE = ("disk_in_cylinder", "double_atwood", "spherical_pendulum", "rough_incline",
        "rod_in_rotating_tube", "disk_on_cart", "rolling_down_incline", "wedge_block")


def _sym(name, positive=True):
    return sp.Symbol(name, positive=True) if positive else sp.Symbol(name, real=True)


def _q(name):
    return sp.Function(name, real=True)(t)


def _hand() -> dict:
    """``{problem: {reaction: value}}``, derived by hand in each file's docstring."""
    m, M, R, r, g, l, k, c, mu, al, L, Om = (_sym(x) for x in
                                            "m M R r g l k c mu alpha L Omega".split())
    th, ph, s, rr, x = _q("theta"), _q("phi"), _q("s"), _q("r"), _q("x")
    d = sp.Derivative
    return {
        "disk_in_cylinder": {"N": m * g * sp.cos(th) + m * (R - r) * d(th, t)**2,
                             "F": m * g * sp.sin(th) / 3},
        "spherical_pendulum": {"T": m * g * sp.cos(th) + m * l * (
            d(th, t)**2 + sp.sin(th)**2 * d(ph, t)**2)},
        "rough_incline": {"N": m * g * sp.cos(al)},
        "rod_in_rotating_tube": {
            "N": m * g * sp.cos(Om * t) + 2 * m * Om * d(rr, t),
            "tau": rr * (m * g * sp.cos(Om * t) + 2 * m * Om * d(rr, t))
            + M * g * L / 2 * sp.cos(Om * t)},
        "disk_on_cart": {"N": m * g, "F": -k * m * x / (3 * M + m), "N_f": (M + m) * g},
        "rolling_down_incline": {"N": m * g * sp.cos(al), "F": m * g * sp.sin(al) / 3},
        "wedge_block": {   # N = m (M g cos(alpha) + F sin(alpha)) / (M + m sin(alpha)^2)
            "N": m * (M * g * sp.cos(al) + _sym("F", False) * sp.sin(al))
            / (M + m * sp.sin(al)**2),
            "N_f": M * g + sp.cos(al) * m * (M * g * sp.cos(al) + _sym("F", False)
                                              * sp.sin(al)) / (M + m * sp.sin(al)**2)},
    }


@functools.lru_cache(maxsize=None)
def checked(name: str):
    return compare(load(str(CORPUS / f"{name}.py")))


@pytest.mark.parametrize("name", MINE)
def test_the_two_models_and_the_referee_agree_and_the_printed_answers_are_right(name):
    c = checked(name)
    assert c.equivalent and c.method == "exact rational-point test", c.text()
    assert c.diagnosis is None
    assert "referee" in c.judgement.referees
    assert c.published and all(v.verdict == "correct" for v in c.published), c.text()


@pytest.mark.parametrize("name", [n for n in MINE if n in _hand()])
def test_the_reactions_are_the_hand_derivation(name):
    got = checked(name).reactions
    for reaction, value in _hand()[name].items():
        assert sp.simplify(got[reaction] - value) == 0, (reaction, got[reaction], value)


def test_the_double_atwood_accelerations_are_the_hand_derivation():
    """With m2 = m3 = m the two rows decouple: y'' = 0, x'' = g (m1 - M_B - 2 m)/(m1 + M/2 +
    M_B + 2 m) (docstring of double_atwood.py)."""
    c = checked("double_atwood")
    m1, m2, m3, M, MB, g = (_sym(n) for n in ("m1", "m2", "m3", "M", "M_B", "g"))
    same = {m3: m2}
    assert sp.simplify(c.accelerations["y"].subs(same)) == 0
    want = g * (m1 - MB - 2 * m2) / (m1 + M / 2 + MB + 2 * m2)
    assert sp.simplify(c.accelerations["x"].subs(same) - want) == 0


@pytest.mark.parametrize("name", MINE)
def test_check_exits_0_and_fits_100_columns_but_the_verdict(name, capsys):
    status = main(["check", str(CORPUS / f"{name}.py")])
    out = capsys.readouterr().out
    assert status == 0
    assert max(len(x) for x in out.splitlines() if not x.startswith("  verdict: ")) <= 100


@pytest.mark.parametrize("name,answer,status", [
    ("disk_in_cylinder", "3*(R - r)*theta'' + 2*g*sin(theta) = 0", 0),
    ("disk_in_cylinder", "3*(R - r)*theta'' - 2*g*sin(theta) = 0", 1),
    ("spherical_pendulum", "l*theta'' - l*sin(theta)*cos(theta)*phi'^2 + g*sin(theta) = 0", 0),
    ("rough_incline", "m*s'' + c*s' + k*s - m*g*sin(alpha) + mu*m*g*cos(alpha) = 0", 0),
    ("rough_incline", "m*s'' + c*s' + k*s - m*g*sin(alpha) - mu*m*g*cos(alpha) = 0", 1),
    ("disk_on_cart", "(3*M + m)*x'' + 3*k*x = 0", 0),
    ("wedge_block", "(M+m)*X'' + m*cos(alpha)*s'' = F", 0),
    ("wedge_block", "(M+m)*X'' - m*cos(alpha)*s'' = F", 1),
    ("wedge_block", "s'' + cos(alpha)*X'' = g*sin(alpha)", 0),
])
def test_grade_a_typed_answer_against_a_teachers_file(name, answer, status, capsys):
    """The hand-derived equations (each file's docstring), typed as a student types them;
    a sign flipped is wrong (exit 1)."""
    assert main(["grade", str(CORPUS / f"{name}.py"), "--answer", answer]) == status
    out = capsys.readouterr().out
    assert out.startswith("RIGHT" if status == 0 else "WRONG"), out


def test_show_at_a_state_names_the_coordinates_when_one_is_unknown(capsys):
    path = str(CORPUS / "disk_in_cylinder.py")
    assert main(["show", path, "--at", "x=0.1"]) == 2
    err = capsys.readouterr().err
    assert "'x' is not a coordinate" in err and "theta" in err
    assert main(["show", path, "--at", "theta=0.5, theta_dot=1"]) == 0
    out = capsys.readouterr().out
    # N = m g cos(0.5) + m (R - r) 1^2, F = m g sin(0.5)/3 at the defaults m=1, R=1, r=0.2
    N = 9.81 * 0.8775825618903728 + 0.8
    F = 9.81 * 0.479425538604203 / 3
    assert f"{N:.6g}" in out and f"{F:.6g}" in out, out


def test_stability_says_the_state_it_refused_and_not_at_a_line_of_the_file(capsys):
    """A driven problem has no steady motion: a refusal of the study, not an error at a line
    of the teacher's file; an equilibrium that is none is shown with its accelerations in
    the teacher's notation."""
    assert main(["stability", str(CORPUS / "rod_in_rotating_tube.py")]) == 2
    err = " ".join(capsys.readouterr().err.split())   # the message wrapped, as words
    assert "is driven" in err and "r'' = " in err and ", line " not in err
    assert main(["stability", str(CORPUS / "double_atwood.py")]) == 2
    err = capsys.readouterr().err
    assert "(every coordinate and rate zero)" in err and "x'' = " in err
    assert "{}" not in err and "Derivative" not in err


def test_list_a_file_names_its_problems_as_the_other_commands_take_them(capsys):
    """A file of several problems (a mistakes corpus file defines the problem and each
    variant): ``dualmech list FILE`` names each ``FILE:Class``; a missing file is a usage
    error."""
    path = str(Path(__file__).parent / "corpus" / "teacher_mistakes" /
               "disk_on_cart_mistakes.py")
    assert main(["list", path]) == 0
    out = capsys.readouterr().out
    for cls in ("DiskOnCart", "SpinForgotten", "CartWeightDropped"):
        assert f"{path}:{cls} " in out
    assert main(["list", str(CORPUS / "no_such_problem.py")]) == 2
    assert "no problem file" in capsys.readouterr().err


def test_simulate_warns_where_the_run_leaves_the_declared_scene(capsys):
    """The disk rolling down the incline from the default state (x0 = 60 % into its range
    (-1, 1) = 0.2, at rest) speeds up at x'' = (2/3) g sin(alpha) (by hand, the docstring of
    the problem file): it passes x = 1, the end of its declared range, at
    t = sqrt(2 (1 - 0.2) / x'') -- the run says so, at the first sample past that time, in the
    text and the JSON, and the simple pendulum, which stays in its scene, says nothing."""
    import json
    import math
    path = CORPUS / "rolling_down_incline.py"
    assert main(["simulate", str(path), "--duration", "5"]) == 0
    err = capsys.readouterr().err
    assert "warning: x leaves its declared range [-1, 1]" in err
    assert main(["simulate", str(path), "--duration", "5", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    (what,) = doc["left_declared"]
    when = float(what.split("at t = ")[1].split(" s")[0])
    by_hand = math.sqrt(2 * 0.8 / (2 / 3 * 9.81 * math.sin(0.3)))
    assert by_hand < when <= by_hand + 5 / 400 + 1e-9
    assert main(["simulate", "simple_pendulum", "--duration", "5"]) == 0
    assert "warning" not in capsys.readouterr().err
