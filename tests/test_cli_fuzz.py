"""The ``dualmech`` command under random arguments, and the wording of what it prints.

Issue 6, points 6 and 7.  Hypothesis draws argument lists -- sub-commands, flags, numbers
(``nan``, ``inf``, ``1e400``, non-ASCII digits), problem and model names, random unicode,
empty strings -- and :func:`dualmech.cli.main.main` must return an exit status in {0, 1, 2} (130
for an interrupt), never raise, and never print a traceback.

To stay fast (well under a minute on one core) the catalogue is cut to three cheap problems,
output goes to a temporary directory, numbers stay small (the absurd ones -- ``--points
1000000000``, ``--duration 1e300`` -- get their own deterministic tests, with the work
replaced by a stand-in that raises, so a missing bound shows as a failure, not a hang), and
the heavy sub-commands (``chart``, ``atlas``, ``fidelity``, ``grade --batch``) only see
arguments that cannot name a problem.

The last part pins the wording: "1 point" not "1 points", a bound past double precision as
"< 1e-300", ``show`` with "= 0" on the equation's line and no ``Derivative(...)``.
"""
from __future__ import annotations

import contextlib
import io
import os
import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dualmech import problems
from dualmech.cli.main import main

CHEAP = ("mass_spring_gravity", "satellite_polar", "spring_mass_damper")
MODELS = ("lagrange", "newton_euler", "gravity_as_force", "angular_momentum", "")
STATUSES = {0, 1, 2, 130}


@pytest.fixture(scope="module")
def sandbox(tmp_path_factory):
    """The catalogue cut to the cheap problems (built once) and a scratch working directory."""
    built = {name: problems.get(name) for name in CHEAP}
    real_get = problems.get

    def get(name, **options):
        if name in built and not options:
            return built[name]
        if name in built:
            return real_get(name, **options)
        raise KeyError(f"no problem named {name!r} in the test catalogue")

    scratch = tmp_path_factory.mktemp("cli_fuzz")
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(problems, "get", get)
        mp.setattr(problems, "all_problems", lambda: list(built.values()))
        mp.chdir(scratch)
        yield scratch


