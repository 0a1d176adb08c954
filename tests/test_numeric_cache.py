"""The on-disk cache of generated code: reused across processes, invalidated by a changed
source, regenerated when damaged, off on request."""
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from dualmech import EquationSet, coordinate, t
from dualmech.numeric import NumericModel, cache_dir
from dualmech.numeric import _cache, cbackend, codegen, model

k = sp.Symbol("k", positive=True)
x = coordinate("x")


def spring(factor=1):
    """x'' = -factor k x (hand: the acceleration at x = 0.5, k = 3 is -1.5 factor)."""
    return EquationSet("spring", (x,), (x.diff(t, 2) + factor * k * x,))


def forget():
    """What a new process starts with: nothing generated or loaded in memory."""
    _cache.clear_memory()
    model._BY_ID.clear()
    cbackend._LOADED.clear()


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("DUALMECH_CACHE_DIR", str(tmp_path))
    forget()
    yield tmp_path
    forget()


def _no_codegen(monkeypatch):
    def refuse(*_a, **_k):
        raise AssertionError("code was generated again although it is cached")
    monkeypatch.setattr(codegen, "program", refuse)


def _acc(eqs, backend="python"):
    return NumericModel(eqs, {k: 3.0}, backend=backend).accelerations(0.0, [0.5], [0.0])[0]


def test_cached_module_is_loaded_not_regenerated(cache, monkeypatch):
    assert _acc(spring()) == -1.5
    files = sorted(p.name for p in cache.glob("dm_*.py"))
    assert len(files) == 1
    forget()
    _no_codegen(monkeypatch)
    assert _acc(spring()) == -1.5          # a new EquationSet object, the same source
    assert sorted(p.name for p in cache.glob("dm_*.py")) == files


def test_changed_source_gets_new_code(cache):
    assert _acc(spring()) == -1.5
    forget()
    assert _acc(spring(2)) == -3.0
    assert len(list(cache.glob("dm_*.py"))) == 2
    with_assumption = EquationSet("spring", (x,), (x.diff(t, 2) + sp.Symbol("k") * x,))
    assert _cache.digest(with_assumption.equations) != _cache.digest(spring().equations)


def test_damaged_module_is_generated_again(cache):
    assert _acc(spring()) == -1.5
    (path,) = cache.glob("dm_*.py")
    path.write_text("KEY = 'something else'\n")
    forget()
    assert _acc(spring()) == -1.5
    assert "def static" in path.read_text()


@pytest.mark.skipif(cbackend.compiler() is None, reason="no C compiler here")
def test_compiled_library_is_cached_too(cache, monkeypatch):
    assert _acc(spring(), "c") == -1.5
    assert len(list(cache.glob("dm_*.so"))) == 1
    forget()

    def refuse(*_a, **_k):
        raise AssertionError("compiled again although cached")
    monkeypatch.setattr(cbackend, "_compile", refuse)
    assert _acc(spring(), "c") == -1.5
    forget()
    monkeypatch.undo()
    monkeypatch.setenv("DUALMECH_CACHE_DIR", str(cache))
    assert _acc(spring(3), "c") == -4.5    # changed source: a new library


def test_cache_can_be_turned_off(tmp_path, monkeypatch):
    monkeypatch.setenv("DUALMECH_CACHE_DIR", "off")
    forget()
    assert cache_dir() is None
    assert _acc(spring(5)) == -7.5
    forget()


def test_default_directory_follows_xdg(monkeypatch, tmp_path):
    monkeypatch.delenv("DUALMECH_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert cache_dir() == tmp_path / "dualmech"
    monkeypatch.delenv("XDG_CACHE_HOME")
    assert cache_dir() == Path.home() / ".cache" / "dualmech"


def test_another_process_reuses_the_cache(cache):
    """A second interpreter (another hash seed) finds the module by the same digest."""
    assert _acc(spring(7)) == -10.5
    script = textwrap.dedent("""
        import sympy as sp
        from dualmech import EquationSet, coordinate, t
        from dualmech.numeric import NumericModel, codegen
        def refuse(*a, **kw):
            raise SystemExit("regenerated")
        codegen.program = refuse
        x, k = coordinate("x"), sp.Symbol("k", positive=True)
        eqs = EquationSet("spring", (x,), (x.diff(t, 2) + 7 * k * x,))
        nm = NumericModel(eqs, {k: 3.0}, backend="python")
        print(nm.accelerations(0.0, [0.5], [0.0])[0])
    """)
    env = dict(os.environ, DUALMECH_CACHE_DIR=str(cache), PYTHONHASHSEED="12345")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          env=env, cwd=Path(__file__).resolve().parent.parent, timeout=300)
    assert done.returncode == 0, done.stderr
    assert float(done.stdout) == -10.5


def three_unknowns():
    """x'' = -k x with two reactions fixed by two trivial equations (a 3x3 system)."""
    a, b = sp.Symbol("a"), sp.Symbol("b")
    return EquationSet("three", (x,), (x.diff(t, 2) + k * x, 2 * a - k, b + a - 1), (a, b))


def test_without_a_working_compiler_auto_falls_back_and_c_says_why(cache, monkeypatch):
    monkeypatch.setenv("CC", "false")          # found, but compiles nothing
    nm = NumericModel(three_unknowns(), {k: 3.0})
    # hand: x'' = -1.5, a = k/2 = 1.5, b = 1 - a = -0.5
    assert np.array_equal(nm.solve(0.0, [0.5], [0.0]), [-1.5, 1.5, -0.5])
    assert nm._c is None and not list(cache.glob("*.so"))
    monkeypatch.setattr(cbackend, "compiler", lambda: None)
    forget()
    with pytest.raises(RuntimeError, match=r"`backend='c'` needs a working C compiler"):
        NumericModel(three_unknowns(), {k: 3.0}, backend="c").rhs(0.0, np.array([0.5, 0.0]))
