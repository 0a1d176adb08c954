"""Facts about one problem are declarations on Problem (dualmech.model.facts), never engine tables.

Hand references: a bob of mass m on a string of length a, thrown from the bottom at the rate
w0 (theta from the downward vertical).  Energy: theta'^2 = w0^2 - 2 (g/a) (1 - cos theta);
radial balance: T = m (g cos theta + a theta'^2), so the string goes slack where
cos theta = (2 g - a w0^2) / (3 g), reached at t = int_0^theta dth / theta'(th).  In the
horizontal coordinate x = a sin theta the mass is m a^2 / (a^2 - x^2) = m / cos^2 theta:
unbounded at theta = pi/2 (the declared singular set cos(theta) = 0), its degeneracy against
the start at the bottom 1 / cos^2 theta.
"""
from __future__ import annotations

import ast
import dataclasses
import re
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

import dualmech
from dualmech import FidelityRung, Probe, ProblemError, StiffScene
from dualmech.model.facts import state_vector
from dualmech.numeric.contacts import scene_span, watch
from dualmech.numeric.studies.atlas import atlas
from dualmech.numeric.studies.regimes import stiffness
from dualmech.numeric.studies.singularities import GARBAGE, ProbeReport
from dualmech.problems import declarations, get, load

EPS = np.finfo(float).eps
PACKAGE = Path(dualmech.__file__).resolve().parent


# -- no engine module names a catalogue problem --------------------------------------------------
def _catalogue_names() -> list[str]:
    return sorted({d.name for d in declarations()}, key=len, reverse=True)


def _docstrings(tree) -> set[int]:
    kinds = (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)
    return {id(node.body[0].value) for node in ast.walk(tree)
            if isinstance(node, kinds) and node.body and isinstance(node.body[0], ast.Expr)
            and isinstance(node.body[0].value, ast.Constant)}


def _engine_modules() -> list[Path]:
    catalogue = Path(dualmech.problems.__file__).resolve().parent
    return [p for p in sorted(PACKAGE.rglob("*.py")) if catalogue not in p.parents]


def _named(path: Path, names: list[str]) -> list[tuple]:
    """``(line, name, text)`` of each string constant (dict keys included) of ``path`` that
    names a catalogue problem, docstrings left out (the doctests' examples use the catalogue)."""
    word = re.compile(r"(?<![\w.])(" + "|".join(map(re.escape, names)) + r")(?!\w)")
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    docs = _docstrings(tree)
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) \
                and id(node) not in docs:
            hit = word.search(node.value)
            if hit:
                found.append((node.lineno, hit.group(1), node.value))
    return sorted(found)


def test_no_engine_module_names_a_catalogue_problem():
    names = _catalogue_names()
    assert "toy_car" in names and "n_link_rigid_pendulum" in names   # the list is the catalogue
    modules = _engine_modules()
    assert len(modules) > 50 and not any(p.parent.name == "problems" for p in modules)
    found = [f"{path.relative_to(PACKAGE.parent)}:{line}: {name!r} in {text[:60]!r}"
             for path in modules for line, name, text in _named(path, names)]
    assert found == [], "declare these facts on the problem class instead:\n" + "\n".join(found)


def test_the_scan_sees_a_name_in_a_table_key_and_in_a_message(tmp_path):
    # the scan itself must be able to fail: the old engine tables, reduced to three lines
    path = tmp_path / "table.py"
    path.write_text('"""A doc naming toy_car is an example."""\n'
                    'PROBES = {"toy_car": ([1.3, 0.0], "lagrange")}\n'
                    'HINT = "try mobile_robot, or a pendulum"\n'
                    'NOT_A_NAME = "toy_cart and dualmech.toy_car.x"\n')
    assert _named(path, _catalogue_names()) == [
        (2, "toy_car", "toy_car"), (3, "mobile_robot", "try mobile_robot, or a pendulum")]