def run(argv) -> tuple[int, str, str]:
    """``main(argv)`` -> (status, stdout, stderr); any exception escaping is a failure."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))
    return status, out.getvalue(), err.getvalue()


def assert_well_behaved(argv, status, out, err) -> None:
    assert isinstance(status, int) and not isinstance(status, bool), (argv, status)
    assert status in STATUSES, (argv, status, err)
    assert "Traceback" not in err and "Traceback" not in out, (argv, err)
    if status == 2:
        assert "error" in err.lower() or "usage" in err.lower(), (argv, err)


# -- strategies ----------------------------------------------------------------------------------
SMALL_NUMBERS = ("0", "1", "2", "3", "-1", "0.01", "0.001", "1e-3", "nan", "NaN", "inf",
                 "-inf", "1e400", "-1e400", "0x10", "١", "٢", "+1", " 1", "1_0", "1.5",
                 "2e0", "", " ", "١e-2", "0.0", "-0", "1e-320", "\x00", "a\x00b")
FLAGS = ("--all", "--json", "--n", "--points", "--seed", "--latex", "--model", "--out",
         "--duration", "--help", "-h", "--", "-", "--points=1", "--seed=-7", "--n=2",
         "--duration=0.01", "--version", "--nope", "--list", "--quantity", "--answer",
         "--about", "--answer-file", "--no-progress")
#: random text that cannot be an option (argparse accepts abbreviations of long options)
WORDS = st.text(st.characters(blacklist_categories=("Cs",)), max_size=10).filter(
    lambda s: not s.startswith(("-", "/", "~")) and ".." not in s and s not in CHEAP)
ANSWERS = ("theta''", "x'' + 1 = 0", "M*x'' + k*x = F - M*g", "__import__('os')", "", "=",
           "x''''''''", "1/0", "x**x**x**x**99", "sin(", "é = 0")


def _token():
    return st.one_of(st.sampled_from(FLAGS), st.sampled_from(SMALL_NUMBERS),
                     st.sampled_from(CHEAP), st.sampled_from(MODELS), st.sampled_from(ANSWERS),
                     WORDS)


def _argv(commands):
    return st.tuples(st.sampled_from(commands),
                     st.lists(_token(), max_size=6)).map(lambda c: [c[0], *c[1]])


LIGHT = ("list", "check", "show", "grade", "", "chekc", "--version", "-h", "help", "LIST")


# -- the fuzz ------------------------------------------------------------------------------------
@settings(max_examples=70, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(argv=_argv(LIGHT))
def test_random_arguments_never_escape(sandbox, argv):
    assert_well_behaved(argv, *run(argv))


@settings(max_examples=25, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(argv=st.tuples(st.sampled_from(("check", "show", "grade")), st.sampled_from(CHEAP),
                      st.lists(_token(), max_size=4)).map(lambda c: [c[0], c[1], *c[2]]))
def test_random_arguments_on_a_real_problem_never_escape(sandbox, argv):
    assert_well_behaved(argv, *run(argv))


@settings(max_examples=20, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(argv=st.tuples(st.sampled_from(("chart", "atlas", "fidelity")),
                      st.lists(st.one_of(WORDS, st.sampled_from(
                          ("--out", "--section", "--duration", "--quick", "-h", "0", "nan",
                           "inf", "-1", ""))), max_size=4)).map(lambda c: [c[0], *c[1]]))
def test_heavy_commands_without_a_problem_never_escape(sandbox, argv):
    assert_well_behaved(argv, *run(argv))


@settings(max_examples=6, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(points=st.sampled_from(("1", "2", "0", "-1", "x", "nan")),
       duration=st.sampled_from(("0.01", "0.02", "0", "-1", "nan", "inf", "1e400", "x", "")),
       seed=st.sampled_from(("0", "-5", "x", "99999999999999999999")),
       out=st.one_of(WORDS.filter(bool), st.sampled_from(("report", "a b", "é"))))
def test_random_reports_never_escape(sandbox, points, duration, seed, out):
    argv = ["report", "--out", out, "--points", points, "--duration", duration, "--seed", seed]
    status, stdout, stderr = run(argv)
    assert_well_behaved(argv, status, stdout, stderr)
    if status in (0, 1):
        assert (sandbox / out / "report.md").is_file()


# -- bad output places: one line, exit 2 -----------------------------------------------------------
@pytest.mark.parametrize("where", ["/proc/dualmech_cannot_write_here", "/dev/null/x",
                                   "a_file"])
def test_unwritable_report_directory_is_one_line_and_exit_2(sandbox, where):
    (sandbox / "a_file").write_text("not a directory\n")
    status, out, err = run(["report", "--out", where, "--points", "1", "--duration", "0.01"])
    assert status == 2
    assert err.count("\n") == 1 and "error" in err and where in err
    assert "Traceback" not in err


def test_an_impossible_path_is_named_not_an_exception_class(sandbox):
    status, _, err = run(["report", "--out", "a\x00b", "--points", "1", "--duration", "0.01"])
    assert status == 2 and "Traceback" not in err
    assert not re.search(r"error: [A-Z]\w*Error:", err), err


def test_an_unreadable_input_is_not_called_unwritable(sandbox):
    (sandbox / "a_directory.csv").mkdir(exist_ok=True)
    status, _, err = run(["grade", "--batch", "a_directory.csv", "--out", "grades"])
    assert status == 2 and "Traceback" not in err
    assert "cannot write" not in err and "a_directory.csv" in err


class _WorkStarted(Exception):
    """Raised by a stand-in: the argument was accepted and the work began."""


def _refuse_work(*args, **kwargs):
    raise _WorkStarted


def _stub_everywhere(monkeypatch, *names: str) -> None:
    """Replace each of ``names`` by :func:`_refuse_work` in every ``dualmech`` module that has
    it, after importing every module of the packages the command uses (wherever the command
    looks the function up, the stand-in is found)."""
    import importlib
    import pkgutil
    import sys
    for package in ("dualmech.numeric", "dualmech.report", "dualmech.verify"):
        with contextlib.suppress(Exception):
            pkg = importlib.import_module(package)
            for info in pkgutil.iter_modules(pkg.__path__, package + "."):
                with contextlib.suppress(Exception):
                    importlib.import_module(info.name)
    with contextlib.suppress(ImportError):
        importlib.import_module("dualmech.verify.check")
    for name in names:
        for module_name, module in list(sys.modules.items()):
            if module_name.startswith(("dualmech", "scipy.integrate")) \
                    and callable(getattr(module, name, None)):
                monkeypatch.setattr(module, name, _refuse_work)


def test_absurd_durations_are_refused(sandbox, monkeypatch):
    _stub_everywhere(monkeypatch, "simulate", "scene_span", "solve_ivp")
    status, _, err = run(["report", "--out", "r", "--points", "1", "--duration", "1e300"])
    assert status == 2 and "--duration" in err


def test_absurd_point_counts_are_refused(sandbox, monkeypatch):
    _stub_everywhere(monkeypatch, "compare")
    status, _, err = run(["check", "mass_spring_gravity", "--points", "1000000000"])
    assert status == 2 and "--points" in err


# -- wording ---------------------------------------------------------------------------------------
def test_one_point_is_singular_in_the_text_report(sandbox):
    status, out, _ = run(["check", "mass_spring_gravity", "--points", "1"])
    assert status == 0
    assert "1 point," in out
    assert not re.search(r"\b1 points\b", out)


def test_one_point_is_singular_in_json(sandbox):
    status, out, _ = run(["check", "satellite_polar", "--json", "--points", "1"])
    assert status == 0
    assert not re.search(r"\b1 points\b", out)


def test_a_bound_past_double_precision_is_printed_as_below_1e_300(sandbox):
    status, out, _ = run(["check", "mass_spring_gravity", "--points", "40"])
    assert status == 0
    assert "< 1e-300" in out
    assert "0.0e+00" not in out and "e-3" not in out.replace("1e-300", "")


def test_a_bound_past_double_precision_has_one_comparison(sandbox):
    _, out, _ = run(["check", "mass_spring_gravity", "--points", "40"])
    assert "P(false equal) < 1e-300" in out and "<= <" not in out


@pytest.mark.parametrize("latex", [False, True])
def test_show_puts_the_equals_sign_on_the_equation_line(sandbox, latex):
    # each row is written `left = right` (show groups it by acceleration), the sign on the
    # line of the terms, never alone on a line of its own
    argv = ["show", "satellite_polar"] + (["--latex"] if latex else [])
    status, out, _ = run(argv)
    assert status == 0
    lines = out[out.index("\n== "):].splitlines()
    with_equals = [ln for ln in lines if re.search(r"\S\s+=\s+\S", ln)
                   and not ln.startswith("==")]
    assert len(with_equals) == 4   # two equations in each of the two models
    assert all(not ln.strip().startswith("=") and not ln.strip().endswith("=")
               for ln in with_equals)
    assert "Derivative(" not in out


def test_check_prints_primes_not_derivatives(sandbox):
    for argv in (["check", "spring_mass_damper"], ["check", "satellite_polar", "--json"]):
        status, out, _ = run(argv)
        assert status == 0 and "Derivative(" not in out
    assert os.getcwd() == str(sandbox)
