"""Cold start of one ``dualmech grade`` call: a fresh process, timed end to end.

Runs ``python -m dualmech grade toy_car --quantity equation --answer "R*theta'' = 0"`` (or the
command given after ``--``) as a new process ``--repeat`` times (default 7), and, interleaved
with it in the same run, ``python -c "import sympy"`` -- the floor of any sympy-based command.
Prints the median wall and user CPU time of each and their ratio, so the figure means the
same on a fast machine and a slow one.  With ``--all`` it also times ``dualmech --help`` and
``dualmech list`` (commands that need no sympy at all).

User time is the process's own plus that of the children it waited for (the grader forks a
worker per answer: that is counted).  One untimed run of each command comes first (it warms
the file cache, the byte-code, and the user's cache directory: the parser's tables and the
problem's prepared grading context, :mod:`dualmech.grade.stored_contexts`).  The row "... (first
call)" runs the same command with an empty cache directory each time: what the first call
for a problem costs after an install or a change of code.  The commands run with byte-code
caching on whatever ``PYTHONDONTWRITEBYTECODE`` says, as an installed package has it (pip
compiles it); ``--no-bytecode`` keeps the variable as it is.  A script, not a test::

    python bench/grade_cold_start.py [--repeat N] [--all] [-- grade NAME --answer TEXT ...]
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

DEFAULT = ["grade", "toy_car", "--quantity", "equation", "--answer", "R*theta'' = 0"]


def run_once(argv: list[str], env: dict) -> tuple[float, float, int]:
    """Wall seconds, user CPU seconds (with waited-for children) and exit status of one run."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            env=env)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    return wall, usage.ru_utime, proc.returncode


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=7, help="runs of each command (default 7)")
    parser.add_argument("--all", action="store_true",
                        help="also time `dualmech --help` and `dualmech list`")
    parser.add_argument("--no-bytecode", action="store_true",
                        help="keep PYTHONDONTWRITEBYTECODE as set (default: byte-code cached)")
    parser.add_argument("command", nargs="*", help="dualmech arguments (after --); default: "
                        + " ".join(repr(a) if " " in a else a for a in DEFAULT))
    args = parser.parse_args(argv)
    py = sys.executable
    env = dict(os.environ)
    if not args.no_bytecode:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
    commands = {"import sympy": [py, "-c", "import sympy"],
                "dualmech " + (args.command or DEFAULT)[0]: [py, "-m", "dualmech",
                                                           *(args.command or DEFAULT)]}
    if args.all:
        commands["dualmech --help"] = [py, "-m", "dualmech", "--help"]
        commands["dualmech list"] = [py, "-m", "dualmech", "list"]
    first = "dualmech " + (args.command or DEFAULT)[0] + " (first call)"
    commands[first] = commands["dualmech " + (args.command or DEFAULT)[0]]
    times: dict[str, list[tuple[float, float]]] = {k: [] for k in commands}
    statuses = {}
    with tempfile.TemporaryDirectory() as scratch:
        def env_of(name: str, i: int) -> dict:
            if name != first:
                return env
            return dict(env, DUALMECH_CACHE_DIR=os.path.join(scratch, f"empty{i}"))
        for name, cmd in commands.items():   # untimed warm-up
            statuses[name] = run_once(cmd, env_of(name, -1))[2]
        for i in range(args.repeat):          # interleaved: a slow spell falls on every command
            for name, cmd in commands.items():
                wall, user, _ = run_once(cmd, env_of(name, i))
                times[name].append((wall, user))
    floor_wall = statistics.median(w for w, _ in times["import sympy"])
    floor_user = statistics.median(u for _, u in times["import sympy"])
    print(f"{'command':30s} {'wall [s]':>9s} {'user [s]':>9s} {'wall/floor':>11s} "
          f"{'user/floor':>11s}  (medians of {args.repeat}; exit status)")
    for name, rows in times.items():
        wall = statistics.median(w for w, _ in rows)
        user = statistics.median(u for _, u in rows)
        print(f"{name:30s} {wall:9.3f} {user:9.3f} {wall / floor_wall:11.2f} "
              f"{user / floor_user:11.2f}  ({statuses[name]})")
    print(f"load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