# -- a teacher's own problem file ---------------------------------------------------------------
TEACHER = '''
"""A bob on a string thrown from the bottom: the string can only pull."""
import sympy as sp

from dualmech import (Coordinate, Frame, Lagrangian, NewtonEuler, Parameter, Particle, Point,
                      Probe, Problem, Reaction, coordinate, rate, rot_z, ACCELERATION, ANGLE,
                      FORCE, LENGTH, MASS)

m, a, g = sp.symbols("m a g", positive=True)
theta, x = coordinate("theta"), coordinate("x")


class ThrownBob(Problem):
    name = "thrown_bob"
    title = "Bob on a string, thrown from the bottom"
    source = "a teacher's notes"
    parameters = (Parameter(m, MASS, 0.5, (0.1, 2.0)), Parameter(a, LENGTH, 1.0, (0.5, 2.0)),
                  Parameter(g, ACCELERATION, 9.81, (9.0, 10.0)))
    coordinates = (Coordinate(theta, ANGLE, (-1.5, 1.5), (-8.0, 8.0), "from straight down"),)
    extra_coordinates = (Coordinate(x, LENGTH, (-0.9, 0.9), (-8.0, 8.0), "bob's abscissa"),)
    reactions = (Reaction("T", FORCE, "string on bob, towards the pivot"),)
    singular = (sp.cos(theta),)
    extra_models = ("lagrange_x",)
    unilateral = {"T": "the string goes slack"}
    probes = (Probe((0.0, 5.0), "lagrange_x", 1.0, "thrown past the horizontal"),)
    initial_state = {theta: 0.0, rate(theta): 5.0}

    def coordinate_maps(self):
        return {"lagrange_x": {x: a * sp.sin(theta)}}

    def newton_euler(self):
        O = Frame.ground("O")
        arm = O.child("arm", rot_z(theta))
        bob = Particle("bob", m, Point.origin(O, "pivot").locate("bob", -a * arm.y))
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction("T", bob, arm.y)
        ne.linear_momentum(bob, arm.x)
        ne.linear_momentum(bob, arm.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[theta])
        lg.kinetic("T", m * (a * rate(theta))**2 / 2)
        lg.potential("V", -m * g * a * sp.cos(theta))
        return lg.equations()

    def lagrange_x(self):
        lg = Lagrangian("lagrange_x", coordinates=[x])
        lg.kinetic("T", m * a**2 * rate(x)**2 / (2 * (a**2 - x**2)))
        lg.potential("V", -m * g * sp.sqrt(a**2 - x**2))
        return lg.equations()
'''

A, G, W0 = 1.0, 9.81, 5.0         # the file's string length, gravity, and rate at the bottom


def _time_to(angle: float) -> float:
    """Hand: the time the bob takes from the bottom to ``angle`` (energy integral)."""
    rate = lambda th: np.sqrt(W0**2 - 2 * G / A * (1 - np.cos(th)))  # noqa: E731
    return quad(lambda th: 1 / rate(th), 0.0, angle, epsabs=1e-14, epsrel=1e-13)[0]


SLACK = np.arccos((2 * G - A * W0**2) / (3 * G))      # 1.7546 rad: past the horizontal


@pytest.fixture(scope="module")
def bob(tmp_path_factory):
    path = tmp_path_factory.mktemp("teacher") / "thrown_bob.py"
    path.write_text(TEACHER)
    problem = load(f"{path}:ThrownBob")
    problem.validate()
    return problem


def test_teachers_string_goes_slack_where_the_hand_energy_balance_says(bob):
    assert bob.name not in _catalogue_names()
    loose = watch(bob, (0, 2), y0=[0.0, W0], rtol=1e-9, atol=1e-11).first
    tight = watch(bob, (0, 2), y0=[0.0, W0], rtol=1e-11, atol=1e-13).first
    assert tight.reaction == "T" and "the string goes slack" in str(tight)
    hand = _time_to(SLACK)
    # the tight run's error is at most the loose run's distance from it (plus rounding)
    assert abs(tight.time - hand) <= abs(loose.time - tight.time) + 8 * EPS * hand
    assert abs(tight.state["theta"] - SLACK) <= \
        abs(loose.state["theta"] - tight.state["theta"]) + 8 * EPS * SLACK


