"""Given inputs F(t) (``Problem.inputs``): free values in the verdict, the user's history in a
simulation.  The teacher's file is tests/corpus/teacher_problems/forced_block.py: a block of
mass m on a smooth floor, held by a spring k, pushed by F(t) at 30 degrees below the
horizontal.  By hand: m x'' = -k x + (sqrt(3)/2) F, N = m g + F/2; from rest at x = 0 under
F = F0 sin(w t) (w != w0 = sqrt(k/m)) the motion is
x(t) = a / (w0^2 - w^2) (sin(w t) - (w/w0) sin(w0 t)), a = sqrt(3) F0 / (2 m).
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from dualmech import Input, FORCE, compare, problems, simulate
from dualmech.cli.main import main
from dualmech.model.problem import ProblemError
from dualmech.numeric.inputs import InputError

FILE = Path(__file__).resolve().parent / "corpus" / "teacher_problems" / "forced_block.py"
M, K, G = 2.0, 8.0, 9.81          # the file's defaults
W0 = np.sqrt(K / M)


def exact_x(t, F0, w):
    a = np.sqrt(3) * F0 / (2 * M)
    return a / (W0**2 - w**2) * (np.sin(w * t) - w / W0 * np.sin(W0 * t))


@pytest.fixture
def block():
    return problems.load(str(FILE))


def _module(p):
    import sys
    return sys.modules[type(p).__module__]


def test_the_verdict_treats_the_input_as_a_free_value(block):
    c = compare(block)
    assert c.equivalent
    mod = _module(block)
    assert sp.simplify(c.reactions["N"] - (mod.m * mod.g + mod.F / 2)) == 0


def test_a_wrong_generalised_force_of_the_input_is_a_disagreement(block):
    mod = _module(block)

    class Wrong(type(block)):
        def lagrange(self):      # forgot the cosine of 30 degrees: Q = F
            lg = mod.Lagrangian(coordinates=[mod.x])
            lg.kinetic_of(mod.block, mod.O)
            lg.potential("spring", mod.k * mod.x**2 / 2)
            lg.generalized_force("push", [mod.F])
            return lg.equations()
    assert not compare(Wrong()).equivalent


def test_declaration_mistakes_are_refused(block):
    mod = _module(block)

    class InEnergy(type(block)):
        def lagrange(self):      # a given *motion* put in V: not a load
            lg = mod.Lagrangian(coordinates=[mod.x])
            lg.kinetic_of(mod.block, mod.O)
            lg.potential("spring", mod.k * (mod.x - mod.F / mod.k)**2 / 2)
            return lg.equations()
    with pytest.raises(ProblemError, match="input `F` appears in V"):
        InEnergy().validate()

    class Unused(type(block)):
        inputs = block.inputs + (Input(sp.Symbol("P"), FORCE, "unused"),)
    with pytest.raises(ProblemError, match="input `P` is declared but no model uses it"):
        Unused().validate()

    class Twice(type(block)):
        inputs = (Input(mod.m, FORCE, "also a parameter"),) + block.inputs
    with pytest.raises(ProblemError, match="input `m` is declared twice"):
        Twice().validate()
    with pytest.raises(TypeError, match="must be a sympy Symbol"):
        Input(sp.Function("F")(sp.Symbol("t")), FORCE)


def test_simulation_with_a_callable_matches_the_closed_form(block):
    F0, w = 1.5, 3.0
    run = simulate(block, (0, 3), y0=[0, 0], samples=31,
                   inputs={"F": lambda t: F0 * np.sin(w * t)})
    assert np.abs(run.q[0] - exact_x(run.t, F0, w)).max() < 1e-8
    assert np.abs(run.reactions["N"] - (M * G + F0 * np.sin(w * run.t) / 2)).max() < 1e-9


def test_simulation_with_a_table_is_interpolated(block):
    F0, w = 1.5, 3.0
    T = np.linspace(0, 3, 3001)
    run = simulate(block, (0, 3), y0=[0, 0], samples=31, inputs={"F": (T, F0 * np.sin(w * T))})
    # linear interpolation on a 1 ms grid: |F - F_table| <= F0 w^2 h^2 / 8 ~ 1.7e-6
    assert np.abs(run.q[0] - exact_x(run.t, F0, w)).max() < 2e-6
    step = simulate(block, (0, 2), y0=[0, 0], samples=5, inputs={"F": ([0, 2], [0, 4])})
    assert step.reactions["N"] == pytest.approx(M * G + np.array([0, 1, 2, 3, 4]) / 2)  # F = 2t


BAD = [
    ({}, ValueError, "needs the given input F"),
    ({"G": lambda t: 0}, ValueError, "'G' is not a given input"),
    ({"F": "2*sin(t)"}, TypeError, "is text"),
    ({"F": ([0, 1], [0])}, ValueError, "the same length"),
    ({"F": ([0], [0])}, ValueError, "2 to"),
    ({"F": ([0, 2, 1], [0, 0, 0])}, ValueError, "increase strictly"),
    ({"F": ([0, 1, 3], [0, np.nan, 0])}, ValueError, "not a finite number"),
    ({"F": ([0, 1], [0, 1])}, ValueError, "covers t in \\[0, 1\\]"),
    ({"F": lambda t: float("nan")}, InputError, "is nan"),
    ({"F": lambda t: "x"}, InputError, "did not give a number"),
    ({"F": lambda t: 1 / (t - t)}, InputError, "ZeroDivisionError"),
]


@pytest.mark.parametrize("inputs, kind, message", BAD, ids=[m for *_, m in BAD])
def test_bad_histories_are_refused_naming_the_input(block, inputs, kind, message):
    with pytest.raises(kind, match=message):
        simulate(block, (0, 2), y0=[0, 0], samples=3, inputs=inputs)


def run_cli(capsys, *argv):
    """The status, stdout and stderr of ``dualmech ARGV``; stderr as one line of words (its
    messages are wrapped to the terminal, a line breaking between any two words)."""
    status = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return status, out, " ".join(err.split())


def test_cli_expression_and_csv_histories(capsys, tmp_path):
    status, out, err = run_cli(capsys, "simulate", FILE, "--duration", "3", "--json",
                               "--input", "F=1.5*sin(3 t)")
    assert status == 0, err
    x_end = json.loads(out)["final_state"][0]
    assert x_end == pytest.approx(exact_x(3.0, 1.5, 3.0), abs=1e-7)
    table = tmp_path / "push.csv"
    T = np.linspace(0, 3, 3001)
    table.write_text("time,F\n" + "\n".join(f"{a:.17g},{b:.17g}" for a, b in
                                             zip(T, 1.5 * np.sin(3 * T))))
    status, out, err = run_cli(capsys, "simulate", FILE, "--duration", "3", "--json",
                               "--input", f"F={table}")
    assert status == 0, err
    assert json.loads(out)["final_state"][0] == pytest.approx(exact_x(3.0, 1.5, 3.0), abs=2e-6)
    # the expression may name the parameters, at this run's values
    status, out, _ = run_cli(capsys, "simulate", FILE, "--duration", "1", "--json",
                             "--input", "F=k*0", "--param", "k=8")
    assert status == 0 and json.loads(out)["final_state"] == [0.0, 0.0]


HOSTILE = {
    "F": "takes NAME=HISTORY",
    "=2": "takes NAME=HISTORY",
    "F=": "takes NAME=HISTORY",
    "G=1": "'G' is not a given input",
    "F=__import__('os').system('true')": "could not read",
    "F=nan": "'nan' is not t, pi or a parameter",
    "F=inf": "'inf' is not t, pi or a parameter",
    "F=x'": "a function of t alone",
    "F=[1, 2]": "is not allowed",
    "F=1; 2": "not several",
    "F=t = 1": "not an equation",
    "F=10^10^10": "did not give a number",
    "F=" + "t+" * 1500 + "t": "characters long",
    "F=" + "(" * 300 + "t" + ")" * 300: "",
    "F=nowhere.csv": "no file",
    "1F=2": "takes NAME=HISTORY",
}


@pytest.mark.parametrize("text", sorted(HOSTILE), ids=lambda s: repr(s[:30]))
def test_hostile_input_options_are_refused(capsys, text):
    status, out, err = run_cli(capsys, "simulate", FILE, "--duration", "1", "--input", text)
    assert status == 2, (out, err)
    assert HOSTILE[text] in err and "Traceback" not in err and "internal error" not in err


def test_hostile_tables_are_refused(capsys, tmp_path):
    cases = {"0,0\n1,nan\n2,0\n": "not a finite number", "0,0\n1,1\n": "covers t in [0, 1]",
             "0;0\n1;1\n": "a table has two", "0,0\n0,1\n": "increase strictly",
             "0,0\nx,y\n": "are not two numbers", "0,0,0\n": "a table has two"}
    for i, (text, message) in enumerate(cases.items()):
        path = tmp_path / f"t{i}.csv"
        path.write_text(text)
        status, _, err = run_cli(capsys, "simulate", FILE, "--duration", "2", "--input",
                                 f"F={path}")
        assert status == 2 and message in err, (text, err)


def test_show_at_takes_the_input_value(capsys):
    status, out, err = run_cli(capsys, "show", FILE, "--json", "--at", "x=0.1, F=4")
    assert status == 0, err
    values = json.loads(out)["values_at_state"]
    assert values["state"]["F"] == 4.0
    assert values["values"]["N"]["direct"] == pytest.approx(M * G + 2.0, rel=1e-12)
    assert values["values"]["N"]["referee"] == pytest.approx(M * G + 2.0, rel=1e-12)


def test_an_input_in_a_direct_model_position_is_refused(block):
    mod = _module(block)

    class Moved(type(block)):
        def newton_euler(self):   # the block placed at x + F: a given motion, not a load
            ground = mod.O
            moved = mod.Particle("block", mod.m, mod.Point.origin(ground).locate(
                "P", (mod.x + mod.F / mod.k) * ground.x))
            ne = mod.NewtonEuler(coordinates=[mod.x], ground=ground)
            ne.gravity(-mod.g * ground.y)
            ne.force("spring", moved, -mod.k * mod.x * ground.x)
            ne.reaction("N", moved, ground.y)
            ne.linear_momentum(moved, ground.x)
            ne.linear_momentum(moved, ground.y)
            return ne.equations()
    with pytest.raises(ProblemError, match="input `F` appears in the position or rotation of "
                                           "body `block`"):
        Moved().validate()
