"""``dualmech grade``: the command, CSV batches on a process pool and on Dask, the reports.

The subcommand is tested through a parser built here with :func:`dualmech.cli.grade.register`,
as the main ``dualmech`` command wires it.  Batches use the simple pendulum and the toy car;
the verdicts they must reach are those of the single-answer tests (``a theta'' + g sin(theta)``
is the pendulum's equation; its mirror image with ``-g`` is not).
"""
from __future__ import annotations

import argparse
import csv
import json

import pytest

from dualmech.grade.batch import BatchError, grade_batch, grade_rows, read_csv
from dualmech.cli.grade import EXIT_RIGHT, EXIT_USAGE, EXIT_WRONG, register
from dualmech.grade.report import summarise, write_report

RIGHT = "a*theta'' + g*sin(theta) = 0"
WRONG = "a*theta'' - g*sin(theta) = 0"
TOY_F = "m*(g*cos(phi)*cos(theta) + R*phi'^2*cos(theta)^2 + R*theta'^2)"
TOY_F_WRONG = "m*(g*cos(phi)*cos(theta) + R*phi'^2*cos(theta)^2 - R*theta'^2)"

ROWS = [
    {"id": "ana", "question": "simple_pendulum", "answer": RIGHT},
    {"id": "ben", "question": "simple_pendulum", "answer": WRONG},
    {"id": "cy", "question": "simple_pendulum", "answer": WRONG.replace("a*", "2*a*")},
    {"id": "ana", "question": "toy_car:F_r", "answer": TOY_F},
    {"id": "ben", "question": "toy_car:F_r", "answer": TOY_F_WRONG},
    {"id": "cy", "question": "toy_car", "quantity": "F_r", "answer": TOY_F_WRONG},
    {"id": "dee", "question": "toy_car:F_r", "answer": "__import__('os').system('ls')"},
    {"id": "eve", "question": "no_such_problem", "answer": RIGHT},
    {"id": "fay", "question": "simple_pendulum:eom", "answer": RIGHT},
]
STATUSES = ["right", "wrong", "wrong", "right", "wrong", "wrong", "invalid", "invalid", "right"]


def run(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="dualmech")
    register(parser.add_subparsers(dest="command"))
    args = parser.parse_args(["grade"] + argv)
    return args.func(args)


def write_csv(path, rows):
    with path.open("w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=["id", "question", "quantity", "answer"])
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in ("id", "question", "quantity", "answer")})


# -- one answer ---------------------------------------------------------------------------------
def test_exit_status_and_text(capsys):
    assert run(["simple_pendulum", "--answer", RIGHT]) == EXIT_RIGHT
    assert capsys.readouterr().out.startswith("RIGHT: equivalent")
    assert run(["simple_pendulum", "--answer", WRONG]) == EXIT_WRONG
    out = capsys.readouterr().out
    assert out.startswith("WRONG") and "wrong sign" in out
    assert run(["simple_pendulum", "--answer", "a*thetaa'' + g"]) == EXIT_USAGE
    assert "unknown name `thetaa`" in capsys.readouterr().out


def test_json_and_quantities(capsys):
    assert run(["toy_car", "--quantity", "F_r", "--answer", TOY_F_WRONG, "--json"]) == EXIT_WRONG
    d = json.loads(capsys.readouterr().out)
    assert d["status"] == "wrong" and d["quantity"] == "F_r" and d["edits"][0]["kind"] == "sign"
    assert run(["toy_car", "--list"]) == EXIT_RIGHT
    out = capsys.readouterr().out
    assert "F_r" in out and "equation:phi" in out


def test_answer_file_and_linearisation(tmp_path, capsys):
    f = tmp_path / "answer.txt"
    f.write_text("R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0\n"
                 "R*phi''*cos(theta) - 2*R*phi'*theta'*sin(theta) + g*sin(phi) = 0\n")
    assert run(["toy_car", "--answer-file", str(f)]) == EXIT_RIGHT
    assert run(["simple_pendulum", "--quantity", "linearised", "--about", "theta=0",
                "--answer", "a*theta'' + g*theta"]) == EXIT_RIGHT
    capsys.readouterr()


