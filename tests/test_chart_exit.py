"""``dualmech chart``'s exit status over several problems (dualmech.cli.studies).

Rule (``chart --help``): 0 when every problem is charted or not applicable (the reason on
stderr); 2 when a problem could not be charted for another reason, or nothing was charted.
Two tiny problems written here: a block on a spring (an ODE: charts), and the same block
beside a massless slider no equation holds (no model integrates in the reference
coordinates: not applicable).  The rule itself is checked on made-up results as well.
"""
import argparse
import textwrap

import pytest

from dualmech.cli.errors import Failure
from dualmech.cli.main import main
from dualmech.cli.studies import CHART_EXIT_STATUS, _chart_status

PROBLEMS = textwrap.dedent('''
    import sympy as sp
    from dualmech import (Coordinate, EquationSet, Lagrangian, Parameter, Problem, coordinate,
                          t, LENGTH, MASS, STIFFNESS)

    m, k = sp.symbols("m k", positive=True)
    x, z = coordinate("x"), coordinate("z")


    class Spring(Problem):
        """m x'' + k x = 0, twice."""
        name, title, source = "tiny_spring", "Block on a spring", "test: by hand"
        parameters = (Parameter(m, MASS, 2.0, (0.1, 10.0)),
                      Parameter(k, STIFFNESS, 50.0, (1, 500)))
        coordinates = (Coordinate(x, LENGTH, (-0.5, 0.5)),)

        def newton_euler(self):
            return EquationSet("newton_euler", (x,), (-k * x - m * x.diff(t, 2),),
                               labels=("sum F . x",))

        def lagrange(self):
            lg = Lagrangian(coordinates=[x])
            lg.kinetic("T", m * x.diff(t)**2 / 2)
            lg.potential("V", k * x**2 / 2)
            return lg.equations()


    class Idle(Problem):
        """The block beside a massless slider z that appears in no equation."""
        name, title, source = "idle_slider", "Block and an idle slider", "test: by hand"
        parameters = Spring.parameters
        coordinates = (Coordinate(x, LENGTH, (-0.5, 0.5)), Coordinate(z, LENGTH, (-0.5, 0.5)))

        def newton_euler(self):
            return EquationSet("newton_euler", (x, z),
                               (-k * x - m * x.diff(t, 2), sp.Integer(0)),
                               labels=("sum F . x", "slider"))

        def lagrange(self):
            lg = Lagrangian(coordinates=[x, z])
            lg.kinetic("T", m * x.diff(t)**2 / 2)
            lg.potential("V", k * x**2 / 2)
            return lg.equations()
''')
FAST = ["--quick", "--duration", "0.2", "--budget", "0.2", "--jobs", "1", "--repeats", "1"]


@pytest.fixture
def tiny(tmp_path):
    path = tmp_path / "tiny.py"
    path.write_text(PROBLEMS)
    return path


def _chart(capsys, tmp_path, *names):
    """The status and the captured output; stderr as one line of words (its messages are
    wrapped to the terminal, a line breaking between any two words)."""
    status = main(["chart", *names, "--out", str(tmp_path / "out"), *FAST])
    out = capsys.readouterr()
    return status, out._replace(err=" ".join(out.err.split()))


def test_a_not_applicable_problem_beside_a_charted_one_exits_0(capsys, tmp_path, tiny):
    status, out = _chart(capsys, tmp_path, f"{tiny}:Spring", f"{tiny}:Idle")
    assert status == 0, out.err
    assert (tmp_path / "out" / "tiny_spring_workprecision.png").exists()
    assert not (tmp_path / "out" / "idle_slider_workprecision.png").exists()
    assert "idle_slider" in out.err and "not applicable" in out.err
    assert "acceleration of z" in out.err              # the reason, naming the coordinate
    assert "Traceback" not in out.err


def test_nothing_charted_exits_2(capsys, tmp_path, tiny):
    status, out = _chart(capsys, tmp_path, f"{tiny}:Idle")
    assert status == 2 and "not applicable" in out.err


def _result(name, status=None, inapplicable=False):
    failure = None if status is None else Failure(status, f"{name}: why", "model")
    return (name, failure, {"problem": name} if failure is None else None, "", inapplicable)


@pytest.mark.parametrize("results, want", [
    ([_result("a"), _result("b", 2, True)], 0),            # charted + not applicable
    ([_result("a"), _result("b", 2, False)], 2),           # charted + a real failure
    ([_result("b", 2, True), _result("c", 2, True)], 2),   # nothing charted
    ([_result("a"), _result("b")], 0),
])
def test_the_exit_status_rule(capsys, results, want):
    assert _chart_status(results, argparse.Namespace(json=False, all=True)) == want
    err = capsys.readouterr().err
    assert all(f"{r[0]}: why" in err for r in results if r[1] is not None)


def test_the_rule_is_in_the_help(capsys):
    try:
        main(["chart", "--help"])
    except SystemExit:
        pass
    text = " ".join(capsys.readouterr().out.split())
    assert "0 every problem charted, or not applicable" in text
    assert "nothing charted at all" in text
    assert CHART_EXIT_STATUS.startswith("Exit status: 0")


@pytest.mark.slow
def test_a_pipe_gets_no_progress_bar(capsys, tmp_path):
    """stderr that is not a terminal (a pipe, a CI log) gets the per-problem lines, not tqdm's
    carriage-return redraws piling up into one line hundreds of columns wide."""
    from dualmech.cli.main import main
    assert main(["chart", "simple_pendulum", "--quick", "--out", str(tmp_path)]) == 0
    err = capsys.readouterr().err
    assert "\r" not in err and "run/s" not in err, err[:300]
