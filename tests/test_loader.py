"""Problems from anywhere: a file, ``file.py:Class``, ``module:Class``, a registered catalogue,
and the skeleton ``dualmech new`` writes -- each checked end to end through the command line.

The user problem is a block on a spring (``m x'' + k x = 0``, by hand); its wrong twin has the
classic slip ``V = k x^2`` (the Lagrangian then gives ``m x'' + 2 k x = 0``)."""
from __future__ import annotations

import json
import sys
import textwrap

import pytest
import sympy as sp

from dualmech import problems
from dualmech.cli.main import main

USER_FILE = textwrap.dedent('''
    import sympy as sp
    from dualmech import Lagrangian, coordinate, t
    from dualmech.model.dimensions import LENGTH, MASS, STIFFNESS
    from dualmech.model.equations import EquationSet
    from dualmech.model.problem import Coordinate, Parameter, Problem

    m, k = sp.symbols("m k", positive=True)
    x = coordinate("x")


    class Spring(Problem):
        name, title, source = "my_spring", "Block on a spring", "my notes: example 1"
        parameters = (Parameter(m, MASS, 2.0, (0.1, 10.0)),
                      Parameter(k, STIFFNESS, 50.0, (1.0, 500.0)))
        coordinates = (Coordinate(x, LENGTH, (-0.5, 0.5)),)
        factor = 1

        def newton_euler(self):
            return EquationSet("newton_euler", (x,), (-k * x - m * x.diff(t, 2),))

        def lagrange(self):
            lg = Lagrangian(coordinates=[x])
            lg.kinetic("T", m * x.diff(t)**2 / 2)
            lg.potential("V", self.factor * k * x**2 / 2)
            return lg.equations()


    class WrongSpring(Spring):
        name = "my_wrong_spring"
        factor = 2
''')


def run(capsys, *argv):
    """Status, stdout and stderr of ``dualmech ARGV``; stderr as one line of words (messages
    are wrapped to the terminal, a line breaking between any two words)."""
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, " ".join(err.split())


@pytest.fixture
def user_dir(tmp_path):
    (tmp_path / "my_springs.py").write_text(USER_FILE)
    (tmp_path / "one_spring.py").write_text(USER_FILE.split("class WrongSpring")[0])
    return tmp_path


def test_a_file_with_one_problem_is_checked_by_path(capsys, user_dir):
    status, out, err = run(capsys, "check", str(user_dir / "one_spring.py"), "--json")
    assert status == 0, err
    d = json.loads(out)
    assert d["name"] == "my_spring" and d["equivalent"] is True
    # the acceleration, by hand: x'' = -k x / m
    from dualmech.verify.check import compare
    problem = problems.load(str(user_dir / "one_spring.py"))
    mod = sys.modules[type(problem).__module__]
    (acc,) = compare(problem).accelerations.values()
    assert sp.simplify(acc + mod.k * mod.x / mod.m) == 0


def test_path_colon_class_picks_one_of_several_and_names_the_culprit(capsys, user_dir):
    path = str(user_dir / "my_springs.py")
    status, _, err = run(capsys, "check", path)
    assert status == 2
    assert "several problems (Spring, WrongSpring)" in err and f"{path}:Spring" in err
    assert run(capsys, "check", f"{path}:Spring")[0] == 0
    assert run(capsys, "check", f"{path}:my_spring")[0] == 0      # the problem's name works too
    status, out, _ = run(capsys, "check", f"{path}:WrongSpring")
    assert status == 1
    # two derivations, no majority: both sides shown; the slip is k x (V = k x^2, not k x^2/2)
    assert "NOT equivalent" in out and "residual after the best combination: k x" in out


def test_module_colon_class_with_the_folder_on_sys_path(capsys, user_dir, monkeypatch):
    monkeypatch.syspath_prepend(str(user_dir))
    status, out, err = run(capsys, "check", "my_springs:Spring", "--json")
    assert status == 0, err
    assert json.loads(out)["name"] == "my_spring"
    status, _, err = run(capsys, "check", "my_springs:Sprin")
    assert status == 2 and "Did you mean 'Spring'" in err


def test_module_colon_class_from_the_current_directory(capsys, user_dir, monkeypatch):
    monkeypatch.chdir(user_dir)
    assert run(capsys, "show", "one_spring:Spring")[0] == 0


def test_other_commands_take_a_file_too(capsys, user_dir):
    path = str(user_dir / "one_spring.py")
    status, out, _ = run(capsys, "show", path)
    assert status == 0 and "my_spring" in out
    status, out, _ = run(capsys, "grade", path, "--answer", "m*x'' + k*x = 0")
    assert status == 0 and out.startswith("RIGHT")
    status, out, _ = run(capsys, "grade", path, "--answer", "m*x'' + 2*k*x = 0")
    assert status == 1


@pytest.mark.parametrize("content, message", [
    ("import sympy\n", "defines no Problem subclass"),
    ("x = 1\ny = undefined_name\n", "line 2: NameError: name 'undefined_name' is not defined"),
    ("def f(:\n    pass\n", "line 1: SyntaxError"),
])
def test_errors_in_the_users_file_are_the_users_with_their_line(capsys, tmp_path, content,
                                                                message):
    path = tmp_path / "broken.py"
    path.write_text(content)
    status, out, err = run(capsys, "check", str(path))
    assert status == 2 and out == ""
    assert message in err and str(path) in err
    assert "Traceback" not in err


