"""The ``dualmech`` command line: list, check, show, report, exit statuses and JSON schema.

Most tests run on two tiny problems defined here -- a mass on a spring resting on a floor,
written correctly twice, and the same with a wrong Lagrangian -- swapped into the catalogue
with ``monkeypatch``, so they are fast and do not depend on the real problems.  A few run on
the real catalogue.
"""
from __future__ import annotations

import contextlib
import io
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

from dualmech import problems
from dualmech import coordinate, t
from dualmech.cli.main import main
from dualmech.model.dimensions import ACCELERATION, FORCE, LENGTH, MASS, STIFFNESS
from dualmech.model.equations import EquationSet
from dualmech.model.lagrange import Lagrangian
from dualmech.model.problem import Coordinate, Parameter, Problem, Reaction

m, k, g = sp.symbols("m k g", positive=True)
x = coordinate("x")
N = sp.Symbol("N", real=True)

#: keys every ``check --json`` object carries (the lead's Comparison.to_dict)
SCHEMA = {"name", "title", "source", "coordinates", "parameters", "equivalent", "method",
          "seconds", "eom", "accelerations", "reactions", "reaction_directions", "published",
          "mismatches"}


class SpringOnFloor(Problem):
    """A block on a frictionless floor, tied to a wall by a spring.

    ::

        wall |--/\\/\\/--[ m ]  -> x      N (floor on block) up, m g down
    """

    name, title, source = "spring_on_floor", "Block on a spring, on a floor", "test: by hand"
    parameters = (Parameter(m, MASS, 2.0, (0.1, 10.0)), Parameter(k, STIFFNESS, 50.0, (1, 500)),
                  Parameter(g, ACCELERATION, 9.81, (1, 20)))
    coordinates = (Coordinate(x, LENGTH, (-0.5, 0.5)),)
    reactions = (Reaction("N", FORCE, "floor on block, up"),)

    def newton_euler(self) -> EquationSet:
        return EquationSet("newton_euler", (x,), (-k * x - m * x.diff(t, 2), N - m * g),
                           unknowns=(N,), labels=("sum F . x", "sum F . y"))

    def lagrange(self) -> EquationSet:
        lg = Lagrangian(coordinates=[x])
        lg.kinetic("T", m * x.diff(t)**2 / 2)
        lg.potential("V", self.stiffness_factor * k * x**2 / 2)
        return lg.equations()

    stiffness_factor = 1


class WrongSpring(SpringOnFloor):
    """The same block with the classic slip: V = k x^2 instead of k x^2 / 2."""

    name, title = "wrong_spring", "Block on a spring, Lagrangian with V = k x^2"
    stiffness_factor = 2


@pytest.fixture
def tiny_catalogue(monkeypatch):
    """Replace the catalogue by the two tiny problems."""
    catalogue = {"spring_on_floor": SpringOnFloor, "wrong_spring": WrongSpring}

    def all_problems():
        return [cls() for cls in catalogue.values()]

    def module_of(name):
        if name not in catalogue:
            raise KeyError(f"no problem named {name!r}; known problems: {', '.join(catalogue)}.")
        cls = catalogue[name]
        return problems.Declaration("test", cls.__name__, name, cls.title, cls.source, "",
                                    tuple(c.name for c in cls.coordinates), ())

    def get(name, **options):
        module_of(name)
        return catalogue[name]()

    monkeypatch.setattr(problems, "all_problems", all_problems)
    monkeypatch.setattr(problems, "get", get)
    monkeypatch.setattr(problems, "module_of", module_of)
    monkeypatch.setattr(problems, "declarations", lambda: [module_of(n) for n in catalogue])
    monkeypatch.setattr(problems, "OUT_OF_SCOPE", ())
    return catalogue


def run(capsys, *argv):
    """``main(argv)`` -> (exit status, stdout, stderr)."""
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


# -- help and usage ---------------------------------------------------------------------------
def test_help_lists_the_commands(capsys):
    status, out, _ = run(capsys, "--help")
    assert status == 0
    for command in ("list", "check", "show", "report"):
        assert command in out


@pytest.mark.parametrize("argv", [["--help"], ["list"], ["grade", "--help"]],
                         ids=["help", "list", "grade-help"])
def test_commands_that_need_no_algebra_start_without_sympy(argv):
    code = ("import sys; from dualmech.cli.main import main; status = main(sys.argv[1:]); "
            "heavy = sorted(m for m in ('sympy', 'symengine', 'numpy', 'scipy', 'matplotlib', "
            "'lark') if m in sys.modules); print(status, heavy, file=sys.stderr)")
    done = subprocess.run([sys.executable, "-c", code, *argv], capture_output=True,
                          text=True, timeout=120)
    assert done.stderr.strip().splitlines()[-1] == "0 []"