def test_teachers_initial_state_starts_the_chart_and_the_scene_ends_at_the_slack(bob):
    span = scene_span(bob, 2.0)           # from the declared initial_state, theta' = 5 rad/s
    # watch's default rtol 1e-9 over a run of some hundred steps: within 1e-8 s; any other
    # start (the default, at rest 60 % into the range) never slackens and runs the full 2 s
    assert span.t_end == pytest.approx(_time_to(SLACK), abs=1e-8)
    assert "T would have to change sign" in span.reason and "goes slack" in span.reason


def test_teachers_probe_runs_into_the_declared_singular_set(bob):
    a = atlas(bob, sections=("singularities",), progress=False)
    scan, report = a.results["singularities"]
    # the x form's mass m / cos^2(theta): unbounded at theta = +-pi/2, degeneracy ~ d^-2
    x_form = sorted((p for p in scan.points if p.formulation == "lagrange_x"),
                    key=lambda p: p.value)
    assert [p.value for p in x_form] == pytest.approx([-np.pi / 2, np.pi / 2], abs=1e-6)
    assert all(p.kind == "M unbounded" and round(p.order) == 2 and p.declared == "cos(theta)"
               for p in x_form)
    assert isinstance(report, ProbeReport) and report.formulation == "lagrange_x"
    assert report.y0 == [0.0, W0] and report.span == (0.0, 1.0)
    runs = {(r.method, r.mode): r for r in report.runs}
    horizontal = _time_to(np.pi / 2)      # the bob reaches x = a: the singular set
    guard = np.arccos(GARBAGE ** -0.5)    # where 1 / cos^2(theta) passes the guard's limit
    for method in ("RK45", "DOP853"):
        guarded = runs[method, "guarded"]
        # stopped on the safe side of the singular set, within the step that crosses the limit
        assert not guarded.success and guarded.message.startswith(("guard:", "the next step"))
        assert guarded.t_end < horizontal and guarded.max_kappa <= GARBAGE
        assert guarded.t_end <= _time_to(guard)
        # the run continues in the reference form, theta, which is regular there
        switched = runs[method, "switched"]
        assert switched.success and switched.error <= GARBAGE * report.rtol


# -- a study with nothing declared names the declaration --------------------------------------
def test_each_study_without_its_declaration_names_it(bob):
    class Bare(type(bob)):
        unilateral, probes, initial_state = {}, (), ()
    bare = Bare()
    a = atlas(bare, sections=("singularities", "stiffness"), progress=False)
    (hint,) = [r for r in a.results["singularities"] if isinstance(r, str)]
    assert hint == ("no probe run declared: add `probes = (Probe(state, formulation, duration, "
                    "why),)` to the problem class")
    assert a.skipped["stiffness"] == ("no stiff scene declared: add `stiff_scene = StiffScene("
                                      "parameter, state, duration, why)` to the problem class")
    report = watch(bare, (0, 0.1), y0=[0.0, W0])
    assert report.first is None and str(report).startswith(
        "no one-sided reaction declared: add `unilateral = {")


def test_fidelity_command_names_the_ladder_declaration(capsys):
    import argparse
    from dualmech.cli.studies import register
    parser = argparse.ArgumentParser(prog="dualmech")
    register(parser.add_subparsers(dest="command"))
    args = parser.parse_args(["fidelity", "falling_container"])
    assert args.func(args) == 2
    err = capsys.readouterr().err
    assert "add `fidelity_ladder = (FidelityRung(" in err and "LADDERS" not in err


def test_stiff_scene_without_an_exact_motion_is_measured_against_a_tight_radau_run():
    falling = get("falling_container")

    class NoExact(type(falling)):
        stiff_scene = dataclasses.replace(type(falling).stiff_scene, exact=None)
    kw = {"values": (1e4, 1e6), "methods": ("RK45",)}
    exact, tight = stiffness(falling, **kw).rows, stiffness(NoExact(), **kw).rows
    for e, r in zip(exact, tight):
        assert (e["value"], e["steps"]) == (r["value"], r["steps"])
        assert e["error"] > 1e-4            # RK45 at rtol 1e-6 on the stiff spring
        # |error against free fall - error against Radau| <= |Radau - free fall|: Radau's
        # rtol 1e-12 of the 6 m/s rate scale, a few steps' worth
        assert abs(e["error"] - r["error"]) <= 10 * 1e-12 * 6.0