def test_missing_file_and_not_a_problem(capsys, user_dir):
    status, _, err = run(capsys, "check", str(user_dir / "absent.py"))
    assert status == 2 and "no file" in err
    status, _, err = run(capsys, "check", f"{user_dir / 'my_springs.py'}:sp")
    assert status == 2 and "not a Problem subclass" in err
    status, _, err = run(capsys, "check", "toy_cr")
    assert status == 2 and "Did you mean 'toy_car'" in err


def test_a_spec_is_made_absolute_for_worker_processes(user_dir, monkeypatch):
    monkeypatch.chdir(user_dir)
    spec = problems.canonical("one_spring.py:Spring")
    assert spec == f"{user_dir.resolve() / 'one_spring.py'}:Spring"
    monkeypatch.chdir(user_dir.parent)
    assert problems.load(spec).name == "my_spring"
    assert problems.canonical("toy_car") == "toy_car"


def test_a_registered_catalogue_is_found_by_name_and_qualified(capsys, user_dir, monkeypatch):
    """A course package registers ``mycourse = my_springs`` in the group dualmech.problems
    (faked by a dist-info folder on sys.path, as pip would install it)."""
    info = user_dir / "mycourse-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: mycourse\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[dualmech.problems]\nmycourse = my_springs\n")
    monkeypatch.syspath_prepend(str(user_dir))
    assert "mycourse" in problems.registered()
    assert problems.load("my_wrong_spring").name == "my_wrong_spring"   # by problem name
    assert run(capsys, "check", "mycourse:my_spring")[0] == 0           # qualified
    assert run(capsys, "check", "mycourse:WrongSpring")[0] == 1
    assert problems.load("toy_car").name == "toy_car"                    # the catalogue first
    status, out, _ = run(capsys, "list", "--json")
    mine = [r for r in json.loads(out) if r["catalogue"] == "mycourse"]
    assert [r["name"] for r in mine] == ["mycourse:my_spring", "mycourse:my_wrong_spring"]
    assert "mycourse:my_wrong_spring" in run(capsys, "list")[1]


def test_the_loader_doctests_run():
    """problems/ is not among the suite's doctest paths; its examples run here."""
    import doctest

    import dualmech.problems._loader as loader
    for module in (problems, loader):
        failed, tried = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
        assert tried > 0 and failed == 0, module.__name__


def test_options_reach_only_parametric_problems():
    assert len(problems.load("n_link_pendulum", n=2).model("lagrange").coordinates) == 2
    with pytest.raises(ValueError, match="fixed size"):
        problems.load("toy_car", n=2)


@pytest.mark.slow
def test_new_writes_a_skeleton_that_passes_check_and_its_test(capsys, tmp_path):
    status, out, _ = run(capsys, "new", "bead_on_rod", "--out", str(tmp_path))
    assert status == 0 and "TODO" in out and "dualmech check" in out
    path = tmp_path / "bead_on_rod.py"
    text = path.read_text()
    assert "Sign sketch" in text and "def newton_euler" in text and "def lagrange" in text
    status, out, err = run(capsys, "check", str(path), "--json")
    assert status == 0, err
    d = json.loads(out)
    assert d["name"] == "bead_on_rod" and d["equivalent"]
    # the pendulum by hand: tension m (g cos theta + l theta'^2)
    from dualmech import compare, rate
    mod = sys.modules[type(problems.load(str(path))).__module__]
    (tension,) = compare(problems.load(str(path))).reactions.values()
    hand = mod.m * (mod.g * sp.cos(mod.theta) + mod.l * rate(mod.theta)**2)
    assert sp.simplify(tension - hand) == 0
    import subprocess
    test = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                           str(tmp_path / "test_bead_on_rod.py")], capture_output=True,
                          text=True, cwd=tmp_path, timeout=300)
    assert test.returncode == 0, test.stdout + test.stderr
    assert "2 passed" in test.stdout
    status, _, err = run(capsys, "new", "bead_on_rod", "--out", str(tmp_path))
    assert status == 2 and "already exist" in err
    status, _, err = run(capsys, "new", "Bad-Name")
    assert status == 2 and "lower-case" in err


def test_a_batch_csv_row_never_imports_a_file_or_module(tmp_path):
    """Questions in a CSV are untrusted text: a path or module:Class there is refused, and the
    file it names is not executed."""
    from dualmech.grade.batch import grade_rows
    marker = tmp_path / "executed"
    evil = tmp_path / "evil.py"
    evil.write_text(f"open({str(marker)!r}, 'w').close()\n" + USER_FILE)
    rows = [{"id": "1", "question": str(evil), "answer": "m*x'' + k*x = 0"},
            {"id": "2", "question": f"{evil}:eom", "answer": "m*x'' + k*x = 0"}]
    results = grade_rows(rows)
    assert [r["status"] for r in results] == ["invalid", "invalid"]
    assert "not a problem name" in results[0]["summary"]
    assert not marker.exists()
    assert not problems.is_name("os:path") and problems.is_name("toy_car")
