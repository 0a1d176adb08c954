"""The answer grammar's LALR tables kept between runs: same parses, and never a trusted file
that is not the user's own.

Each test points ``DUALMECH_CACHE_DIR`` at a fresh directory and forgets the tables held in
memory, so it sees what a new process sees.  Parses from loaded tables are compared with
those of a parser lark builds directly from the grammar (an independent construction).
"""
from __future__ import annotations

import os
import pickle
import subprocess
import sys

import pytest
from lark import Lark

from dualmech.grade import lalr
from dualmech.grade.parser import _GRAMMAR, LIMITS, AnswerError, _Build

OPTIONS = {"lexer": "contextual", "maybe_placeholders": False}
ANSWERS = ["R*theta'' + g*sin(theta) = 0", r"\frac{1}{2} m \dot{x}_1^2", "sin^2(x) + cos x",
           "m g (a + b)^3; x1'' = -k_t x1", "[F_x, F_y, 0]", r"\sqrt{l} \cdot 2\theta",
           "2^3^2 - -x", "m_{0}*θ̈", "1.5e1 + .5"]


@pytest.fixture
def cache(tmp_path, monkeypatch):
    folder = tmp_path / "cache"
    monkeypatch.setenv("DUALMECH_CACHE_DIR", str(folder))
    monkeypatch.setattr(lalr, "_TABLES", {})
    monkeypatch.setattr(lalr, "_UNLOADABLE", set())
    return folder


def _parser():
    return lalr.lalr_parser(_GRAMMAR, _Build(LIMITS), **OPTIONS)


def _files(folder):
    return sorted(p.name for p in folder.iterdir()) if folder.exists() else []


def _forget(monkeypatch):
    """As a new process: no tables in memory."""
    monkeypatch.setattr(lalr, "_TABLES", {})


def _builds(monkeypatch) -> list:
    """Record every build of the tables."""
    calls: list = []
    real = lalr._build

    def counting(grammar, options):
        calls.append(1)
        return real(grammar, options)
    monkeypatch.setattr(lalr, "_build", counting)
    return calls


def _parse_all(parser):
    out = []
    for text in ANSWERS:
        try:
            out.append(repr(parser.parse(text)))
        except (AnswerError, Exception) as exc:   # compared by kind, as the trees are
            out.append(type(exc).__name__)
    return out


def test_saved_tables_parse_as_a_parser_built_from_the_grammar(cache, monkeypatch):
    direct = Lark(_GRAMMAR, parser="lalr", transformer=_Build(LIMITS), **OPTIONS)
    builds = _builds(monkeypatch)
    first = _parser()
    assert len(builds) == 1
    (name,) = _files(cache)
    assert name.startswith("lalr-") and name.endswith(".pickle")
    assert os.stat(cache / name).st_mode & 0o777 == 0o600
    assert os.stat(cache).st_mode & 0o777 == 0o700
    _forget(monkeypatch)
    second = _parser()
    assert len(builds) == 1   # read back, not built again
    assert _parse_all(first) == _parse_all(second) == _parse_all(direct)


def test_one_build_serves_every_transformer(cache, monkeypatch):
    builds = _builds(monkeypatch)
    tight = LIMITS.__class__(nodes=5)
    a = lalr.lalr_parser(_GRAMMAR, _Build(LIMITS), **OPTIONS)
    b = lalr.lalr_parser(_GRAMMAR, _Build(tight), **OPTIONS)
    assert len(builds) == 1
    a.parse("a + b + c + d + e + f")
    with pytest.raises(AnswerError, match="more than 5 operations"):
        b.parse("a + b + c + d + e + f")


def test_a_changed_grammar_gets_its_own_file(cache, monkeypatch):
    _parser()
    lalr.lalr_parser(_GRAMMAR + "\n// changed\n", _Build(LIMITS), **OPTIONS)
    lalr.lalr_parser(_GRAMMAR, _Build(LIMITS), lexer="contextual", maybe_placeholders=True)
    assert len(_files(cache)) == 3


