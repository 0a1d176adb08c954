"""Slow connections against the web page, loopback only: does one client stall the others?

Starts ``dualmech serve`` (its default deadlines and per-address limits) in a subprocess on a
free port of 127.0.0.1, then:

1. **baseline**: a normal request (``GET /api/problems``, a fresh connection each time) from
   127.0.0.2, ``--repeats`` times: the median and the worst latency;
2. **attack**: ``--slow`` connections from 127.0.0.1, each sending its request headers one
   byte every ``--trickle`` seconds and never finishing them (a slowloris), kept up for
   ``--seconds``; meanwhile the same normal request from 127.0.0.2 is timed again.

Prints how many slow connections the server held and refused, the normal request's latency
under attack (median, worst) and its ratio to the baseline; the target is a worst latency
under 1 s with every normal request answered 200.

    python bench/web_slow.py [--slow 1000] [--seconds 15] [--repeats 30]
"""
from __future__ import annotations

import argparse
import json
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time

from dualmech.web.transport import raise_open_files


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _normal(port: int) -> tuple[float, int]:
    start = time.perf_counter()
    with socket.create_connection(("127.0.0.1", port), timeout=10,
                                  source_address=("127.0.0.2", 0)) as s:
        s.sendall(b"GET /api/problems HTTP/1.1\r\nHost: b\r\nConnection: close\r\n\r\n")
        data = b""
        while chunk := s.recv(65536):
            data += chunk
    return time.perf_counter() - start, int(data[9:12] or 0)


def _timed(port: int, repeats: int) -> tuple[list[float], list[int]]:
    times, codes = [], []
    for _ in range(repeats):
        t, code = _normal(port)
        times.append(t)
        codes.append(code)
        time.sleep(0.05)
    return times, codes


class _Slowloris:
    """``n`` connections from 127.0.0.1 trickling headers; counts held and refused ones."""

    def __init__(self, port: int, n: int, trickle: float):
        self.port, self.n, self.trickle = port, n, trickle
        self.socks: list[socket.socket] = []
        self.refused = self.cut = 0
        self.stop = threading.Event()

    def open(self) -> None:
        for _ in range(self.n):
            try:
                s = socket.create_connection(("127.0.0.1", self.port), timeout=5,
                                             source_address=("127.0.0.1", 0))
                s.sendall(b"GET / HTTP/1.1\r\n")
                s.setblocking(False)
                self.socks.append(s)
            except OSError:
                self.refused += 1

    def run(self) -> None:
        while not self.stop.wait(self.trickle):
            alive = []
            for s in self.socks:
                try:
                    if s.recv(1, socket.MSG_PEEK) == b"":
                        raise ConnectionError
                except BlockingIOError:
                    pass
                except OSError:
                    self._closed(s)
                    continue
                try:
                    s.send(b"X")
                    alive.append(s)
                except OSError:
                    self._closed(s)
            self.socks = alive

    def _closed(self, s) -> None:
        try:
            reply = s.recv(64)
        except OSError:
            reply = b""
        if b" 503 " in reply[:16]:
            self.refused += 1
        else:
            self.cut += 1
        s.close()

    def close(self) -> None:
        self.stop.set()
        for s in self.socks:
            s.close()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--slow", type=int, default=1000)
    ap.add_argument("--seconds", type=float, default=15.0)
    ap.add_argument("--trickle", type=float, default=1.0)
    ap.add_argument("--repeats", type=int, default=30)
    args = ap.parse_args(argv)
    raise_open_files(4 * args.slow + 256)
    port = _free_port()
    data = tempfile.mkdtemp(prefix="dualmech-bench-")
    proc = subprocess.Popen([sys.executable, "-m", "dualmech", "serve", "--port", str(port),
                             "--problems", "simple_pendulum", "--data", data, "--workers", "1",
                             "--json"], stdout=subprocess.PIPE, text=True)
    try:
        json.loads(proc.stdout.readline())
        for _ in range(300):
            try:
                _normal(port)
                break
            except OSError:
                time.sleep(0.1)
        base, base_codes = _timed(port, args.repeats)
        attack = _Slowloris(port, args.slow, args.trickle)
        attack.open()
        worker = threading.Thread(target=attack.run, daemon=True)
        worker.start()
        end = time.monotonic() + args.seconds
        under, codes = [], []
        while time.monotonic() < end:
            t, c = _timed(port, 1)
            under += t
            codes += c
        still_open = len(attack.socks)
        attack.close()
        print(f"slow connections asked: {args.slow}; refused (503): {attack.refused}; cut by "
              f"the header deadline: {attack.cut}; still open after {args.seconds:.0f} s: "
              f"{still_open}")
        print(f"normal request, baseline : median {statistics.median(base) * 1e3:7.1f} ms, "
              f"worst {max(base) * 1e3:7.1f} ms ({len(base)} requests, "
              f"{sum(c != 200 for c in base_codes)} not 200)")
        print(f"normal request, attacked : median {statistics.median(under) * 1e3:7.1f} ms, "
              f"worst {max(under) * 1e3:7.1f} ms ({len(under)} requests, "
              f"{sum(c != 200 for c in codes)} not 200)")
        print(f"ratio attacked/baseline  : median {statistics.median(under) / statistics.median(base):.2f}x"
              f", worst {max(under) / max(base):.2f}x; target worst < 1 s: "
              f"{'met' if max(under) < 1 and all(c == 200 for c in codes) else 'MISSED'}")
    finally:
        proc.kill()
        proc.wait(10)
    return 0


if __name__ == "__main__":
    sys.exit(main())
