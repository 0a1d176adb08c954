"""Work-precision sweeps (dualmech.numeric.studies.workprecision) on the particle pendulum of source 003.

What is asserted are the measured numbers and their bookkeeping, not the pictures: the
errors are recomputed independently for one run, RK45's error is proportional to its
tolerance, the midpoint rule's to the square of its step, and formulations that are the same
ODE are recognised as the same curve.
"""
import csv
import json

import numpy as np
import pytest

from dualmech.numeric.formulations import formulations
from dualmech.numeric.studies.workprecision import work_precision
from dualmech.problems import get

TOLS = (1e-4, 1e-6, 1e-8)
STEPS = (32, 64, 128)


@pytest.fixture(scope="module")
def wp():
    return work_precision(get("pendulum_particle"), duration=3.0, tolerances=TOLS,
                          steps=STEPS, methods=("RK45", "DOP853", "midpoint", "IDA"),
                          models=("lagrange", "newton_euler", "cartesian"), samples=51,
                          y0=[1.0, 0.0], progress=False, baumgarte_gains=(10.0,),
                          stabilisations=("none", "baumgarte", "projection", "ggl"),
                          repeats=2)


def _curve(wp, form, method):
    return wp.curves()[(form, method)]


@pytest.mark.slow
def test_every_run_succeeded_and_the_path_error_bounds_the_final_one(wp):
    assert wp.runs and all(r.success for r in wp.runs)
    assert all(r.path_error >= r.final_error for r in wp.runs)


@pytest.mark.slow
def test_measures_apply_where_they_mean_something(wp):
    for r in wp.runs:
        assert np.isfinite(r.reaction_error) and np.isfinite(r.energy_drift)
        assert np.isfinite(r.drift) == (r.kind == "dae")
    assert wp.drift_unit == "m"


@pytest.mark.slow
def test_one_run_recomputed_by_hand(wp):
    """The Baumgarte DAE with RK45 at 1e-6, measured again without the sweep's bookkeeping."""
    f = {g.name: g for g in formulations(get("pendulum_particle"), y0=[1.0, 0.0],
                                         baumgarte_gains=(10.0,))[0]}
    te = np.linspace(0.0, 3.0, 51)
    ref = f["lagrange"].run("DOP853", (0.0, 3.0), te, rtol=1e-13)
    th, thd = ref.y
    bob = np.vstack([np.sin(th), np.cos(th), np.cos(th) * thd, -np.sin(th) * thd])  # l = 1
    dae = f["cartesian (DAE, Baumgarte 10/s)"]
    run = dae.run("RK45", (0.0, 3.0), te, rtol=1e-6)
    err = np.abs(run.y - bob) / dae.scales[:, None]
    point = [r for r in _curve(wp, dae.name, "RK45") if r.tolerance == 1e-6][0]
    assert point.final_error == pytest.approx(err[:, -1].max(), rel=1e-6)
    assert point.path_error == pytest.approx(err.max(), rel=1e-6)
    S_hand = 9.81 * np.cos(th) + thd**2                       # m = l = 1
    S = dae.reactions(te, run.y)["S"]
    assert point.reaction_error == pytest.approx(np.abs(S - S_hand).max()
                                                 / np.abs(S_hand).max(), rel=1e-6)


@pytest.mark.slow
def test_rk45_error_is_proportional_to_its_tolerance(wp):
    runs = _curve(wp, "lagrange", "RK45")
    slope = np.polyfit(np.log([r.tolerance for r in runs]),
                       np.log([r.path_error for r in runs]), 1)[0]
    assert round(slope) == 1


@pytest.mark.slow
def test_midpoint_error_falls_with_the_square_of_the_step(wp):
    runs = _curve(wp, "lagrange", "midpoint")
    order = np.polyfit(np.log([r.tolerance for r in runs]),
                       np.log([r.path_error for r in runs]), 1)[0]
    assert round(order) == 2
    assert [r.steps for r in runs] == list(STEPS)


@pytest.mark.slow
def test_same_ode_is_recognised_as_the_same_curve(wp):
    # the body-axes direct form solves the same theta'' as the Lagrangian: same steps, errors
    for method in ("RK45", "DOP853", "midpoint"):
        assert all(r.same_as == f"lagrange x {method}"
                   for r in _curve(wp, "newton_euler", method))
    assert not any(r.same_as for r in _curve(wp, "cartesian (DAE, index 1)", "RK45"))


@pytest.mark.slow
def test_every_point_records_its_repeats_backend_and_work(wp):
    for r in wp.runs:
        assert r.repeats == 2 and r.cpu_spread >= 1.0 and r.evaluations >= r.calls > 0
        assert r.backend == {"ode": "NumPy", "dae": "C"}[r.kind] or \
            (r.method == "IDA" and r.backend == "Python") or r.method == "midpoint"
    # the projection is driven step by step: IDA only for the GGL form, no LSODA there
    assert {m for (f, m) in wp.curves() if "GGL" in f} == {"IDA"}
    assert {m for (f, m) in wp.curves() if "projection" in f} == {"RK45", "DOP853"}


