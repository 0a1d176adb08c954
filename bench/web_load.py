"""Load on the web page, loopback only: 50 concurrent clients x 20 answers (right, wrong, hostile).

Starts ``dualmech serve`` in a subprocess on a free port of 127.0.0.1, then runs ``--clients``
threads, each an HTTP client bound to its own loopback address (127.0.0.2, 127.0.0.3, ...,
so the per-client rate limit sees a class, not one client), each posting ``--answers``
answers to ``/api/grade`` in a fixed mix.  Prints the p50/p99 latency, the throughput and the
errors: a non-200 response, a failed request, or a verdict other than the expected one (0
expected).  The baseline, measured in the same run, is one client alone posting the same mix
one answer at a time; the ratio says what the class costs each student.  Every answer text is
made unique (trailing spaces; a different multiple angle for the too-costly ones), so the server's
cache of verdicts never answers for the grader.

    python bench/web_load.py [--clients 50] [--answers 20] [--workers N] [--one-address]

``--one-address`` runs a class behind one address (a school's NAT): the teacher makes an
assignment for ``--clients`` students, and every student posts their answers to it with their
own token, all from 127.0.0.1; the rate limit counts each student's token, so the target is
0 answers refused (no 429) and p99 under 1 s.

Every request goes to 127.0.0.0/8; the run is bounded in count and in time (``--timeout``).
"""
from __future__ import annotations

import argparse
import itertools
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time

import httpx

TOKEN = "web-load-bench-token"
# (problem, answer, quantity, expected status) -- verdicts from problems/simple_pendulum.py
# and problems/toy_car.py
MIX = [
    ("simple_pendulum", "a*theta'' + g*sin(theta) = 0", None, "right"),
    ("simple_pendulum", "a*theta'' - g*sin(theta) = 0", None, "wrong"),
    ("toy_car", "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0",
     None, "right"),
    ("toy_car", "R*theta'' - R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0",
     None, "wrong"),
    ("simple_pendulum", "M*(g*cos(theta) + a*theta'^2)", "T", "right"),
    ("simple_pendulum", "__import__('os').system('ls')", None, "invalid"),
    ("simple_pendulum", "9^9^9^9", None, "invalid"),
    ("toy_car", "x" * 5000, None, "invalid"),
    ("toy_car", "(theta + phi + theta' + phi' + R + g + m)^24 * (theta - phi + theta' - phi' "
     "+ R - g + m)^24 = 0", None, "wrong"),                    # heavy, but within bounds
    ("toy_car", "sin({n}*theta) = 0", None, "invalid"),   # too costly: the worker is replaced
    ("simple_pendulum", "a*theta'' + g*sin(theta) + <script>alert(1)</script>", None,
     "invalid"),
]


_UNIQUE = itertools.count(1)     # thread-safe in CPython (one C call)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _start(port: int, data: str, workers: int | None) -> subprocess.Popen:
    cmd = [sys.executable, "-m", "dualmech", "serve", "--port", str(port),
           "--data", data, "--problems", "simple_pendulum", "toy_car"]
    if workers:
        cmd += ["--workers", str(workers)]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env={**os.environ, "DUALMECH_TOKEN": TOKEN})
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise SystemExit(f"the server stopped: {proc.stderr.read().decode()[-2000:]}")
        try:
            if httpx.get(f"http://127.0.0.1:{port}/api/problems", timeout=2).status_code == 200:
                return proc
        except httpx.HTTPError:
            time.sleep(0.2)
    proc.kill()
    raise SystemExit("the server did not start within 120 s")


def _client(url: str, address: str, n: int, offset: int, out: list, deadline: float,
            mix: list) -> None:
    transport = httpx.HTTPTransport(local_address=address)
    with httpx.Client(transport=transport, timeout=120) as c:
        for i in range(n):
            if time.monotonic() > deadline:
                out.append((None, "time limit of the run reached"))
                return
            problem, answer, quantity, expected = mix[(offset + i) % len(mix)]
            # every text unique (a different costly answer, trailing spaces), so the
            # server's cache of verdicts never answers: each request is graded
            k = next(_UNIQUE)
            answer = answer.replace("{n}", str(1000 + k)) + " " * (k % 3000)
            t0 = time.perf_counter()
            try:
                r = c.post(f"{url}/api/grade", json={"problem": problem, "answer": answer,
                                                     "quantity": quantity})
            except httpx.HTTPError as exc:
                out.append((None, f"{type(exc).__name__}: {exc}"))
                continue
            dt = time.perf_counter() - t0
            if r.status_code != 200:
                out.append((dt, f"HTTP {r.status_code}: {r.text[:200]}"))
            elif r.json()["status"] != expected:
                out.append((dt, f"{answer[:40]!r}: {r.json()['status']}, expected {expected}"
                                f" ({r.json()['summary'][:120]})"))
            else:
                out.append((dt, None))


def _student(url: str, assignment: str, token: str, n: int, offset: int, out: list,
             deadline: float, mix: list) -> None:
    """One student of an assignment posting ``n`` answers with their token (question 0 is
    simple_pendulum's equation of motion, question 1 toy_car's), all from 127.0.0.1."""
    questions = {"simple_pendulum": 0, "toy_car": 1}
    # equations of motion only; an answer over the assignment's 4000 characters is refused
    # before grading (413), which is not what this run measures
    mine = [m for m in mix if m[2] is None and len(m[1]) <= 4000]
    with httpx.Client(timeout=120, headers={"Authorization": f"Bearer {token}"}) as c:
        for i in range(n):
            if time.monotonic() > deadline:
                out.append((None, "time limit of the run reached"))
                return
            problem, answer, _, expected = mine[(offset + i) % len(mine)]
            k = next(_UNIQUE)
            answer = answer.replace("{n}", str(1000 + k)) + " " * (k % 3000)
            t0 = time.perf_counter()
            try:
                r = c.post(f"{url}/api/assignments/{assignment}/answers",
                           json={"question": questions[problem], "answer": answer})
            except httpx.HTTPError as exc:
                out.append((None, f"{type(exc).__name__}: {exc}"))
                continue
            dt = time.perf_counter() - t0
            if r.status_code != 200:
                out.append((dt, f"HTTP {r.status_code}: {r.text[:200]}"))
            elif r.json()["status"] != expected:
                out.append((dt, f"{answer[:40]!r}: {r.json()['status']}, expected {expected}"))
            else:
                out.append((dt, None))


