"""Answers graded per second, one answer's latency, and the batch's scaling from one core to two.

A mixed batch (default 1,200 answers) is written from the verified equations of 2-DOF problems
of the catalogue by :mod:`dualmech.grade.generate` -- correct forms and classic mistakes, about
half each -- plus a few answers that cannot be graded (unknown names, hostile text).  The
problems are loaded first (models, sampled points, feedback targets: the per-problem work the
grader caches); then the batch is graded on one core (in this process) and on two (a process
pool whose forked workers share the loaded problems), and the script prints answers per second
for both and their ratio, in wall time and in CPU time (on a shared machine the wall time
measures the load as much as the grader).  It also prints the median CPU time of one answer
per problem, right and wrong, which the issue asks to be well under 10 ms for a 2-DOF problem.

Then: answers per second through the bounded sandbox (:class:`dualmech.grade.sandbox.GradingPool`,
one warm worker), and the wall and CPU time of one ``dualmech grade`` call beside that of
``python -c "import sympy"`` (the floor of any sympy-based command).

A script, not a test: ``python bench/grade_throughput.py [--answers N] [--problems a,b,...]``.
"""
from __future__ import annotations

import argparse
import os
import statistics
import time

from dualmech import Grader
from dualmech.grade.batch import grade_batch, warm
from dualmech.grade.generate import correct_answers, wrong_answers

PROBLEMS = ("toy_car", "cart_pendulum", "pendulum_on_mass", "falling_container",
            "block_on_wedge", "coupled_pendulums")
INVALID = ["R*thta'' + g = 0", "__import__('os').system('ls')", "9^9^9^9", "(theta" * 3]


def answers_for(names, total: int) -> list[dict]:
    """``total`` rows cycling through every problem's right and wrong answers."""
    pool = []
    for name in names:
        ctx = Grader.of(name).context
        for s in correct_answers(ctx) + wrong_answers(ctx):
            pool.append({"question": f"{name}:{s.quantity}" if s.quantity else name,
                         "answer": s.text, "expect": "right" if s.right else "wrong"})
        for text in INVALID:
            pool.append({"question": name, "answer": text, "expect": "invalid"})
    rows = []
    i = 0
    while len(rows) < total:
        row = dict(pool[i % len(pool)])
        row["id"] = f"s{i}"
        rows.append(row)
        i += 1
    return rows


def latency(names) -> None:
    print(f"\n{'problem':20s} {'right [ms]':>11s} {'wrong [ms]':>11s}   "
          "(median CPU time of one answer)")
    for name in names:
        g = Grader.of(name)
        ctx = g.context
        times = {"right": [], "wrong": []}
        for s in (correct_answers(ctx) + wrong_answers(ctx)) * 3:
            t0 = time.process_time()
            g.grade(s.text, s.quantity)
            times["right" if s.right else "wrong"].append(time.process_time() - t0)
        print(f"{name:20s} {1e3 * statistics.median(times['right']):11.2f} "
              f"{1e3 * statistics.median(times['wrong']):11.2f}")


def sandbox(rows) -> None:
    """Answers per second through the bounded sandbox (one warm worker, one core)."""
    from dualmech.grade.sandbox import GradingPool
    with GradingPool(1) as pool:
        for name in {r["question"].split(":")[0] for r in rows}:
            pool.grade(name, "0")                      # load the problem in the worker
        batch = [(r["question"].partition(":")[0], r["answer"],
                  r["question"].partition(":")[2] or None) for r in rows]
        for b in batch[:20]:                           # first-use caches in the worker
            pool.grade(*b)
        t0, c0 = time.perf_counter(), time.process_time()
        futures = [pool.submit(*b) for b in batch]
        statuses = [f.result().status for f in futures]
        dt = time.perf_counter() - t0
    agree = sum(s == r["expect"] for s, r in zip(statuses, rows))
    print(f"sandbox, 1 warm worker: {len(rows) / dt:7.1f} answers/s wall "
          f"(target >= 300 per core; {agree}/{len(rows)} verdicts as expected; parent CPU "
          f"{time.process_time() - c0:.2f} s)")


def cli_latency(name: str, answer: str, repeats: int = 3) -> None:
    """Wall and CPU time of one ``dualmech grade`` call, against ``python -c 'import sympy'``
    measured the same way (the floor any sympy-based CLI pays)."""
    import subprocess
    import sys

    def run(args):
        walls, cpus = [], []
        for _ in range(repeats):
            t0, c0 = time.perf_counter(), _children_cpu()
            subprocess.run([sys.executable, *args], check=False, capture_output=True)
            walls.append(time.perf_counter() - t0)
            cpus.append(_children_cpu() - c0)
        return statistics.median(walls), statistics.median(cpus)
    w, c = run(["-m", "dualmech", "grade", name, "--answer", answer])
    w0, c0 = run(["-c", "import sympy"])
    print(f"dualmech grade {name} (one answer): {w:.2f} s wall, {c:.2f} s CPU "
          f"(target < 0.5 s wall); `import sympy` alone: {w0:.2f} s wall, {c0:.2f} s CPU; "
          f"ratio x{w / w0:.1f} wall")


def _children_cpu() -> float:
    t = os.times()
    return t.children_user + t.children_system


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--answers", type=int, default=1200, help="batch size (>= 1000)")
    parser.add_argument("--problems", default=",".join(PROBLEMS),
                        help="comma-separated catalogue names")
    args = parser.parse_args()
    names = [n.strip() for n in args.problems.split(",") if n.strip()]
    t0 = time.perf_counter()
    warm(names)
    rows = answers_for(names, args.answers)
    print(f"loaded {len(names)} problems in {time.perf_counter() - t0:.1f} s; "
          f"{len(rows)} answers")
    grade_batch(rows[:len(names) * 4], workers=1, progress=False)   # first-use caches
    rates = {}
    for workers in (1, 2):
        t0 = time.perf_counter()
        results = grade_batch(rows, workers=workers, progress=False)
        dt = time.perf_counter() - t0
        rates[workers] = len(rows) / dt
        agree = sum(r["status"] == row["expect"] for r, row in zip(results, rows))
        print(f"{workers} core{'s' if workers > 1 else ' '}: {dt:6.2f} s wall, "
              f"{rates[workers]:7.1f} answers/s, sandboxed, problems loaded in fresh workers "
              f"({agree}/{len(rows)} verdicts as expected)")
    graders = {}
    c0 = time.process_time()
    for row in rows:          # warm, in this process: the grader's own CPU cost per answer
        name, _, quantity = row["question"].partition(":")
        g = graders.get(name) or graders.setdefault(name, Grader.of(name))
        g.grade(row["answer"], quantity or None)
    cpu = time.process_time() - c0
    print(f"warm, in-process: {len(rows) / cpu:7.1f} answers per CPU-second "
          "(target >= 300 per core)")
    print(f"scaling 1 -> 2 cores (wall): x{rates[2] / rates[1]:.2f}   "
          f"(target: >= 300 answers/s per core warm; load average now "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores)")
    latency(names)
    sandbox(rows[:600])
    cli_latency("toy_car", "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0")


def _cpu() -> float:
    """CPU seconds of this process and of its finished children (the pool's workers)."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


if __name__ == "__main__":
    main()
