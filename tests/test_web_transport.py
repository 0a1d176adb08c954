"""The served page cannot be stalled, crowded out or fooled about who is asking.

A real ``dualmech serve`` runs in a subprocess on a free loopback port with short deadlines;
the tests speak raw HTTP over sockets, the way a slow or hostile client does:

* a request whose headers (or body) trickle in is answered ``408`` and closed at its deadline;
* one address holding its whole allowance of connections is refused more (``503`` at once),
  while a request from another address is served -- the slow ones still open meanwhile;
* ``X-Forwarded-For`` from a client that is not a configured proxy changes nothing: the rate
  limit still counts that client;
* the data directory is private (0700) and so are the files in it (0600).

Every socket has a timeout and the server is killed at the end, so a failure cannot hang.
"""
from __future__ import annotations

import json
import os
import socket
import stat
import subprocess
import sys
import time

import pytest

pytest.importorskip("uvicorn")
pytest.importorskip("starlette")

HEADER_S, BODY_S, PER_CLIENT = 1.5, 1.5, 12


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    data = tmp_path_factory.mktemp("served") / "data"
    port = _free_port()
    proc = subprocess.Popen(
        [sys.executable, "-m", "dualmech", "serve", "--port", str(port), "--problems",
         "simple_pendulum", "--data", str(data), "--workers", "1", "--json",
         "--header-timeout", str(HEADER_S), "--body-timeout", str(BODY_S),
         "--connections-per-client", str(PER_CLIENT)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        info = json.loads(proc.stdout.readline())
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            try:
                if _request(port, "GET /api/problems HTTP/1.1\r\nHost: t\r\n"
                                  "Connection: close\r\n\r\n").startswith(b"HTTP/1.1 200"):
                    break
            except OSError:
                time.sleep(0.2)
        else:
            pytest.fail("the server did not answer within 60 s")
        yield {"port": port, "data": data, "info": info}
    finally:
        proc.kill()
        proc.wait(10)


def _connect(port: int, source: str = "127.0.0.1") -> socket.socket:
    s = socket.socket()
    s.settimeout(10)
    s.bind((source, 0))
    s.connect(("127.0.0.1", port))
    return s


def _read_all(s: socket.socket) -> bytes:
    chunks = []
    while True:
        try:
            chunk = s.recv(65536)
        except (ConnectionResetError, socket.timeout):
            break
        if not chunk:
            break
        chunks.append(chunk)
    return b"".join(chunks)


def _request(port: int, raw: str, source: str = "127.0.0.1") -> bytes:
    with _connect(port, source) as s:
        s.sendall(raw.encode())
        return _read_all(s)


def test_headers_that_trickle_in_are_cut_at_their_deadline(server):
    with _connect(server["port"]) as s:
        start = time.monotonic()
        s.sendall(b"GET /api/problems HTTP/1.1\r\nHost: t\r\n")   # never finished
        reply = _read_all(s)
        waited = time.monotonic() - start
    assert reply.startswith(b"HTTP/1.1 408"), reply[:80]
    assert HEADER_S * 0.8 < waited < HEADER_S + 5, waited


def test_a_body_that_trickles_in_is_cut_at_its_deadline(server):
    with _connect(server["port"]) as s:
        s.sendall(b"POST /api/validate HTTP/1.1\r\nHost: t\r\nContent-Type: application/json"
                  b"\r\nContent-Length: 200\r\n\r\n{\"problem\": ")
        start = time.monotonic()
        reply = _read_all(s)
        waited = time.monotonic() - start
    assert reply == b"" or reply.startswith(b"HTTP/1.1 408"), reply[:80]
    assert waited < BODY_S + 5, waited


def test_one_address_cannot_take_the_connections_of_the_others(server):
    port = server["port"]
    held = [_connect(port) for _ in range(PER_CLIENT)]
    try:
        for s in held:
            s.sendall(b"GET / HTTP/1.1\r\n")                     # headers never finished
        extra = _request(port, "GET /api/problems HTTP/1.1\r\nHost: t\r\n\r\n")
        assert extra.startswith(b"HTTP/1.1 503"), extra[:80]
        other = _request(port, "GET /api/problems HTTP/1.1\r\nHost: t\r\nConnection: close"
                               "\r\n\r\n", source="127.0.0.2")
        assert other.startswith(b"HTTP/1.1 200"), other[:80]
        assert b"simple_pendulum" in other
        # the slow connections were still open while the other address was served
        held[0].setblocking(False)
        with pytest.raises(BlockingIOError):
            held[0].recv(1)
    finally:
        for s in held:
            s.close()


def test_forwarded_for_from_an_untrusted_client_does_not_reset_its_limit(server):
    """The validate limit is a burst of 20: a client naming a new address in each request's
    X-Forwarded-For is still one client, refused (429) once its burst is spent."""
    body = json.dumps({"problem": "simple_pendulum", "answer": "a*theta'' = 0"})
    statuses = []
    for i in range(30):
        raw = (f"POST /api/validate HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
               f"X-Forwarded-For: 10.9.{i}.1\r\nContent-Length: {len(body)}\r\n"
               f"Connection: close\r\n\r\n{body}")
        statuses.append(int(_request(server["port"], raw)[9:12]))
    assert set(statuses) <= {200, 429}, statuses
    assert statuses[:20] == [200] * 20 and 429 in statuses[20:], statuses


def test_the_data_is_private(server):
    data = server["data"]
    assert stat.S_IMODE(os.stat(data).st_mode) == 0o700
    files = [p for p in data.rglob("*") if p.is_file()]
    assert files, "the server wrote nothing into its data directory"
    assert {stat.S_IMODE(os.stat(p).st_mode) for p in files} == {0o600}
