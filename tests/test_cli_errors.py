"""``dualmech.cli.errors``: the one set of exit statuses and the one handler.

What each kind of exception becomes (status, message), that every command's ``--help``
ends with the exit statuses, and that no command module defines codes or handlers of its
own.
"""
from __future__ import annotations

import argparse
import re
from pathlib import Path

import pytest

from dualmech.cli import errors
from dualmech.cli.errors import (DISAGREE, INTERRUPTED, OK, USAGE_OR_MODEL_ERROR, UsageError,
                                 describe, guarded, worst)
from dualmech.cli.main import build_parser, main

CLI = Path(errors.__file__).resolve().parent


def test_the_statuses_keep_their_meaning():
    assert (OK, DISAGREE, USAGE_OR_MODEL_ERROR, INTERRUPTED) == (0, 1, 2, 130)
    assert worst([OK, DISAGREE]) == DISAGREE
    assert worst([DISAGREE, USAGE_OR_MODEL_ERROR, OK]) == USAGE_OR_MODEL_ERROR
    assert worst([USAGE_OR_MODEL_ERROR, INTERRUPTED]) == INTERRUPTED


def test_no_command_module_defines_its_own_codes_or_handler():
    for path in CLI.glob("*.py"):
        if path.name == "errors.py":
            continue
        text = path.read_text()
        assert not re.search(r"^EXIT_\w+(, \w+)* = ", text, re.M), path.name
        assert not re.search(r"^class \w*Usage\w*\(", text, re.M), path.name
        assert "except KeyboardInterrupt" not in text, path.name
        assert "return 130" not in text and "return 2\n" not in text, path.name


def test_every_commands_help_ends_with_the_exit_statuses():
    parser = build_parser()
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    assert "Exit status: 0" in parser.epilog
    for name, sub in action.choices.items():
        assert "Exit status: 0" in sub.epilog and "2 " in sub.epilog, name


def test_a_usage_error_and_an_interrupt(capsys):
    @guarded
    def usage(args):
        raise UsageError("name a problem.")

    @guarded
    def interrupted(args):
        raise KeyboardInterrupt

    assert usage(argparse.Namespace(command="check")) == 2
    assert capsys.readouterr().err == "dualmech check: error: name a problem.\n"
    assert interrupted(argparse.Namespace(command="chart")) == 130
    assert capsys.readouterr().err == "dualmech chart: interrupted\n"


def test_an_error_in_the_users_file_is_shown_at_its_line(tmp_path):
    path = tmp_path / "mine.py"
    path.write_text("def build(k):\n    stiffness = 1 / k\n    return stiffness\n")
    code = compile(path.read_text(), str(path), "exec")
    namespace = {}
    exec(code, namespace)
    try:
        namespace["build"](0)
    except ZeroDivisionError as exc:
        failure = describe(exc)
    assert failure.status == 2 and failure.kind == "user"
    first, source, where, fix = failure.message.splitlines()
    assert first == f"{path}, line 2: ZeroDivisionError: division by zero"
    assert source == "    stiffness = 1 / k  # <- error"   # marked: kept whole when wrapped
    assert where == "  in build()" and fix.startswith("  to fix: a division by zero")


def test_an_internal_error_says_so_and_how_to_report_it(capsys, monkeypatch):
    exc = RuntimeError("Not Implemented")   # raised in no line of anyone's own code
    failure = describe(exc)
    assert failure.status == 2 and failure.internal
    assert failure.message.startswith("internal error: RuntimeError: Not Implemented")
    assert "bug in dualmech" in failure.message and "DUALMECH_TRACEBACK=1" in failure.message

    @guarded
    def crash(args):
        raise RuntimeError("Not Implemented")

    monkeypatch.setattr(errors, "_deliberate", lambda exc: False)
    monkeypatch.setattr(errors, "user_line", lambda *a: None, raising=False)
    import dualmech.problems as problems
    monkeypatch.setattr(problems, "user_error", lambda exc, files=(): None)
    assert crash(argparse.Namespace(command="check")) == 2
    assert "Traceback" not in capsys.readouterr().err
    monkeypatch.setenv("DUALMECH_TRACEBACK", "1")
    assert crash(argparse.Namespace(command="check")) == 2
    assert "Traceback" in capsys.readouterr().err


def test_a_refusal_by_dualmech_is_not_called_a_bug(capsys):
    status = main(["check", "simple_pendulum", "--points", "0"])
    assert status == 2 and "internal error" not in capsys.readouterr().err
    from dualmech.verify.check import compare
    with pytest.raises(TypeError) as info:
        compare("simple_pendulum")
    exc = info.value
    assert describe(exc).kind == "user"      # the calling line (this test's) is the one to fix
    exc.__traceback__ = exc.__traceback__.tb_next   # as if called from dualmech itself
    failure = describe(exc)
    assert failure.kind == "refused" and "look it up first" in failure.message


def test_a_hand_written_model_with_sign_that_fails_later_is_explained():
    """A failure deep in a library (here given, not raised) on a problem whose hand-written
    model uses sign(): the message is the refusal that says what to write instead."""
    import sympy as sp
    from dualmech import Coordinate, EquationSet, LENGTH, MASS, Parameter, Problem, coordinate
    m = sp.Symbol("m", positive=True)
    x = coordinate("x")

    class Rough(Problem):
        name, title, source = "rough", "Rough", "by hand"
        parameters = (Parameter(m, MASS, 1, (0.1, 10)),)
        coordinates = (Coordinate(x, LENGTH, (-1, 1)),)

        def lagrange(self):
            return EquationSet("lagrange", (x,), (m * x.diff("t", 2) + sp.sign(x.diff()),))

    failure = describe(RuntimeError("Not Implemented"), Rough())
    assert failure.status == 2 and failure.kind == "model"
    assert "sign(x') is not supported" in failure.message
    assert "one sliding phase of known direction" in failure.message
