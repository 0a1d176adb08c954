"""Grading contexts kept on disk (:mod:`dualmech.grade.stored_contexts`): the same grades, never stale,
never a way to run code.

Each test points ``DUALMECH_CACHE_DIR`` at a fresh directory.  The reference for "the same
grades" is a grader built from scratch in the same process: a context read back from disk
must grade every answer of :mod:`dualmech.grade.generate` (right forms and classic mistakes)
exactly as the context it was written from, feedback, state and method included.
"""
from __future__ import annotations

import hashlib
import os
import pickle
import subprocess
import sys
from dataclasses import replace

import pytest
import sympy as sp

from dualmech.grade import stored_contexts as stored
from dualmech.grade.api import Grader
from dualmech.grade.batch import warm_targets
from dualmech.grade.generate import correct_answers, wrong_answers
from dualmech.grade.parser import LIMITS
from dualmech.problems import declarations, get

from _catalogue_expected import graded_params

#: the two graders are compared answer by answer, not timed: a roomy ceiling, so a stall of a
#: loaded machine (a first wrong answer takes ~1 s of the 2 s default) is not read as "too
#: costly" by one of them
ROOMY = replace(LIMITS, seconds=60.0)


@pytest.fixture
def cache(tmp_path, monkeypatch):
    folder = tmp_path / "cache"
    monkeypatch.setenv("DUALMECH_CACHE_DIR", str(folder))
    return folder


def _fresh(name: str) -> Grader:
    """A grader built from the models, as a first run builds it (no stored context)."""
    g = Grader.__new__(Grader)
    Grader.__init__(g, get(name), limits=ROOMY)
    g._named = name
    return g


def _warm(g: Grader) -> None:
    ctx = g.context
    try:
        warm_targets(ctx)
        g.grade("0")
    except Exception:   # noqa: BLE001 - as the sandbox warms: what fails is built later
        pass