def test_the_parsers_notations_are_those_of_the_notation_module():
    from dualmech.cli import main as cli
    from dualmech.model import notation
    assert cli._NOTATIONS == notation.NOTATIONS


@pytest.mark.parametrize("argv", [[], ["frobnicate"], ["check", "--points", "0"],
                                  ["show"]], ids=["nothing", "unknown-command", "zero-points",
                                                  "show-without-name"])
def test_usage_errors_exit_2(capsys, argv):
    status, _, err = run(capsys, *argv)
    assert status == 2
    assert "usage:" in err


def test_check_needs_names_or_all(capsys, tiny_catalogue):
    status, _, err = run(capsys, "check")
    assert status == 2
    assert "spring_on_floor" in err  # the message lists the known problems
    status, _, err = run(capsys, "check", "--all", "spring_on_floor")
    assert status == 2
    assert "not both" in err


def test_unknown_problem_exits_2_and_lists_the_known_names(capsys, tiny_catalogue):
    status, out, err = run(capsys, "check", "no_such_problem")
    assert status == 2
    assert out == ""
    assert "no_such_problem" in err
    assert "spring_on_floor" in err and "wrong_spring" in err


# -- list ---------------------------------------------------------------------------------------
def test_list_shows_name_dof_reactions_and_title(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "list")
    assert status == 0
    header, rule, *rows = out.strip().split("\n\n")[0].splitlines()
    assert header.split() == ["name", "dof", "reactions", "title"]
    assert len(rows) == 2
    assert rows[0].split()[:3] == ["spring_on_floor", "1", "-"]
    assert rows[0].endswith("Block on a spring, on a floor")


def test_list_json_carries_source_and_summary(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "list", "--json")
    assert status == 0
    rows = json.loads(out)
    assert [r["name"] for r in rows] == ["spring_on_floor", "wrong_spring"]
    assert rows[0]["source"] == "test: by hand" and rows[0]["dof"] == 1
    assert rows[0]["source_file"] is None            # "test" is not a file name
    assert rows[0]["status"] == "modelled" and rows[0]["coordinates"] == ["x"]


#: the archive's file names: ``000_203248afac9714e6.txt``
HASHED = re.compile(r"\d{3}_[0-9a-f]{16}")


def test_sources_are_named_by_course_with_the_file_beside_them(capsys):
    """Over the whole catalogue: what a person reads names the course and the problem; the
    file stays in JSON as ``source_file``.  By hand from sources/README.md: 001 is MIT 2.003J
    (Spring 2011), 000 the lecture notes on Lagrange's method."""
    out = run(capsys, "list")[1]
    assert not HASHED.search(out)
    rows = json.loads(run(capsys, "list", "--json")[1])
    declared = {d.name: d.source for d in problems.declarations()}
    declared.update({name: source for name, source, _ in problems.OUT_OF_SCOPE})
    assert {r["name"] for r in rows} == set(declared)
    for r in rows:
        assert not HASHED.search(r["source"] + r["summary"] + r["title"]), r
        file = declared[r["name"]].partition(": ")[0]
        if HASHED.match(file):
            assert r["source_file"] == file and r["source"].endswith(
                declared[r["name"]].partition(": ")[2].split(", ")[-1])
        else:
            assert r["source_file"] is None and r["source"] == declared[r["name"]]
    toy = next(r for r in rows if r["name"] == "toy_car")
    assert toy["source"] == "MIT 2.003J Dynamics and Control I, Spring 2011: quiz 1"
    assert toy["source_file"] == "001_9d08622cf8d659c2.txt"
    assert next(r for r in rows if r["name"] == "shaft_torsion")["source"].startswith(
        "Exam \"Dynamics and Stability\"")
    shown = json.loads(run(capsys, "show", "simple_pendulum", "--json")[1])
    checked = json.loads(run(capsys, "check", "simple_pendulum", "--json")[1])
    for doc in (shown, checked):
        assert doc["source"] == ("Cambridge 3C5 Dynamics, Lagrangian mechanics: section 2.2, "
                                 "Lagrange's equation for a simple pendulum")
        assert doc["source_file"] == "002_df41972c66c4514e.txt"
    for argv in (("show", "simple_pendulum"), ("check", "simple_pendulum")):
        out = run(capsys, *argv)[1]
        assert "Cambridge 3C5" in out and not HASHED.search(out)


