"""CVODE driving the generated C right-hand side (``dualmech.numeric.cvode``) and ``dualmech
simulate``: the same motion as the scipy route, the JSON a script reads, the named fallback.

Tolerance of the comparisons, derived from CVODE's own error: CVODE controls the local error,
and its global error is proportional to the tolerance (measured on these scenes: the error at
``rtol`` is 15 to 220 times ``rtol`` and shrinks about 100-fold at ``rtol / 100``).  So
``est = |y(rtol) - y(rtol / 100)|`` is the global error of the run at ``rtol`` to within about
1 % (the triangle inequality leaves ``est >= err (1 - 1/100)`` when the error shrinks
100-fold), and the run at ``rtol`` must lie within ``2 est`` of the reference: scipy's DOP853
at ``rtol = 1e-11`` (error about 6e-11 here, below 1e-3 of ``est``), or the closed form where
there is one.  A driver that ignored the tolerance (``est`` near 0), integrated another
equation or read the wrong parameters (errors of order 1) fails it.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from dualmech import problems
from dualmech.cli.main import main
from dualmech.numeric import NumericModel
from dualmech.numeric.cvode import CVODE_METHODS, available, integrate
from dualmech.numeric.simulation import default_initial_state, problem_parameters

pytestmark = pytest.mark.skipif(available() is not None,
                                reason=f"CVODE route unavailable here: {available()}")

RTOL = 1e-8
SPAN = (0.0, 10.0)
SAMPLES = np.linspace(*SPAN, 11)

#: A teacher's own problem, outside the catalogue: a block on a spring and a damper, driven
#: by F0 cos(w t) -- m x'' + c x' + k x = F0 cos(w t), with a closed-form solution (below).
TEACHER_FILE = textwrap.dedent('''
    import sympy as sp
    from dualmech import Lagrangian, coordinate, t
    from dualmech.model.dimensions import DAMPING, FORCE, FREQUENCY, LENGTH, MASS, STIFFNESS
    from dualmech.model.equations import EquationSet
    from dualmech.model.problem import Coordinate, Parameter, Problem

    m, c, k, F0, w = sp.symbols("m c k F0 w", positive=True)
    x = coordinate("x")


    class DrivenSpring(Problem):
        name, title, source = "driven_spring", "Driven block on a spring", "my notes: ex. 4"
        parameters = (Parameter(m, MASS, 2.0, (0.1, 10.0)),
                      Parameter(c, DAMPING, 0.3, (0.0, 10.0)),
                      Parameter(k, STIFFNESS, 50.0, (1.0, 500.0)),
                      Parameter(F0, FORCE, 1.5, (0.0, 10.0)),
                      Parameter(w, FREQUENCY, 3.0, (0.1, 20.0)))
        coordinates = (Coordinate(x, LENGTH, (-0.5, 0.5)),)

        def newton_euler(self):
            return EquationSet("newton_euler", (x,), (F0 * sp.cos(w * t) - c * x.diff(t)
                                                      - k * x - m * x.diff(t, 2),))

        def lagrange(self):
            lg = Lagrangian(coordinates=[x])
            lg.kinetic("T", m * x.diff(t)**2 / 2)
            lg.spring("spring", k, x)
            lg.damper("damper", c, x.diff(t))
            lg.generalized_force("drive", [F0 * sp.cos(w * t)])
            return lg.equations()
''')


def driven_spring(t, x0, v0, m=2.0, c=0.3, k=50.0, F0=1.5, w=3.0):
    """``[x, x']`` of ``m x'' + c x' + k x = F0 cos(w t)`` (underdamped), by hand: the steady
    response ``X cos(w t - delta)`` plus the free decay fitted to ``x0, v0``."""
    X = F0 / np.hypot(k - m * w**2, c * w)
    delta = np.arctan2(c * w, k - m * w**2)
    a, wd = c / (2 * m), np.sqrt(k / m - (c / (2 * m))**2)
    A = x0 - X * np.cos(delta)
    B = (v0 - X * w * np.sin(delta) + a * A) / wd
    e = np.exp(-a * t)
    x = X * np.cos(w * t - delta) + e * (A * np.cos(wd * t) + B * np.sin(wd * t))
    v = (-X * w * np.sin(w * t - delta) - a * e * (A * np.cos(wd * t) + B * np.sin(wd * t))
         + e * wd * (-A * np.sin(wd * t) + B * np.cos(wd * t)))
    return np.array([x, v])


@pytest.fixture(scope="module")
def teacher_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("course") / "driven_spring.py"
    path.write_text(TEACHER_FILE)
    return str(path)


def _setup(spec: str, **options):
    p = problems.load(spec, **options)
    model = NumericModel(p.model(p.reference), problem_parameters(p))
    q0, qd0 = default_initial_state(p)
    return model, np.array(q0 + qd0, dtype=float)


def _run(model, y0, method, rtol, t_eval=SAMPLES):
    run = integrate(model, SPAN, y0, t_eval=t_eval, rtol=rtol, atol=rtol * 1e-2,
                    method=method)
    assert run.success, run.message
    assert run.method == method and np.array_equal(run.t, t_eval)
    return run.y


@pytest.mark.parametrize("method", CVODE_METHODS)
@pytest.mark.parametrize("spec, options", [("toy_car", {}), ("n_link_pendulum", {"n": 3})],
                         ids=["toy_car", "3-link chain"])
def test_cvode_matches_the_scipy_route_within_its_own_error(spec, options, method):
    model, y0 = _setup(spec, **options)
    reference = _run(model, y0, "DOP853", 1e-11)
    y = _run(model, y0, method, RTOL)
    est = np.abs(y - _run(model, y0, method, RTOL / 100)).max(axis=0)
    err = np.abs(y - reference).max(axis=0)
    assert (err <= 2 * est).all(), (err, est)
    assert est.max() < 1e4 * RTOL  # the error scales with rtol: it is not of order one
    assert np.array_equal(y[:, 0], y0)


@pytest.mark.parametrize("method", CVODE_METHODS)
def test_a_teachers_file_outside_the_catalogue_against_its_closed_form(teacher_file, method):
    model, y0 = _setup(teacher_file)
    exact = driven_spring(SAMPLES, *y0)
    y = _run(model, y0, method, RTOL)
    est = np.abs(y - _run(model, y0, method, RTOL / 100)).max(axis=1, keepdims=True)
    assert (np.abs(y - exact) <= 2 * est).all()
    assert (np.abs(y - _run(model, y0, "DOP853", 1e-11)) <= 2 * est).all()


def test_a_backward_span_and_samples_at_the_start():
    model, y0 = _setup("toy_car")
    t_eval = np.array([0.0, -0.5, -2.0])
    back = integrate(model, (0.0, -2.0), y0, t_eval=t_eval, rtol=1e-10, atol=1e-12,
                     method="CVODE-Adams")
    ref = integrate(model, (0.0, -2.0), y0, t_eval=t_eval, rtol=1e-12, atol=1e-14,
                    method="DOP853")
    assert back.success and np.array_equal(back.y[:, 0], y0)
    assert np.abs(back.y - ref.y).max() < 1e-7  # 2 s at rtol 1e-10: error ~ 50 rtol (above)


def test_bad_requests_are_refused_with_what_to_fix():
    model, y0 = _setup("toy_car")
    with pytest.raises(ValueError, match="`y0` must hold 4"):
        integrate(model, SPAN, y0[:3])
    with pytest.raises(ValueError, match="`t_eval` must be sample times from 0 to 10"):
        integrate(model, SPAN, y0, t_eval=[5.0, 1.0])
    with pytest.raises(ValueError, match="`method` must be one of"):
        integrate(model, SPAN, y0, method="CVODE")


def test_simulate_json_holds_the_run(capsys):
    status = main(["simulate", "toy_car", "--json", "--duration", "3", "--rtol", "1e-9"])
    out = json.loads(capsys.readouterr().out)
    assert status == 0
    p = problems.load("toy_car")
    assert out["parameters"] == {s.name: float(v) for s, v in p.defaults().items()}
    assert out["coordinates"] == ["theta", "phi", "theta'", "phi'"]
    model, y0 = _setup("toy_car")
    assert out["initial_state"] == y0.tolist()
    again = integrate(model, (0.0, 3.0), y0, rtol=1e-9, atol=1e-10)  # the same route
    assert out["final_state"] == again.y[:, -1].tolist()
    assert out["method"] == "CVODE-Adams" and out["fallback"] is None
    assert 0 < out["cpu_seconds"] < 5 and out["steps"] > 100 and out["t_final"] == 3.0


@pytest.mark.parametrize("argv, message", [
    (["--param", "mass=2"], "unknown parameter 'mass'"),
    (["--param", "m=heavy"], "`--param` m: 'heavy' is not a number"),
    (["--method", "cvode"], "`--method` 'cvode' is not one of auto, CVODE-Adams")],
    ids=["misspelt-parameter", "not-a-number", "unknown-method"])
def test_simulate_refuses_bad_options_saying_what_to_fix(capsys, argv, message):
    status = main(["simulate", "toy_car", *argv])
    assert status == 2
    assert message in capsys.readouterr().err


def test_without_a_compiler_simulate_falls_back_and_says_so_in_one_line(tmp_path):
    """A fresh machine with no C compiler: nothing compiled in the cache, none on PATH."""
    env = {**os.environ, "PATH": str(tmp_path), "DUALMECH_CACHE_DIR": str(tmp_path / "c")}
    env.pop("CC", None)
    done = subprocess.run([sys.executable, "-m", "dualmech", "simulate", "simple_pendulum",
                           "--duration", "2", "--json"], capture_output=True, text=True,
                          env=env, timeout=600)
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert out["method"] == "DOP853" and "no C compiler" in out["fallback"]
    assert done.stderr.splitlines() == [
        f"dualmech simulate: CVODE cannot run here ({out['fallback']}); fell back to scipy "
        "DOP853 on the generated right-hand side."]
    model, y0 = _setup("simple_pendulum")  # the same route: the Python right-hand side
    ref = integrate(model.with_backend("python"), (0.0, 2.0), y0, rtol=1e-8, atol=1e-10,
                    method="DOP853")
    assert out["final_state"] == ref.y[:, -1].tolist()


@pytest.mark.parametrize("method", CVODE_METHODS + ("DOP853",))
def test_the_run_stops_where_the_motion_reaches_the_declared_singular_set(method):
    """The toy car's mass matrix diag(m R^2, m R^2 cos^2 theta) is singular at cos(theta) = 0
    (the car on the track's pivot axis).  Thrown from theta = 1.2 at theta' = 5 with the track
    at rest (phi = phi' = 0: phi stays 0), the car swings as a pendulum,
    theta'' = -(g/R) sin(theta), and passes theta = pi/2 at
    t* = int_1.2^(pi/2) dtheta / sqrt(25 + 2 (g/R)(cos(theta) - cos(1.2)))  (by hand)."""
    from scipy.integrate import quad

    from dualmech.numeric.model import SingularityError
    car = problems.load("toy_car")
    model, _ = _setup("toy_car")
    gR = 9.81 / 0.5
    t_star = quad(lambda th: 1 / np.sqrt(25 + 2 * gR * (np.cos(th) - np.cos(1.2))), 1.2,
                  np.pi / 2, epsabs=1e-14, epsrel=1e-13)[0]
    with pytest.raises(SingularityError, match=r"reaches the singular set cos\(theta\(t\)\) = 0 "
                                               r"at t=(\S+), theta=1.5708, phi=0:") as info:
        integrate(model, (0.0, 2.0), [1.2, 0.0, 5.0, 0.0], rtol=1e-10, atol=1e-12,
                  method=method, singular=car.singular)
    t_hit = float(str(info.value).split(" at t=")[1].split(",")[0])
    assert abs(t_hit - t_star) < 1e-7  # rtol 1e-10 over 0.09 s; t printed to 9 digits


def test_simulate_reports_a_motion_that_reaches_the_singular_set(capsys):
    """The ball in the sphere, released at rest (phi' = 0), swings through the pole
    theta = pi where its spherical coordinates fail (sin(theta) = 0, declared)."""
    status = main(["simulate", "ball_in_sphere", "--json"])
    captured = capsys.readouterr()
    out = json.loads(captured.out)
    assert status == 1 and out["success"] is False and out["final_state"] is None
    assert "reaches the singular set sin(theta(t)) = 0" in out["message"]
    assert captured.err == f"dualmech simulate: stopped early: {out['message']}\n"
