"""``dualmech stability``: its JSON, its refusals, and a teacher's own file.

The teacher's file is a conical pendulum (mass ``m`` on a rod ``l``, ``theta`` from the
downward vertical, azimuth ``phi``) with its steady conical motion declared: ``phi' = W``,
``cos(theta0) = g / (l W^2)``.  By hand, with ``h = sin^2(theta) phi'`` conserved,
``theta'' = h^2 cos/sin^3 - (g/l) sin``; linearised at ``theta0`` with ``h`` fixed:
``omega^2 = W^2 (sin^2 + 3 cos^2) + (g/l) cos = W^2 (1 + 3 cos^2(theta0))`` -- the classic
result for small oscillations about conical motion.
"""
from __future__ import annotations

import json
import math
import textwrap

import pytest

from dualmech.cli.main import main

CONICAL = textwrap.dedent('''
    """A conical pendulum, as in my notes."""
    import sympy as sp
    from dualmech import (Lagrangian, Problem, Parameter, Coordinate, SteadyMotion, coordinate,
                          rate, MASS, LENGTH, ACCELERATION, ANGLE)

    m, l, g = sp.symbols("m l g", positive=True)
    W = sp.Symbol("W", positive=True)
    th, ph = coordinate("theta"), coordinate("phi")


    class Conical(Problem):
        name, title, source = "my_conical", "Conical pendulum", "my notes: example 7"
        parameters = (Parameter(m, MASS, 1, (0.1, 10)), Parameter(l, LENGTH, 1, (0.1, 2)),
                      Parameter(g, ACCELERATION, 9.81, (1, 20)))
        coordinates = (Coordinate(th, ANGLE, (-1, 1)), Coordinate(ph, ANGLE, (-3, 3)))
        steady_motion = SteadyMotion({th: sp.acos(g / (l * W**2)), rate(ph): W}, "W",
                                     (3.5, 6.0, 6), "conical motion at the rate W")

        def lagrange(self):
            lg = Lagrangian(coordinates=[th, ph])
            lg.kinetic("T", m * l**2 * (rate(th)**2 + sp.sin(th)**2 * rate(ph)**2) / 2)
            lg.potential("gravity", -m * g * l * sp.cos(th))
            return lg.equations()
''')


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return status, out, err


def test_json_holds_values_eigenvalues_and_critical(capsys, tmp_path):
    status, out, err = run(capsys, "stability", "rolling_disk", "--sweep", "v=0.5:1.5:6",
                           "--json", "--out", tmp_path)
    assert status == 0, err
    data = json.loads(out)
    assert data["parameter"] == "v" and data["values"] == pytest.approx([0.5, 0.7, 0.9, 1.1,
                                                                         1.3, 1.5])
    first = sorted(x for x, _ in data["eigenvalues"][0])
    want = math.sqrt(4 * (10 * 0.3 - 3 * 0.25) / (5 * 0.09))   # hand: rolling_disk docstring
    assert first == pytest.approx([-want, 0, 0, 0, want], abs=1e-9)
    (crit,) = data["critical"]
    assert crit["value"] == pytest.approx(1.0, abs=1e-9)          # sqrt(g r / 3), g=10, r=0.3
    assert crit["kind"] == "a real pair meets at zero and becomes imaginary"
    assert data["derivations"]["agree"] is True
    assert data["chart"].endswith("rolling_disk_root_locus.png")
    assert (tmp_path / "rolling_disk_root_locus.png").stat().st_size > 10_000


def test_text_names_the_agreement(capsys):
    status, out, _ = run(capsys, "stability", "pendulum_particle", "--about", "theta=0")
    assert status == 0
    assert "newton_euler, lagrange, cartesian linearised" in out and "agree" in out