# -- bad declarations are refused, each with what to fix ----------------------------------------
def _mistakes(problem) -> list[str]:
    with pytest.raises(ProblemError) as info:
        problem.validate()
    return str(info.value).split("\n  - ")[1:]


def test_bad_declarations_are_each_named(bob):
    theta = bob.coordinates[0].function

    class Bad(type(bob)):
        unilateral = {"N": "the bob lifts off", "T": ""}
        probes = (Probe((0.0, 5.0, 1.0), "lagrange_y", 1.0),)
        stiff_scene = StiffScene("k", (0.0, 0.0), 0.5)
        fidelity_ladder = (FidelityRung("alone", type(bob)),)
        chaotic_state = (1.0,)
        initial_state = {theta.diff(theta.args[0]): 2.0}
    assert _mistakes(Bad()) == [
        "`unilateral`: `N` is not a declared reaction (declared: T)",
        "`unilateral['T']` must say in words what happens when the reaction would change "
        "sign, got ''",
        "`probes[0].state` has 3 numbers; it needs 2: the coordinates theta, then their rates",
        "`probes[0]`: formulation `lagrange_y` is not one of the models newton_euler, lagrange, "
        "lagrange_x",
        "`stiff_scene.parameter`: `k` is not a declared parameter (declared: m, a, g)",
        "`fidelity_ladder` needs at least two rungs (a simpler model below the richest); the "
        "small-oscillation rung is added without a declaration",
        "`chaotic_state` has 1 number; it needs 2: the coordinates theta, then their rates",
        "`initial_state` gives no value for theta",
    ]


def test_a_ladder_must_end_in_a_problem_holding_the_reactions_it_neglects(bob):
    Bob = type(bob)

    class Ladder(Bob):
        fidelity_ladder = (FidelityRung("no string", Bob, "the string", ("S",)),
                           FidelityRung("string", Bob))
    assert _mistakes(Ladder()) == ["`fidelity_ladder` rung 'no string': `S` is not a reaction "
                                   "of the richest rung (its reactions: T)"]

    class NotAProblem(Bob):
        fidelity_ladder = (FidelityRung("a", Bob), FidelityRung("b", lambda: 42))
    assert _mistakes(NotAProblem()) == ["`fidelity_ladder`: the richest rung 'b' must give a "
                                        "problem, got 42"]


def test_a_state_mapping_may_only_name_coordinates_and_their_rates(bob):
    theta = bob.coordinates[0].function
    assert state_vector(bob, {theta: 0.2}) == [0.2, 0.0]
    with pytest.raises(ValueError, match=r"x\(t\).* is not a coordinate of the reference model"):
        state_vector(bob, {theta: 0.2, bob.extra_coordinates[0].function: 0.5})


@pytest.mark.parametrize("make, error, says", [
    (lambda: Probe((0.0, 1.0), "lagrange", 0.0), ValueError, "positive number of seconds"),
    (lambda: Probe((0.0, 1.0), "", 1.0), ValueError, "`Probe.formulation` is empty"),
    (lambda: Probe("0, 1", "lagrange", 1.0), TypeError, "must be numbers, got the text"),
    (lambda: Probe((0.0, float("nan")), "lagrange", 1.0), ValueError, "must be finite"),
    (lambda: StiffScene("k", (0.0, 0.0), 1.0, exact=5), TypeError, "must be a function"),
    (lambda: FidelityRung("rung", "toy_car"), TypeError, "a problem class or a function"),
], ids=["duration", "formulation", "text-state", "nan-state", "exact", "rung-problem"])
def test_a_malformed_declaration_is_refused_where_it_is_written(make, error, says):
    with pytest.raises(error, match=re.escape(says)):
        make()


def test_help_of_problem_documents_every_declaration():
    doc = dualmech.Problem.__doc__
    for attr in ("unilateral", "probes", "stiff_scene", "fidelity_ladder", "chaotic_state",
                 "initial_state"):
        assert f"\n    {attr} :" in doc, attr


