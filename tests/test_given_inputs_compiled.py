"""Given inputs on the compiled route (numeric/input_code.py): a closed form printed into the
generated C, a table interpolated in C, a Python callable kept on scipy's route with the
reason said.  The problem: tests/corpus/teacher_problems/forced_block.py (m x'' = -k x +
(sqrt 3 / 2) F; from rest under F = F0 sin(w t) its motion is known in closed form, see
tests/test_given_inputs.py).  Hostile tables: tests/corpus/input_tables/.
"""
from __future__ import annotations

import json
import resource
import time
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from dualmech import EquationSet, coordinate, problems, t
from dualmech.cli.main import main
from dualmech.cli.simulate import summary
from dualmech.numeric import NumericModel
from dualmech.numeric.cvode import available, integrate
from dualmech.numeric.inputs import input_functions

HERE = Path(__file__).resolve().parent
FILE = HERE / "corpus" / "teacher_problems" / "forced_block.py"
TABLES = HERE / "corpus" / "input_tables"
M, K = 2.0, 8.0
W0 = np.sqrt(K / M)
F0, W = 1.5, 3.0

needs_cvode = pytest.mark.skipif(available() is not None, reason=str(available()))


def exact_x(t_, F0=F0, w=W):
    a = np.sqrt(3) * F0 / (2 * M)
    return a / (W0**2 - w**2) * (np.sin(w * t_) - w / W0 * np.sin(W0 * t_))


@pytest.fixture(scope="module")
def block():
    return problems.load(str(FILE))


def _run(block, history, method, rtol=1e-10):
    values = {p.symbol: p.default for p in block.parameters}
    drive = input_functions(block, {"F": history}, (0, 3), values)
    model = NumericModel(block.model(block.reference), values, inputs=drive)
    return model, integrate(model, (0, 3), [0, 0], t_eval=np.linspace(0, 3, 31), rtol=rtol,
                            atol=1e-12, method=method)


T = np.linspace(0, 3, 3001)
HISTORIES = {"closed form": F0 * sp.sin(W * t), "table": (T, F0 * np.sin(W * T))}


def exact_table_x(times, values, t_out):
    """x(t) under the table's piecewise-linear F, exactly: on each row F = a + b s, and
    x'' + w0^2 x = c F (c = sqrt 3 / (2 m)) has the particular solution c (a + b s) / w0^2."""
    c = np.sqrt(3) / (2 * M)
    x = v = 0.0
    out = np.empty(len(t_out))
    for i in range(len(times) - 1):
        h, a = times[i + 1] - times[i], values[i]
        b = (values[i + 1] - values[i]) / h
        A, B = x - c * a / W0**2, (v - c * b / W0**2) / W0

        def at(s):
            return (A * np.cos(W0 * s) + B * np.sin(W0 * s) + c * (a + b * s) / W0**2,
                    W0 * (B * np.cos(W0 * s) - A * np.sin(W0 * s)) + c * b / W0**2)
        inside = (t_out >= times[i]) & (t_out <= times[i + 1])
        out[inside] = at(t_out[inside] - times[i])[0]
        x, v = at(h)
    return out


@needs_cvode
def test_compiled_and_python_routes_agree_on_a_closed_form(block):
    model, cv = _run(block, HISTORIES["closed form"], "auto")
    _, py = _run(block, HISTORIES["closed form"], "DOP853")
    assert model.inputs_in_python is None and cv.method == "CVODE-Adams", cv.message
    # a smooth input: each route's global error at rtol 1e-10 (|x| <= 0.2, atol 1e-12) is
    # a few 1e-11 here (measured), so they agree to 1e-9 and both match the closed form
    assert np.abs(cv.y - py.y).max() < 1e-9
    assert np.abs(cv.y[0] - exact_x(cv.t)).max() < 1e-9


@needs_cvode
def test_compiled_and_python_routes_agree_on_a_table(block):
    model, cv = _run(block, HISTORIES["table"], "auto")
    _, py = _run(block, HISTORIES["table"], "DOP853")
    assert model.inputs_in_python is None and cv.method == "CVODE-Adams", cv.message
    exact = exact_table_x(T, F0 * np.sin(W * T), cv.t)
    # F' jumps at each of the 3000 rows, where rtol's error control assumes smoothness:
    # measured global errors 4e-9 (CVODE) and 7e-9 (DOP853) at rtol 1e-10, so 1e-8 each.
    # Another interpolation would show (measured): nearest-row F moves x by 1.3e-7, the
    # table shifted by one row by 7e-4; the smooth sine's own solution differs by 2.3e-7
    assert np.abs(cv.y[0] - exact).max() < 1e-8
    assert np.abs(py.y[0] - exact).max() < 1e-8
    assert np.abs(cv.y[0] - py.y[0]).max() < 2e-8


