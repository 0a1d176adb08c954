"""`dualmech check` of several problems in worker processes prints what one process prints."""
from __future__ import annotations

import json
import re

from dualmech.cli.main import main

CHEAP = ["spring_mass_damper", "simple_pendulum", "mass_spring_gravity"]


def _run(capsys, *argv) -> tuple[int, str]:
    code = main(["check", *argv])
    out = capsys.readouterr().out
    return code, re.sub(r"\d+\.\d+ s\b", "X s", out)


def test_parallel_check_prints_the_same_report_in_the_same_order(capsys):
    code1, one = _run(capsys, *CHEAP, "-j", "1")
    code2, two = _run(capsys, *CHEAP, "-j", "2")
    assert code1 == code2 == 0
    strip = lambda s: re.sub(r"(?m)^(\S+ +\d+ +\w+ +.*?) +[0-9.]+ +", r"\1 ", s)  # noqa: E731
    assert strip(one) == strip(two)
    assert [m.group(1) for m in re.finditer(r"(?m)^(\w+): ", two)][:3] == CHEAP


def test_parallel_check_json_and_exit_status(capsys):
    code, out = _run(capsys, *CHEAP[:2], "--json", "-j", "2")
    data = json.loads(out)
    assert code == 0
    assert [d["name"] for d in data] == CHEAP[:2]
    assert all(d["equivalent"] for d in data)


def test_jobs_must_be_positive(capsys):
    assert main(["check", *CHEAP[:2], "-j", "0"]) == 2
    assert "--jobs/-j: expected a positive integer, got 0" in capsys.readouterr().err
