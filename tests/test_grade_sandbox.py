"""The bounded-grading contract: every answer graded under a wall-clock and memory ceiling.

Hostile answers really run long here: the pool is given parser limits loose enough that the
cost model lets ``phi^3000000`` through, whose exact value at a sampled point (``phi`` a
61-bit rational) has about 180 million bits -- minutes of big-integer squaring.  The ceiling
must stop it, say ``too costly to grade``, and the next answer in the same pool must still be
graded right (a fresh worker replaces the killed one).
"""
from __future__ import annotations

import concurrent.futures
import json
import os
import subprocess
import sysconfig
import time
from pathlib import Path

import pytest

from dualmech.grade.parser import LIMITS, Limits
from dualmech.grade.result import Grade
from dualmech.grade.sandbox import GradingPool, _grade_here, grade_bounded

LOOSE = Limits(exponent=10 ** 9, degree=10 ** 12)
RIGHT = "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0"
SLOW = "theta''*phi^3000000 = 0"


@pytest.fixture(scope="module")
def pool():
    with GradingPool(1, seconds=1.0, memory_mb=256, limits=LOOSE) as p:
        assert p.grade("toy_car", RIGHT).status == "right"      # loaded, warm
        yield p


def test_a_long_answer_is_stopped_and_the_pool_goes_on(pool):
    t0 = time.monotonic()
    g = pool.grade("toy_car", SLOW)
    stopped = time.monotonic() - t0
    assert isinstance(g, Grade) and g.status == "invalid"
    assert g.summary.startswith("too costly to grade: `phi^3000000`")
    # the ceiling is 1 s; loading is not counted, so the kill comes well before the minutes
    # the computation would take (a generous margin for a loaded test machine)
    assert stopped < 30
    after = pool.grade("toy_car", RIGHT)
    assert after.status == "right", after.summary
    assert pool.grade("toy_car", "R*theta'' = 0").status == "wrong"


def test_submit_is_thread_safe_and_futures_resolve_to_grades(pool):
    answers = [RIGHT, "R*theta'' = 0", "thta'' = 0", SLOW, RIGHT]
    with concurrent.futures.ThreadPoolExecutor(4) as ex:
        futures = list(ex.map(lambda a: pool.submit("toy_car", a), answers))
    got = [f.result().status for f in futures]
    assert got == ["right", "wrong", "invalid", "invalid", "right"]


def test_unknown_problem_is_a_grade_not_an_exception(pool):
    g = pool.grade("no_such_problem", "x = 0")
    assert g.status == "invalid" and "no_such_problem" in g.summary


class _Hog:
    """A grader whose grading allocates far more than the ceiling."""

    def grade(self, answer, quantity, about):
        blocks = [bytearray(64 * 2 ** 20) for _ in range(64)]   # 4 GB
        return Grade("p", "q", "", answer, "right", f"{len(blocks)}")


def test_memory_ceiling_stops_an_allocation():
    g, healthy = _grade_here(_Hog(), "p", "x", None, None, 256)
    assert not healthy                  # the worker that hit the ceiling is retired
    assert g.status == "invalid" and g.summary.startswith("too costly to grade")
    assert "256 MB" in g.summary
    big = bytearray(300 * 2 ** 20)      # the ceiling was lifted again afterwards
    assert len(big) == 300 * 2 ** 20


def test_grade_bounded_one_answer():
    assert grade_bounded("toy_car", RIGHT).status == "right"
    g = grade_bounded("toy_car", "sin(1000*theta) = 0")
    assert g.status == "invalid" and g.summary.startswith("too costly to grade: "
                                                          "`sin(1000*theta)`")
    assert LIMITS.degree < 4000


@pytest.mark.slow
def test_workers_ignore_a_dualmech_folder_in_the_current_directory(tmp_path):
    # regression: the forkserver imported its preloaded modules with the current directory
    # first on sys.path, so a dualmech/ folder there (a source tree, with a plain install)
    # made every answer of `dualmech grade --batch` "invalid: cannot import name ...".  The
    # command is run as installed (its script: `python -m` would itself put the current
    # directory on the path) from a directory holding an empty dualmech package.
    script = Path(sysconfig.get_path("scripts")) / "dualmech"
    assert script.exists(), f"the installed command: {script}"
    (tmp_path / "dualmech").mkdir()
    (tmp_path / "dualmech" / "__init__.py").write_text("")
    (tmp_path / "answers.csv").write_text(
        "id,question,answer\n"
        "s1,simple_pendulum,a*theta'' + g*sin(theta) = 0\n"
        "s2,simple_pendulum,a*theta'' - g*sin(theta) = 0\n")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONSAFEPATH", "PYTHONPATH")}
    run = subprocess.run([str(script), "grade", "--batch", "answers.csv", "--out", "out",
                          "--workers", "1", "--no-progress"], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    assert "simple_pendulum: 1/2 right" in run.stdout, run.stdout + run.stderr
    results = json.loads((tmp_path / "out" / "results.json").read_text())["results"]
    assert [r["status"] for r in results] == ["right", "wrong"]