@needs_cvode
def test_a_python_callable_keeps_scipy_and_says_why(block):
    model, run = _run(block, lambda s: F0 * np.sin(W * s), "auto")
    assert run.method == "DOP853"
    assert "input F is a Python function" in model.inputs_in_python
    assert run.message.startswith("fallback: input F is a Python function")
    assert np.abs(run.y[0] - exact_x(run.t)).max() < 1e-8
    with pytest.raises(RuntimeError, match="CVODE runs compiled code only"):
        _run(block, lambda s: 0.0, "CVODE-BDF")


def test_the_c_table_is_numpy_interp():
    """x'' = F: the compiled right-hand side's second entry is F(t) itself."""
    x, F = coordinate("x"), sp.Symbol("F")
    eqs = EquationSet("driven", (x,), (x.diff(t, 2) - F,))
    rng = np.random.default_rng(7)
    times = np.cumsum(rng.uniform(0.001, 0.1, 400))
    values = rng.standard_normal(400)
    drive = input_functions(_Declared(F), {"F": (times, values)})
    model = NumericModel(eqs, {}, backend="c", inputs=drive)
    assert model.compiled
    probe = np.concatenate([rng.uniform(times[0], times[-1], 2000), times])
    got = np.array([model.rhs(s, np.array([0.0, 0.0]))[1] for s in probe])
    assert np.array_equal(got, np.interp(probe, times, values))
    many = model.rhs(probe, np.zeros((2, probe.size)))[1]   # one call, a time per column
    assert np.array_equal(many, np.interp(probe, times, values))


class _Declared:
    """A problem declaring one input F and nothing else (enough for input_functions)."""

    def __init__(self, F):
        from dualmech import FORCE, Input
        self.name, self.inputs, self.parameters = "driven", (Input(F, FORCE, "F"),), ()

    def defaults(self):
        return {}


def run_cli(capsys, *argv):
    """The status, stdout and stderr of ``dualmech ARGV``; stderr as one line of words (its
    messages are wrapped to the terminal, a line breaking between any two words)."""
    status = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return status, out, " ".join(err.split())


@needs_cvode
@pytest.mark.parametrize("form", ["expression", "csv"])
def test_the_command_runs_inputs_on_cvode(capsys, tmp_path, form):
    value = "1.5*sin(3 t)"
    if form == "csv":
        value = tmp_path / "push.csv"
        value.write_text("\n".join(f"{a:.17g},{b:.17g}" for a, b in
                                   zip(T, F0 * np.sin(W * T))))
    status, out, err = run_cli(capsys, "simulate", FILE, "--duration", "3", "--json",
                               "--rtol", "1e-10", "--atol", "1e-12", "--input", f"F={value}")
    assert status == 0 and not err, err
    doc = json.loads(out)
    assert doc["method"] == "CVODE-Adams" and doc["inputs_in_python"] is None
    # the table's interpolation moves x by 2.3e-7 from the sine's solution (see above)
    assert doc["final_state"][0] == pytest.approx(exact_x(3.0), abs=1e-6 if form == "csv"
                                                  else 1e-9)


HOSTILE = {"empty.csv": "2 to 1000000 rows, got 0",
           "header_only.csv": "2 to 1000000 rows, got 0",
           "not_increasing.csv": "row 3: t = 1 after t = 2",
           "repeated_time.csv": "row 3: t = 1 after t = 1",
           "nan_value.csv": "not a finite number", "inf_value.csv": "not a finite number",
           "three_columns.csv": "3 columns; a table has two",
           "one_column.csv": "1 columns; a table has two",
           "hex_value.csv": "are not two numbers"}


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_tables_are_refused(capsys, name):
    status, out, err = run_cli(capsys, "simulate", FILE, "--duration", "2", "--input",
                               f"F={TABLES / name}")
    assert status == 2 and HOSTILE[name] in err and "Traceback" not in err, err


def _peak_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def test_ten_million_rows_are_refused_early(capsys, tmp_path, block):
    """10^7 rows: a 40 MB file of short rows (under the 50 MB file limit) is refused at row
    10^6 + 1 while reading; 10^7 rows passed as arrays are refused by their size.  Measured
    here (run with -s to print): 3.2 s and +38 MB peak memory for the file, under a
    millisecond for the arrays."""
    path = tmp_path / "huge.csv"
    path.write_bytes(b"1,0\n" * 10_000_000)
    before, start = _peak_mb(), time.perf_counter()
    status, _, err = run_cli(capsys, "simulate", FILE, "--duration", "1", "--input",
                             f"F={path}")
    took, grew = time.perf_counter() - start, _peak_mb() - before
    assert status == 2 and "more than 1000000 rows" in err, err
    print(f"10^7-row file refused in {took:.2f} s, peak memory +{grew:.0f} MB")
    big = np.arange(10_000_000, dtype=float)
    start = time.perf_counter()
    with pytest.raises(ValueError, match="2 to 1000000 rows, got 10000000"):
        summary(block, duration=1.0, inputs={"F": (big, big)})
    print(f"10^7-row arrays refused in {time.perf_counter() - start:.3f} s")