def _answers(ctx, most: int = 6) -> list:
    right = [s for s in correct_answers(ctx)][:most // 2]
    wrong = [s for s in wrong_answers(ctx)][:most - len(right)]
    return right + wrong


def _same(a: Grader, b: Grader, samples) -> None:
    for s in samples:
        x, y = a.grade(s.text, s.quantity).to_dict(), b.grade(s.text, s.quantity).to_dict()
        x.pop("seconds", None)
        y.pop("seconds", None)
        assert x == y, (s.text, s.quantity)


@pytest.mark.slow
@pytest.mark.parametrize("name", graded_params([d.name for d in declarations()]))
def test_a_stored_context_grades_every_answer_as_the_one_it_was_written_from(name, cache):
    fresh = _fresh(name)
    _warm(fresh)
    assert stored.save(fresh.context), "a catalogue problem's warmed context is kept"
    assert not stored.save(fresh.context), "nothing new was built: not written again"
    loaded = Grader(name, limits=ROOMY)
    assert loaded._ctx is not None and loaded.context is not fresh.context
    assert loaded.problem is loaded.context.problem
    # every object read back is the real class's (a stand-in of the reader, left behind in
    # place of a class, would not pickle by reference)
    pickle.dumps(loaded.context, protocol=5)
    _same(fresh, loaded, _answers(fresh.context))


def test_the_grade_command_writes_the_context_and_reads_it_back(cache):
    argv = [sys.executable, "-m", "dualmech", "grade", "simple_pendulum", "--json",
            "--answer", "a*theta'' - g*sin(theta) = 0"]
    env = dict(os.environ, DUALMECH_CACHE_DIR=str(cache))
    first = subprocess.run(argv, capture_output=True, text=True, env=env, timeout=120)
    files = sorted(p.name for p in cache.glob("context-simple_pendulum-*.pickle"))
    assert len(files) == 1
    second = subprocess.run(argv, capture_output=True, text=True, env=env, timeout=120)
    assert first.returncode == second.returncode == 1   # wrong: the sign of gravity
    assert first.stdout.replace('"seconds"', "") and \
        _without_seconds(first.stdout) == _without_seconds(second.stdout)
    assert "-g*sin(theta)" in first.stdout


def _without_seconds(text: str) -> str:
    import json
    data = json.loads(text)
    data.pop("seconds", None)
    return json.dumps(data, sort_keys=True)


def test_only_a_problem_built_from_its_bare_name_is_kept(cache):
    g = Grader(get("n_link_pendulum", n=3))   # another size under the same name
    _warm(g)
    assert g.context.named is None and not stored.save(g.context)
    assert stored.load("n_link_pendulum") is None


def test_a_change_of_code_or_versions_finds_no_file(cache, monkeypatch):
    g = _fresh("simple_pendulum")
    _warm(g)
    assert stored.save(g.context)
    assert stored.load("simple_pendulum") is not None
    monkeypatch.setattr(stored, "_STAMP", ["another build of dualmech"])
    assert stored.load("simple_pendulum") is None
    g = _fresh("simple_pendulum")
    _warm(g)
    assert stored.save(g.context)   # the newer build's file replaces the older one's
    assert len(list(cache.glob("context-simple_pendulum-*.pickle"))) == 1


def test_caching_off_keeps_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("DUALMECH_CACHE_DIR", "off")
    g = _fresh("simple_pendulum")
    _warm(g)
    assert not stored.save(g.context)
    assert stored.load("simple_pendulum") is None


# -- forged and damaged files -------------------------------------------------------------------
def _forge(cache, name: str, payload: bytes, digest: bytes | None = None) -> None:
    folder, file = stored._where(name, 0)
    digest = digest if digest is not None else hashlib.sha256(payload).hexdigest().encode()
    folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    (folder / file).write_bytes(stored._MAGIC + digest + b"\n" + payload)
    os.chmod(folder / file, 0o600)


class _System:
    """Unpickles as ``os.system(...)``: what a forged file would try."""

    def __init__(self, marker):
        self.marker = marker

    def __reduce__(self):
        return (os.system, (f"touch {self.marker}",))


class _TextSine:
    """Unpickles as ``sin("<text>")``: sympy would parse (evaluate) the text."""

    def __init__(self, marker):
        self.marker = marker

    def __reduce__(self):
        return (sp.sin, (f"__import__('os').system('touch {self.marker}')",))


@pytest.mark.parametrize("forgery", [_System, _TextSine])
def test_a_forged_file_runs_no_code_and_is_ignored(forgery, cache, tmp_path):
    marker = tmp_path / "ran"
    _forge(cache, "simple_pendulum", pickle.dumps(forgery(marker), protocol=5))
    assert stored.load("simple_pendulum") is None
    assert not marker.exists()
    g = Grader("simple_pendulum")   # built from the models instead
    assert g.grade("a*theta'' + g*sin(theta) = 0").status == "right"
    assert not marker.exists()


def test_text_inside_a_stored_expression_is_refused(cache, tmp_path):
    marker = tmp_path / "ran"
    payload = pickle.dumps((sp.Symbol("x"), _TextSine(marker)), protocol=5)
    _forge(cache, "simple_pendulum", payload)
    assert stored.load("simple_pendulum") is None and not marker.exists()
    with pytest.raises(pickle.UnpicklingError, match="text"):
        stored._Reader(pickle.dumps(_TextSine(marker), protocol=5)).load()
    assert not marker.exists()


def test_a_damaged_or_foreign_file_is_ignored(cache):
    g = _fresh("simple_pendulum")
    _warm(g)
    assert stored.save(g.context)
    folder, file = stored._where("simple_pendulum", 0)
    data = (folder / file).read_bytes()
    (folder / file).write_bytes(data[:-10])                       # truncated: digest fails
    assert stored.load("simple_pendulum") is None
    _forge(cache, "simple_pendulum", pickle.dumps((1, 2), protocol=5))   # not a context
    assert stored.load("simple_pendulum") is None
    _forge(cache, "simple_pendulum", b"x", digest=b"0" * 64)      # wrong digest
    assert stored.load("simple_pendulum") is None
    (folder / file).write_bytes(data)
    os.chmod(folder / file, 0o666)                                # others may write it
    assert stored.load("simple_pendulum") is None
    os.chmod(folder / file, 0o600)
    assert stored.load("simple_pendulum") is not None


def test_a_stored_context_spares_the_command_symengine_and_numpy(cache):
    """With the context stored, the command's answer needs neither symengine nor numpy
    (``dualmech.startup.defer``); without it, they load when the models are derived."""
    script = ("import sys\nfrom dualmech.cli.main import command\n"
              "sys.argv = ['dualmech', 'grade', 'simple_pendulum', '--answer', "
              "\"a*theta'' + g*sin(theta) = 0\"]\n"
              "code = command()\n"
              "print(code, 'numpy' in sys.modules, "
              "'symengine.lib.symengine_wrapper' in sys.modules)\n")
    env = dict(os.environ, DUALMECH_CACHE_DIR=str(cache))
    runs = [subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                           env=env, timeout=120) for _ in range(2)]
    first, second = (r.stdout.strip().splitlines()[-1] for r in runs)
    assert first == "0 True True"      # right; the models were derived (symengine loaded)
    assert second == "0 False False"   # right; read from the stored context
    assert "RIGHT" in runs[1].stdout


def test_an_oversized_file_is_not_read_past_the_bound(cache):
    """A file past the size bound (a context is 20-300 kB) is cut at the bound, fails its
    digest and is ignored: bounded time and memory, whatever the file's size."""
    import time
    import tracemalloc
    folder, file = stored._where("simple_pendulum", 0)
    folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    payload = pickle.dumps(b"x" * (stored._MOST + 1024), protocol=5)
    digest = hashlib.sha256(payload).hexdigest().encode()
    (folder / file).write_bytes(stored._MAGIC + digest + b"\n" + payload)
    os.chmod(folder / file, 0o600)
    del payload
    tracemalloc.start()
    t0 = time.process_time()
    try:
        assert stored.load("simple_pendulum") is None
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 1.5 * stored._MOST          # the bound read and hashed, never copied
    assert time.process_time() - t0 < 5.0     # reading and hashing 32 MB