def test_list_of_the_real_catalogue_fits_100_columns(capsys):
    status, out, _ = run(capsys, "list")
    assert status == 0
    assert max(len(line) for line in out.splitlines()) <= 100
    names = [line.split()[0] for line in out.split("\n\n")[0].splitlines()[2:]]
    assert names == [d.name for d in problems.declarations()]
    for d in problems.declarations():   # a title is whole, or cut with "..." at the right end
        row = next(line for line in out.splitlines() if line.split()[:1] == [d.name])
        shown = row.split("  ")[-1].strip()
        assert d.title == shown or (shown.endswith("...") and d.title.startswith(shown[:-3]))
    rows = json.loads(run(capsys, "list", "--json")[1])
    assert {r["title"] for r in rows if r["status"] == "modelled"} == \
        {p.title for p in problems.all_problems()}


# -- check ---------------------------------------------------------------------------------------
def test_check_of_agreeing_models_exits_0(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "check", "spring_on_floor")
    assert status == 0
    assert "spring_on_floor" in out


def test_check_of_disagreeing_models_exits_1(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "check", "wrong_spring")
    assert status == 1
    assert "wrong_spring" in out


def test_check_all_exits_1_when_any_pair_disagrees(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "check", "--all")
    assert status == 1
    assert "spring_on_floor" in out and "wrong_spring" in out


def test_check_json_for_one_problem_is_one_object_with_the_schema(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "check", "spring_on_floor", "--json")
    assert status == 0
    d = json.loads(out)
    assert isinstance(d, dict)
    assert SCHEMA <= set(d)
    assert d["name"] == "spring_on_floor"
    assert d["equivalent"] is True
    assert d["coordinates"] == ["x"]
    assert set(d["reactions"]) == {"N"}
    assert sp.sympify(d["reactions"]["N"]) == sp.sympify("g*m")
    assert d["mismatches"] == []


def test_check_json_for_several_problems_is_a_list(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "check", "--all", "--json", "--points", "3", "--seed", "7")
    assert status == 1
    data = json.loads(out)
    assert [d["name"] for d in data] == ["spring_on_floor", "wrong_spring"]
    assert [d["equivalent"] for d in data] == [True, False]
    assert all(SCHEMA <= set(d) for d in data)
    assert data[1]["mismatches"], "a disagreement must say where"


def test_check_of_a_problem_that_cannot_be_built_exits_2_at_its_line(capsys, tiny_catalogue):
    """A model that cannot be built is not a disagreement (1 is "the models disagree"): 2,
    with the error shown at the line of the problem's own file that raised it."""
    class Broken(SpringOnFloor):
        name = "broken"

        def lagrange(self):
            raise ValueError("this model is broken on purpose")

    line = Broken.lagrange.__code__.co_firstlineno + 1
    tiny_catalogue["broken"] = Broken
    status, out, err = run(capsys, "check", "broken", "--json")
    assert status == 2
    d = json.loads(out)
    assert d["equivalent"] is False and "broken on purpose" in d["error"]
    flat = " ".join(err.split())   # the message as words: it is wrapped to the terminal
    assert f"{__file__}, line {line}: ValueError: this model is broken on purpose" in flat
    assert 'raise ValueError("this model is broken on purpose")' in err
    assert "Traceback" not in err
    status, out, err = run(capsys, "check", "--all")   # the worst status of several: 2
    assert status == 2 and "wrong_spring" in out and f"line {line}" in " ".join(err.split())


# -- show ---------------------------------------------------------------------------------------
def test_show_prints_every_model_then_the_reactions(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "show", "spring_on_floor")
    assert status == 0
    assert out.index("newton_euler") < out.index("lagrange") < out.index("reactions")
    assert "sum F . x" in out


def test_show_latex(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "show", "spring_on_floor", "--latex")
    assert status == 0
    assert r"\ddot{x}" in out and r"\frac{d" not in out        # textbook dots
    assert "N = g m" in out


def test_show_one_model(capsys, tiny_catalogue):
    status, out, _ = run(capsys, "show", "spring_on_floor", "--model", "lagrange")
    assert status == 0
    assert "lagrange" in out and "newton_euler" not in out


def test_show_unknown_model_exits_2_and_lists_the_models(capsys, tiny_catalogue):
    status, _, err = run(capsys, "show", "spring_on_floor", "--model", "kane")
    assert status == 2
    assert "newton_euler" in err and "lagrange" in err


def test_show_latex_of_a_real_problem_uses_dotted_rates(capsys):
    name = "toy_car"
    status, out, _ = run(capsys, "show", name, "--latex")
    assert status == 0
    assert r"\dot{\theta}" in out  # in the recovered reaction F_r