@pytest.mark.parametrize("damage", ["truncated", "garbage", "wrong-digest", "empty"])
def test_a_damaged_file_is_rebuilt_and_replaced(cache, monkeypatch, damage):
    _parser()
    (path,) = cache.iterdir()
    blob = path.read_bytes()
    path.write_bytes({"truncated": blob[: len(blob) // 2], "garbage": os.urandom(500),
                      "wrong-digest": blob[:-1] + bytes([blob[-1] ^ 1]), "empty": b""}[damage])
    _forget(monkeypatch)
    builds = _builds(monkeypatch)
    assert _parse_all(_parser()) == _parse_all(
        Lark(_GRAMMAR, parser="lalr", transformer=_Build(LIMITS), **OPTIONS))
    assert len(builds) == 1 and lalr._unpack(path.read_bytes()) is not None   # whole again


def _forge(path, obj) -> None:
    import hashlib
    payload = pickle.dumps(obj)
    digest = hashlib.sha256(payload).hexdigest().encode()
    path.write_bytes(lalr._MAGIC + digest + b"\n" + payload)


def test_a_forged_pickle_is_never_executed(cache, monkeypatch, tmp_path):
    _parser()
    (path,) = cache.iterdir()
    marker = tmp_path / "ran"
    _forge(path, _Exploit(str(marker)))   # a well-formed file whose pickle calls a function
    _forget(monkeypatch)
    builds = _builds(monkeypatch)
    _parser().parse("a + b")
    assert not marker.exists()
    assert len(builds) == 1   # refused, built again


class _Exploit:
    def __init__(self, path):
        self.path = path

    def __reduce__(self):
        return (open, (self.path, "w"))


def test_foreign_tables_that_unpickle_are_rebuilt(cache, monkeypatch):
    _parser()
    (path,) = cache.iterdir()
    _forge(path, {"data": {"nothing": 1}, "memo": {}})   # plain data, not lark's tables
    _forget(monkeypatch)
    builds = _builds(monkeypatch)
    assert _parse_all(_parser()) == _parse_all(
        Lark(_GRAMMAR, parser="lalr", transformer=_Build(LIMITS), **OPTIONS))
    assert len(builds) == 1


@pytest.mark.parametrize("loose", ["directory", "file"])
def test_files_others_may_write_are_not_read(cache, monkeypatch, loose):
    _parser()
    (path,) = cache.iterdir()
    blob = path.read_bytes()
    os.chmod(cache if loose == "directory" else path, 0o777 if loose == "directory" else 0o666)
    _forget(monkeypatch)
    builds = _builds(monkeypatch)
    _parser().parse("a")
    assert len(builds) == 1
    if loose == "directory":   # nor written there
        assert _files(cache) == [path.name] and path.read_bytes() == blob


def test_a_world_writable_cache_directory_is_not_written(cache, monkeypatch):
    cache.mkdir(mode=0o700)
    os.chmod(cache, 0o1777)   # like /tmp
    _parser().parse("a")
    assert _files(cache) == []


def test_a_symbolic_link_is_not_followed(cache, monkeypatch, tmp_path):
    _parser()
    (path,) = cache.iterdir()
    elsewhere = tmp_path / "elsewhere.pickle"
    path.rename(elsewhere)
    path.symlink_to(elsewhere)
    _forget(monkeypatch)
    builds = _builds(monkeypatch)
    _parser().parse("a")
    assert len(builds) == 1


@pytest.mark.parametrize("where", ["off", "under-a-file"])
def test_no_cache_or_an_unwritable_one_still_parses(tmp_path, monkeypatch, where):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a directory")
    monkeypatch.setenv("DUALMECH_CACHE_DIR", "off" if where == "off" else str(blocker / "sub"))
    monkeypatch.setattr(lalr, "_TABLES", {})
    assert _parse_all(_parser()) == _parse_all(
        Lark(_GRAMMAR, parser="lalr", transformer=_Build(LIMITS), **OPTIONS))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-file"]


def test_a_lark_that_cannot_load_tables_builds_each_parser(cache, monkeypatch):
    def broken(payload, transformer):
        raise AttributeError("Lark._load is gone")
    monkeypatch.setattr(lalr, "_load", broken)
    assert _parse_all(_parser()) == _parse_all(
        Lark(_GRAMMAR, parser="lalr", transformer=_Build(LIMITS), **OPTIONS))
    assert _parser().parse("a")   # and again, straight to building


def test_concurrent_processes_never_read_half_a_file(cache):
    code = ("from dualmech.grade.parser import parse; "
            "print(repr(parse(\"R*theta'' + g*sin(theta) = 0\")))")
    env = dict(os.environ, DUALMECH_CACHE_DIR=str(cache))
    procs = [subprocess.Popen([sys.executable, "-c", code], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True) for _ in range(6)]
    outs = [p.communicate(timeout=120) for p in procs]
    assert all(p.returncode == 0 for p in procs), [err for _, err in outs]
    assert len({out for out, _ in outs}) == 1
    assert [n for n in _files(cache) if n.startswith(".tmp_")] == []
    assert len(_files(cache)) == 1