@pytest.mark.parametrize("about, says", [
    ("theta=__import__('os').system('touch HACKED')", "is not a number"),
    ("theta=1e999", "is not finite"),
    ("theta 0.1", "has no '='"),
    ("os.system=1", "is not a coordinate name"),
    ("theta=1, theta=2", "given twice"),
    ("theta=sin(1)", "is not a number"),
    ("omega=1", "not a coordinate"),
    ("x" * 3000 + "=1", "at most"),
])
def test_malformed_about_is_refused_without_evaluation(capsys, tmp_path, monkeypatch, about,
                                                        says):
    monkeypatch.chdir(tmp_path)
    import builtins

    import sympy
    real = sympy.sympify, builtins.eval

    def guard(index):
        def checked(x, *args, **kwargs):   # the text itself never reaches an evaluator
            if isinstance(x, str) and about.partition("=")[2][:20] in x and "=" in about:
                raise AssertionError("the --about text reached an evaluator")
            return real[index](x, *args, **kwargs)
        return checked
    monkeypatch.setattr(sympy, "sympify", guard(0))
    monkeypatch.setattr(builtins, "eval", guard(1))
    status, out, err = run(capsys, "stability", "pendulum_particle", "--about", about)
    assert status == 2 and out == ""
    assert says in err and "Traceback" not in err
    assert not (tmp_path / "HACKED").exists()


@pytest.mark.parametrize("sweep", ["v=0:1", "v=a:b:3", "v=0:1:1", "v=1:1:5", "__x__=0:1:9e9"])
def test_malformed_sweep_is_a_usage_error(capsys, sweep):
    status, _, err = run(capsys, "stability", "rolling_disk", "--sweep", sweep)
    assert status == 2
    assert "PARAM=START:STOP:N" in err or "outside 2..2001" in err or "are equal" in err


def test_unknown_sweep_parameter_is_a_usage_error(capsys):
    status, _, err = run(capsys, "stability", "rolling_disk", "--sweep", "speed=0:1:3")
    assert status == 2 and "'speed' is neither a parameter" in err


def test_teachers_file_with_a_declared_steady_motion(capsys, tmp_path):
    path = tmp_path / "my_conical.py"
    path.write_text(CONICAL)
    status, out, err = run(capsys, "stability", path, "--json")
    assert status == 0, err
    data = json.loads(out)
    assert data["parameter"] == "W" and len(data["values"]) == 6
    assert data["states"] == ["theta", "theta'", "phi'"] and data["dropped"] == ["phi"]
    for w, eig in zip(data["values"], data["eigenvalues"]):
        cos0 = 9.81 / w**2
        omega = w * math.sqrt(1 + 3 * cos0**2)   # hand, module docstring
        imag = sorted(abs(im) for re, im in eig if abs(im) > 1e-9)
        assert imag == pytest.approx([omega, omega], rel=1e-12)
        assert all(abs(re) < 1e-9 for re, _ in eig)
    assert data["critical"] == [] and all(data["stable"])


def test_an_about_that_is_not_a_steady_motion_is_the_users_mistake(capsys):
    status, out, err = run(capsys, "stability", "pendulum_particle", "--about", "theta=0.5")
    assert status == 2 and out == ""
    assert "`--about`: the state {theta = 1/2} is not a steady motion" in err
    assert "theta'' = -981*sin(1/2)/100" in err   # -g sin(theta) / l, l = 1


def test_about_with_rates_and_a_swept_problem_parameter(capsys):
    """Rolling at v = 1.2 (phi' = v / r = 4, r = 0.3): by hand stable while g < 3 v^2 / r = 14.4."""
    status, out, err = run(capsys, "stability", "rolling_disk", "--about",
                           "phi_dot=4, x_dot=1.2", "--sweep", "g=5:20:7", "--json")
    assert status == 0, err
    data = json.loads(out)
    (crit,) = data["critical"]
    assert data["parameter"] == "g" and crit["value"] == pytest.approx(14.4, abs=1e-9)
    assert (crit["stable_below"], crit["stable_above"]) == (True, False)