def test_a_wrong_drawing_or_chart_scene_is_listed_by_validate():
    """Each mistake in `drawing` and `chart_scenes` is named (the pendulum's parameters are
    M, a, g; its coordinate theta)."""
    import sympy as sp

    from dualmech import ChartScene, Drawing
    base = type(get("simple_pendulum"))
    th = base.coordinates[0].function
    b = sp.Symbol("b", positive=True)

    class Wrong(base):
        drawing = Drawing({"pivot": (0, 0), "bob": (b * sp.sin(th), -b * sp.cos(th))},
                          (("pivot", "bob"),))
        chart_scenes = (ChartScene({"G": 3.0}, (), "typo"),
                        ChartScene({"g": 1e6}, (), "out of range"),
                        ChartScene({}, (1.0, 2.0, 3.0), "a state too long"))

    with pytest.raises(ProblemError) as err:
        Wrong().validate()
    text = str(err.value)
    assert "`drawing.points['bob']` uses b" in text
    assert "`chart_scenes[0]`: `G` is not a declared parameter" in text
    assert "`chart_scenes[1]`: `g` = 1000000.0 is outside its declared range" in text
    assert "`chart_scenes[2].state`" in text

    class Right(base):
        a = base.parameters[1].symbol
        drawing = Drawing({"pivot": (0, 0), "bob": (a * sp.sin(th), -a * sp.cos(th))},
                          (("pivot", "bob"),))
        chart_scenes = (ChartScene({"g": 3.0}, (), "weaker gravity"),)

    Right().validate()


def test_a_problem_with_lengths_fixed_at_numbers_declares_the_dimension_audit_unchecked():
    """A pendulum written as a teacher would, its length fixed at 4/5 m (a number, as the
    benchmark bicycle's geometry is): the audit can no longer read a length in the equations
    and flags terms; a problem that declares ``dimensions_unchecked`` gets the reason instead
    of the list, in the text and the JSON, and the verdict is unchanged (by hand: both models
    are M (4/5)^2 theta'' + M g (4/5) sin(theta) = 0 up to a factor)."""
    import sympy as sp
    from dualmech import (ACCELERATION, ANGLE, FORCE, MASS, Coordinate, Frame, Lagrangian,
                          NewtonEuler, Parameter, Particle, Point, Problem, Reaction,
                          coordinate, rate)
    from dualmech.verify.check import compare
    th = coordinate("theta")
    M, g = sp.symbols("M g", positive=True)
    ell = sp.Rational(4, 5)

    class Fixed(Problem):
        name = "fixed_length_pendulum"
        title = "A pendulum 4/5 m long"
        source = "a teacher's own"
        reactions = (Reaction("T", FORCE, "string on bob, towards the pivot"),)
        parameters = (Parameter(M, MASS, 1.0, (0.1, 10.0), "bob"),
                      Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravity"))
        coordinates = (Coordinate(th, ANGLE, (-2.0, 2.0), (-3.0, 3.0), "angle"),)

        def newton_euler(self):
            O = Frame.ground("O")
            arm = O.child("arm", sp.Matrix([[sp.cos(th), -sp.sin(th), 0],
                                            [sp.sin(th), sp.cos(th), 0], [0, 0, 1]]))
            bob = Particle("bob", M, Point.origin(O).locate("bob", -ell * arm.y))
            ne = NewtonEuler("newton_euler", coordinates=[th], ground=O)
            ne.gravity(-g * O.y)
            ne.reaction("T", bob, arm.y)
            ne.linear_momentum(bob, arm.x)
            ne.linear_momentum(bob, arm.y)
            return ne.equations()

        def lagrange(self):
            lg = Lagrangian("lagrange", coordinates=[th])
            lg.kinetic("T", M * (ell * rate(th))**2 / 2)
            lg.potential("V", -M * g * ell * sp.cos(th))
            return lg.equations()

    assert Fixed().dimension_audit()              # the audit flags the fixed length's terms
    Unchecked = type("Unchecked", (Fixed,), {"dimensions_unchecked": "lengths fixed at numbers"})
    c = compare(Unchecked())
    assert c.equivalent and c.dimension_audit == []
    assert "dimension audit: not run (lengths fixed at numbers)" in c.text()
    assert c.to_dict()["dimensions_unchecked"] == "lengths fixed at numbers"