def test_usage_errors(tmp_path, capsys):
    assert run(["--answer", RIGHT]) == EXIT_USAGE
    assert "name a problem" in capsys.readouterr().err
    assert run(["simple_pendulum"]) == EXIT_USAGE
    assert "--answer" in capsys.readouterr().err
    assert run(["simple_pendulum", "--answer-file", str(tmp_path / "none.txt")]) == EXIT_USAGE
    assert "cannot read" in capsys.readouterr().err
    assert run(["toy_cra", "--answer", "x"]) == EXIT_USAGE
    assert "Did you mean 'toy_car'" in capsys.readouterr().out


# -- batches ------------------------------------------------------------------------------------
def test_batch_in_order_bad_rows_reported():
    # (mixes questions with and without a quantity: they must sort together)
    results = grade_batch(ROWS, workers=1, progress=False)
    assert [r["status"] for r in results] == STATUSES
    assert [r["id"] for r in results] == [r["id"] for r in ROWS]
    assert "no problem named 'no_such_problem'" in results[-2]["summary"]


def test_process_pool_gives_the_same_results(capsys):
    one = grade_batch(ROWS, workers=1, progress=False)
    two = grade_batch(ROWS, workers=2, progress=True, chunk=2)
    assert [r["status"] for r in two] == STATUSES
    strip = lambda rs: [{k: v for k, v in r.items() if k != "seconds"} for r in rs]  # noqa
    assert strip(one) == strip(two)
    assert "grading" in capsys.readouterr().err          # the progress bar


def test_dask_local_cluster():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster:
        results = grade_batch(ROWS, scheduler=cluster.scheduler_address, progress=False,
                              chunk=3)
    assert [r["status"] for r in results] == STATUSES


def test_unreachable_scheduler():
    with pytest.raises(BatchError, match="cannot reach the Dask scheduler"):
        grade_batch(ROWS[:1], scheduler="tcp://127.0.0.1:1", progress=False,
                    connect_timeout=1)


def test_csv_errors(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("student,answer\ns1,x\n")
    with pytest.raises(BatchError, match="missing id, question; found student, answer"):
        read_csv(bad)
    empty = tmp_path / "empty.csv"
    empty.write_text("id,question,answer\n")
    with pytest.raises(BatchError, match="no answers"):
        read_csv(empty)
    with pytest.raises(BatchError, match="no such file"):
        read_csv(tmp_path / "none.csv")


def test_report_groups_mistakes_by_the_wrong_term(tmp_path):
    results = grade_rows(ROWS)
    summary = summarise(results)
    toy = summary["toy_car:F_r"]
    assert (toy["answers"], toy["right"], toy["wrong"], toy["invalid"]) == (3, 1, 1, 1)
    # ben and cy made the same mistake (one under another spelling of the question)
    both = summary["toy_car"]["mistakes"][0]
    assert "wrong sign" in both[0] and "centripetal" in both[0]
    paths = write_report(results, tmp_path / "out")
    md = paths["markdown"].read_text()
    assert "1 of 3 right, 1 not graded." in md and "## By student" in md
    assert "| the term `-R*m*theta'^2` has the wrong sign" in md
    data = json.loads(paths["json"].read_text())
    assert len(data["results"]) == len(ROWS) and "simple_pendulum" in data["summary"]


def test_batch_command(tmp_path, capsys):
    path = tmp_path / "answers.csv"
    write_csv(path, ROWS)
    out = tmp_path / "report"
    assert run(["--batch", str(path), "--out", str(out), "--workers", "1",
                "--no-progress"]) == EXIT_RIGHT
    text = capsys.readouterr().out
    assert "simple_pendulum: 1/3 right" in text and "toy_car:F_r: 1/3 right, 1 not graded" in text
    assert (out / "report.md").exists() and (out / "results.json").exists()
    assert run(["simple_pendulum", "--batch", str(path)]) == EXIT_USAGE
    assert "drop NAME" in capsys.readouterr().err