def _run_class(url: str, clients: int, answers: int, deadline: float,
               mix: list) -> tuple[list, float]:
    """A class of ``clients`` students behind one address, answering an assignment."""
    body = {"title": "load", "questions": [{"problem": "simple_pendulum", "quantity": None},
                                           {"problem": "toy_car", "quantity": None}],
            "students": [f"s{i}" for i in range(clients)], "per_student_numbers": False,
            "feedback": "full", "attempts": 100, "deadline": "2100-01-01T00:00:00+00:00"}
    r = httpx.post(f"{url}/api/assignments", json=body, timeout=60,
                   headers={"Authorization": f"Bearer {TOKEN}"})
    r.raise_for_status()
    made = r.json()
    tokens = [made["students"][f"s{i}"]["token"] for i in range(clients)]
    results: list = [[] for _ in range(clients)]
    threads = [threading.Thread(target=_student, args=(url, made["id"], tokens[i], answers,
                                                       i, results[i], deadline, mix))
               for i in range(clients)]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return [x for r in results for x in r], time.perf_counter() - t0


def _run(url: str, clients: int, answers: int, deadline: float,
         mix: list, block: int = 0) -> tuple[list, float]:
    """``clients`` threads on the loopback addresses ``127.0.<block>.2``, ``.3``, ...: each
    run of the script (warm-up, baseline, load) on its own block, so that the per-client rate
    limit counts each simulated student once, not the warm-up and the baseline as well."""
    results: list = [[] for _ in range(clients)]
    threads = [threading.Thread(target=_client, args=(url, f"127.0.{block}.{2 + i % 250}",
                                                      answers,
                                                      i, results[i], deadline, mix))
               for i in range(clients)]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return [x for r in results for x in r], time.perf_counter() - t0


def _pct(values: list, q: float) -> float:
    values = sorted(values)
    return values[min(len(values) - 1, int(round(q * (len(values) - 1))))]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--clients", type=int, default=50)
    ap.add_argument("--answers", type=int, default=20)
    ap.add_argument("--workers", type=int, default=None, help="grading processes")
    ap.add_argument("--timeout", type=float, default=600, help="bound on the whole run (s)")
    ap.add_argument("--no-costly", action="store_true",
                    help="leave out the too-costly answers (the pool replaces its worker after "
                         "each, and the new one loads the problem again)")
    ap.add_argument("--one-address", action="store_true",
                    help="a class behind one address answering an assignment, each student "
                         "with their own token")
    args = ap.parse_args(argv)
    mix = [m for m in MIX if not (args.no_costly and "{n}" in m[1])]
    port = _free_port()
    url = f"http://127.0.0.1:{port}"
    with tempfile.TemporaryDirectory() as data:
        proc = _start(port, data, args.workers)
        try:
            deadline = time.monotonic() + args.timeout
            warm, _ = _run(url, 1, len(mix), deadline, mix, 1)       # loads both problems
            base, _ = _run(url, 1, len(mix), deadline, mix, 2)       # one client alone
            if args.one_address:
                load, wall = _run_class(url, args.clients, args.answers, deadline, mix)
            else:
                load, wall = _run(url, args.clients, args.answers, deadline, mix)
        finally:
            proc.terminate()
            try:
                proc.wait(30)
            except subprocess.TimeoutExpired:
                proc.kill()
    errors = [e for _, e in warm + base + load if e]
    lat = [dt for dt, e in load if dt is not None]
    blat = [dt for dt, e in base if dt is not None]
    refused = sum(1 for _, e in load if e and e.startswith("HTTP 429"))
    print(f"web load on loopback: {args.clients} "
          f"{'students of one assignment, all from 127.0.0.1,' if args.one_address else 'clients'}"
          f" x {args.answers} answers "
          f"({len(load)} requests), {os.cpu_count()} cores, mix of {len(mix)} answers "
          f"(right, wrong, hostile{'' if args.no_costly else ', too costly'})")
    print(f"  baseline, one client alone: p50 {_pct(blat, .5) * 1e3:7.1f} ms   "
          f"p99 {_pct(blat, .99) * 1e3:7.1f} ms")
    print(f"  under load:                 p50 {_pct(lat, .5) * 1e3:7.1f} ms   "
          f"p99 {_pct(lat, .99) * 1e3:7.1f} ms   ({_pct(lat, .5) / _pct(blat, .5):.1f}x and "
          f"{_pct(lat, .99) / _pct(blat, .99):.1f}x the baseline)")
    print(f"  throughput {len(lat) / wall:.1f} answers/s over {wall:.1f} s; "
          f"mean {statistics.mean(lat) * 1e3:.1f} ms")
    print(f"  errors: {len(errors)} (of which refused by the rate limit, 429: {refused}); "
          f"target p99 < 1 s, 0 errors: "
          f"{'met' if not errors and _pct(lat, .99) < 1 else 'MISSED'}")
    for e in sorted(set(errors))[:10]:
        print(f"    {errors.count(e)} x {e}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
