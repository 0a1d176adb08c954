"""Command-line conventions: ``--json`` on every command, progress on stderr when it is not a
terminal, the exit status kept when standard output is closed, and help that names the files.

The problems are a block on a spring (by hand: ``x'' = -k x / m``, frequency ``sqrt(k/m) = 5``
at ``m = 2``, ``k = 50``) and its twin with the slip ``V = k x^2``, written to a file."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from dualmech.cli.main import build_parser, main

from test_loader import USER_FILE


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


@pytest.fixture
def springs(tmp_path):
    path = tmp_path / "springs.py"
    path.write_text(USER_FILE)
    return path


def _subcommands():
    parser = build_parser()
    action = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    return action.choices


def test_every_command_takes_json():
    commands = _subcommands()
    assert {"list", "check", "show", "report", "grade", "chart", "atlas", "fidelity"} <= \
        set(commands)
    for name, sub in commands.items():
        options = {o for a in sub._actions for o in a.option_strings}
        assert "--json" in options, name


def test_report_help_names_report_html(capsys):
    status, out, _ = run(capsys, "report", "--help")
    assert status == 0 and "report.html" in out
    status, out, _ = run(capsys, "--help")
    assert "report.html" in out


def test_show_json_has_the_models_and_the_reaction(capsys):
    status, out, _ = run(capsys, "show", "simple_pendulum", "--json")
    assert status == 0
    d = json.loads(out)
    assert set(d["models"]) == {"newton_euler", "lagrange", "angular_momentum", "multiplier"}
    ne = d["models"]["newton_euler"]
    assert ne["unknowns"] == ["T"] and len(ne["equations"]) == 2
    assert all(e["label"] and e["expression"] for e in ne["equations"])
    assert d["equivalent"] is True
    assert set(d["reactions"]) == {"T"} and "towards the pivot" in d["reactions"]["T"]["direction"]


def test_check_of_several_prints_progress_lines_on_a_non_terminal_stderr(capsys, springs):
    status, out, err = run(capsys, "check", f"{springs}:Spring", f"{springs}:WrongSpring")
    assert status == 1
    lines = err.splitlines()
    assert lines[0] == "checking 1/2: my_spring"
    assert lines[1] == "checking 2/2: my_wrong_spring"
    assert lines[2].startswith("checking: 2 problems done in ")


@pytest.mark.parametrize("spec, status", [("Spring", 0), ("WrongSpring", 1)])
def test_a_closed_stdout_keeps_the_exit_status(springs, spec, status):
    """``dualmech check X | head -1`` (here: the reader closes before anything is written)
    exits with the verdict, with no traceback, as a shell with ``pipefail`` needs."""
    proc = subprocess.Popen([sys.executable, "-m", "dualmech", "check", f"{springs}:{spec}"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=300) == status
    assert "Traceback" not in err and "BrokenPipe" not in err and "Exception ignored" not in err


def test_numeric_commands_print_json(capsys, springs, tmp_path):
    spec = f"{springs}:Spring"
    status, out, err = run(capsys, "atlas", spec, "--section", "linearisation", "--json",
                           "--out", str(tmp_path / "o"))
    assert status == 0, err
    d = json.loads(out)
    (mode,) = d["results"]["linearisation"]
    assert abs(mode["frequency"] - 5.0) < 1e-9      # sqrt(k/m) = sqrt(50/2), by hand
    assert all((tmp_path / "o").joinpath(p).exists() for p in d["files"])
    status, out, err = run(capsys, "fidelity", spec, "--json", "--out", str(tmp_path / "o"))
    assert status == 0, err
    rungs = json.loads(out)["rungs"]
    # the spring is linear: its linearisation is the same model (the same right-hand side
    # integrated the same way), so the rung's error is zero to rounding
    assert rungs[0]["model"] == "linearised" and rungs[0]["error_final"] <= 1e-12
    status, out, err = run(capsys, "chart", spec, "--quick", "--duration", "0.5", "--json",
                           "--out", str(tmp_path / "o"))
    assert status == 0, err
    d = json.loads(out)
    assert d["problem"] == "my_spring" and d["runs"] and d["files"]


def test_report_json_summary_and_progress_lines(capsys, springs, tmp_path, monkeypatch):
    from dualmech import problems
    monkeypatch.setattr(problems, "all_problems",
                        lambda: [problems.load(f"{springs}:Spring"),
                                 problems.load(f"{springs}:WrongSpring")])
    out_dir = tmp_path / "report"
    status, out, err = run(capsys, "report", "--out", str(out_dir), "--duration", "0.5",
                           "--json")
    assert status == 1                                   # the wrong spring disagrees
    d = json.loads(out)
    assert [(p["problem"], p["equivalent"]) for p in d["problems"]] == \
        [("my_spring", True), ("my_wrong_spring", False)]
    assert d["files"]["html"] == str(out_dir / "report.html")
    assert (out_dir / "report.html").exists()
    assert all(Path(p).exists() for p in d["files"]["json"] + d["files"]["charts"])
    lines = err.splitlines()
    assert "checking 1/2: my_spring" in lines and "charts 2/2: my_wrong_spring" in lines