@pytest.mark.slow
def test_projection_after_every_step_keeps_the_rod_length_and_lets_the_steps_follow_rtol(wp):
    runs = _curve(wp, "cartesian (DAE, projection)", "DOP853")
    # |g| = |l^2 - x^2 - y^2|/(2 l) after Gauss-Newton to 1e-13 relative, at every sample
    assert all(r.drift <= 1e-12 for r in runs)
    # a method, not a restart at every sample: the steps fall as the tolerance loosens
    # (the restarting version took the same 199 steps at every tolerance)
    steps = [r.steps for r in runs]
    assert steps == sorted(steps) and steps[0] < steps[-1] < 100


@pytest.mark.slow
def test_ggl_error_follows_the_tolerance(wp):
    runs = _curve(wp, "cartesian (DAE, GGL index 2)", "IDA")
    assert all(r.success for r in runs)
    errors = [r.path_error for r in runs]
    assert errors == sorted(errors, reverse=True)
    slope = np.polyfit(np.log([r.tolerance for r in runs]), np.log(errors), 1)[0]
    assert 0.5 < slope < 1.5   # a BDF code's global error ~ its local tolerance


@pytest.mark.slow
def test_data_and_charts_are_written(wp, tmp_path):
    paths = wp.write(tmp_path)
    assert sorted(p.name for p in paths) == [
        f"pendulum_particle_workprecision{end}" for end in
        (".csv", ".json", ".png", ".svg", "_lesson.png", "_lesson.svg")]
    assert all(p.stat().st_size > 0 for p in paths)
    with open(tmp_path / "pendulum_particle_workprecision.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == len(wp.runs)
    assert [float(r["path_error"]) for r in rows] == [r.path_error for r in wp.runs]
    data = json.loads((tmp_path / "pendulum_particle_workprecision.json").read_text())
    assert data["span"] == [0.0, 3.0] and len(data["runs"]) == len(wp.runs)
    # the scene the figures state: the problem's defaults and the y0 given to the sweep
    assert data["scene"] == ("m = 1 kg, l = 1 m, g = 9.81 m/s^2; from theta = 1 rad, "
                             "theta' = 0 rad/s")


@pytest.mark.slow
def test_the_lesson_figure_draws_one_curve_per_integrator_at_its_best_formulation(wp):
    from dualmech.numeric.studies.wplesson import best_curves
    best = best_curves(wp)
    assert set(best) == {"RK45", "DOP853", "midpoint", "IDA"}
    for method, (form, runs) in best.items():
        assert not runs[0].same_as            # a curve drawn once is chosen under its first name
        rivals = [rs for (f, m), rs in wp.curves().items() if m == method and not rs[0].same_as]
        # no rival with as many successes is cheaper at each of its errors on average
        good = sum(r.success for r in runs)
        for rs in rivals:
            assert sum(r.success for r in rs) <= good
            if sum(r.success for r in rs) == good:
                assert np.mean([np.log10(r.cpu * r.path_error) for r in rs if r.success]) >= \
                    np.mean([np.log10(r.cpu * r.path_error) for r in runs if r.success]) - 1e-12


# -- the `chart` command (dualmech.cli.studies) ------------------------------------------
def _cli():
    import argparse
    from dualmech.cli.studies import register
    parser = argparse.ArgumentParser(prog="dualmech")
    register(parser.add_subparsers(dest="command"))
    return parser


@pytest.mark.parametrize("argv, message", [
    (["chart", "pendulum_partcle"], "no problem named 'pendulum_partcle'. Did you mean "
                                    "'pendulum_particle'"),
    (["chart"], "name at least one problem, or use --all"),
    (["chart", "toy_car", "--all"], "give problem names or --all, not both"),
], ids=["misspelt", "nothing", "both"])
def test_chart_usage_errors_exit_2_with_one_message(argv, message, capsys):
    # one message, wrapped to 100 columns (stderr is no terminal here): the misspelt name's
    # list of every known problem runs over several lines
    args = _cli().parse_args(argv)
    assert args.func(args) == 2
    err = capsys.readouterr().err
    assert message in " ".join(err.split()) and "Traceback" not in err
    assert err.count("dualmech chart: error:") == 1 and err.startswith("dualmech chart: error:")
    assert max(map(len, err.splitlines())) <= 100


def test_chart_into_an_unwritable_directory_exits_2(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("")
    args = _cli().parse_args(["chart", "toy_car", "--out", str(blocker / "sub")])
    assert args.func(args) == 2
    assert "cannot create the output directory" in capsys.readouterr().err