# -- report ---------------------------------------------------------------------------------------
def test_report_writes_markdown_json_and_charts(capsys, tiny_catalogue, tmp_path):
    out_dir = tmp_path / "out"
    status, out, _ = run(capsys, "report", "--out", str(out_dir), "--points", "3",
                         "--duration", "0.5")
    assert status == 1  # wrong_spring disagrees
    assert "spring_on_floor" in out and "wrong_spring" in out
    report = (out_dir / "report.md").read_text()
    assert report.startswith("# dualmech report")
    assert "![spring_on_floor" in report
    for name in ("spring_on_floor", "wrong_spring"):
        d = json.loads((out_dir / f"{name}.json").read_text())
        assert SCHEMA <= set(d)
        png = (out_dir / f"{name}_reactions.png").read_bytes()
        assert png.startswith(b"\x89PNG")


# -- the installed entry points ------------------------------------------------------------------
def test_python_dash_m_dualmech_runs(tmp_path):
    done = subprocess.run([sys.executable, "-m", "dualmech", "check", "no_such_problem"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2
    assert "known problems" in done.stderr


def test_main_in_process_leaves_the_garbage_collector_alone(capsys):
    # only the program (cli.command) pauses and freezes the collector; tests, notebooks and
    # the web server call main() and live on
    import gc
    frozen = gc.get_freeze_count()
    assert main(["grade", "simple_pendulum", "--answer", "a*theta'' + g*sin(theta) = 0"]) == 0
    assert main(["show", "simple_pendulum"]) == 0
    assert gc.isenabled() and gc.get_freeze_count() == frozen


@pytest.mark.parametrize("answer, status, first", [
    ("a*theta'' + g*sin(theta) = 0", 0, "RIGHT"), ("a*theta'' - g*sin(theta) = 0", 1, "WRONG")],
    ids=["right", "wrong"])
def test_the_command_keeps_its_output_and_status_past_its_fast_exit(answer, status, first,
                                                                     tmp_path):
    # command() leaves the objects to the operating system at exit: the whole output is
    # still written, atexit handlers still run, and the exit status is the command's
    code = ("import atexit, sys; from dualmech.cli.main import command; "
            f"atexit.register(lambda: open({str(tmp_path / 'ran')!r}, 'w').close()); "
            "sys.argv[1:] = ['grade', 'simple_pendulum', '--json', '--answer', "
            f"{answer!r}]; raise SystemExit(command())")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == status, done.stderr
    assert json.loads(done.stdout)["status"] == first.lower()
    assert (tmp_path / "ran").exists()


# -- the README stays true ---------------------------------------------------------------------
README = Path(__file__).resolve().parent.parent / "README.md"
CI_SCRIPT = README.parent / ".ci" / "run"
FULL_TESTS = "python -m pytest -n 2 -q"


def _shell_blocks(text: str) -> list[str]:
    return [b.strip() for b in re.findall(r"```sh\n(.*?)```", text, re.S)]


def test_readme_example_runs_and_prints_what_it_says():
    """The README's one example is a doctest: run it and compare what it prints, line by
    line, with what the README shows."""
    import doctest
    text = README.read_text(encoding="utf-8")
    test = doctest.DocTestParser().get_doctest(text, {"__name__": "readme_example"}, "README.md",
                                               str(README), 0)
    assert len(test.examples) >= 3
    assert test.examples[0].source.startswith("from dualmech import ")
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    report = io.StringIO()
    runner.run(test, out=report.write)
    assert runner.failures == 0, report.getvalue()


def test_ci_runs_the_readme_test_command_after_building_the_docs():
    """The README's full test command is the last line of .ci/run; its quick command is the
    same leaving out the slow tests; CI installs the docs extra and builds the manual with
    warnings as errors before the tests."""
    text = README.read_text(encoding="utf-8")
    tests = _shell_blocks(text)[1]
    assert tests.endswith(FULL_TESTS)
    assert f'`{FULL_TESTS} -m "not slow"`' in text
    ci = CI_SCRIPT.read_text().strip().splitlines()
    assert ci[-1] == FULL_TESTS
    build = "python -m sphinx -W -b html docs docs/_build/html"
    assert build in ci and ci.index(build) < len(ci) - 1
    assert any("pip install" in line and ".[test,docs]" in line for line in ci)


def test_readme_main_job_command_is_a_valid_report_command():
    """The README's first command installs the package and ends with `dualmech report`, with
    arguments the command line accepts."""
    from dualmech.cli.main import build_parser
    setup = _shell_blocks(README.read_text(encoding="utf-8"))[0]
    assert "pip install -e ." in setup
    command = setup.rsplit("&&", 1)[1].split()
    assert command[:2] == ["dualmech", "report"]
    args = build_parser().parse_args(command[1:])
    assert Path(args.out) == Path("out") and args.command == "report"


def test_readme_links_point_to_pages_of_the_manual():
    text = README.read_text(encoding="utf-8")
    links = re.findall(r"\]\((docs/[^)]+)\)", text)
    assert len(links) >= 10
    for link in links:
        assert (README.parent / link).is_file(), link
