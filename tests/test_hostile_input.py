"""Hostile input to the public API: text is never evaluated, bad values get clear errors.

Issue 6, points 5 and 6.  Every argument of the public API that takes an expression (angles,
masses, forces, energies, constraints, substitutions, parameter values...) is given hostile
text -- Python code that would create a marker file if it ran, a ``lambda``, an attribute
walk to ``object``, a three-letter string that ``sympify`` would turn into symbols, bytes --
and must answer with a ``TypeError`` or ``ValueError`` whose message says what was given
(the text, or that text is refused), never a Python-internal message such as "object has no
attribute", and never run anything: the marker file must not exist after any test.

Builders are driven to the end (``equations()``, a velocity, a kinetic energy) so that text
stored silently and refused later still counts -- as long as the error is clear.

The second half checks the numeric and comparison entry points' own argument checks:
misspelt parameter names (the close one suggested), out-of-range, NaN and infinite values,
empty and infinite time spans, ``points <= 0``.

Cases that expose a bug still open are marked ``xfail(strict=True)`` with the reason; they
start passing (and so fail as XPASS) when the fix lands -- then drop the mark.
"""
from __future__ import annotations

import math
import tempfile
import warnings
from pathlib import Path

import pytest
import sympy as sp

from dualmech import (EquationSet, Frame, Lagrangian, MassProperties, NewtonEuler, Particle,
                      Point, RigidBody, Vector, composite, coordinate, cuboid, parallel_axis,
                      point_mass, rot_axis, rot_x, rot_y, rot_z, skew, solid_cylinder,
                      solid_sphere, t, thin_disk, thin_rod)
from dualmech.model.dimensions import ACCELERATION, FORCE, LENGTH, MASS, STIFFNESS
from dualmech.model.problem import Coordinate, Parameter, Problem, Published, Reaction

# the same name in every xdist worker (parametrize ids must agree); removed before each check
MARKER = Path(tempfile.gettempdir()) / "PWNED_dualmech_hostile_input"

#: hostile values given to every expression-taking argument
HOSTILE = {
    "code": f'__import__("os").system("touch {MARKER}")',
    "lambda": "lambda: 0",
    "object": "().__class__.__bases__[0]",
    "letters": "xyz",          # sympify would make three symbols of it
    "bytes": b"1+1",
}

#: phrases of messages that explain Python's internals instead of the caller's mistake
INTERNAL = ("object has no attribute", "can't multiply sequence", "unsupported operand",
            "bad operand type", "data type not understood", "could not convert",
            "not supported between", "sympifyerror", "can't calculate derivative",
            "is not callable", "object is not iterable", "not subscriptable")


@pytest.fixture(autouse=True)
def _nothing_ran():
    """No test may create the marker file (the hostile code would have run)."""
    MARKER.unlink(missing_ok=True)
    yield
    ran = MARKER.exists()
    MARKER.unlink(missing_ok=True)
    assert not ran, "hostile text was evaluated: the marker file was created"


def assert_refused_clearly(call, value) -> None:
    """``call(value)`` raises TypeError/ValueError saying what was given, in the caller's words."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")   # sympy deprecation noise is not the point here
        try:
            result = call(value)
        except (TypeError, ValueError) as exc:
            msg = str(exc)
        except Exception as exc:  # noqa: BLE001 - any other exception is the failure reported
            pytest.fail(f"{type(exc).__name__} instead of TypeError/ValueError: {exc}")
        else:
            pytest.fail(f"hostile input {value!r} was accepted, giving {result!r:.200}")
    low = msg.lower()
    internal = [p for p in INTERNAL if p in low]
    assert not internal, f"the message explains Python's internals ({internal}): {msg}"
    shown = {repr(value)[:12], str(value)[:12]}
    assert "text" in low or "string" in low or any(s in msg for s in shown), \
        f"the message does not say what was given ({value!r}): {msg}"


# -- a small world to build in ----------------------------------------------------------
th, x = coordinate("theta"), coordinate("x")
m, k, g = sp.symbols("m k g", positive=True)
O = Frame.ground("O")
A = O.child("A", rot_z(th))
PT = Point.origin(O).locate("P", -A.y)
BALL = Particle("ball", m, PT)
ROD = RigidBody("rod", m, PT, A, sp.eye(3))
PEND = EquationSet("pend", (th,), (m * th.diff(t, 2) + k * sp.sin(th),))
D = lambda q, n=1: q.diff(t, n)  # noqa: E731


def _ne(load):
    """A Newton--Euler model of the ball with ``load(ne)`` added, built to the end."""
    ne = NewtonEuler(coordinates=[th], ground=O)
    load(ne)
    ne.linear_momentum(BALL, A.x)
    ne.angular_momentum(ROD, O.z, about=Point.origin(O))
    return ne.equations()


def _lg(term):
    """A Lagrangian of the pendulum with ``term(lg)`` added, built to the end."""
    lg = Lagrangian(coordinates=[th])
    lg.kinetic("T", m * D(th)**2 / 2)
    term(lg)
    return lg.equations()


def _compare_with(**declared):
    """``compare`` a correct one-coordinate problem whose declarations get ``declared``."""
    from dualmech.verify.check import compare
    dims = dict(pdim=MASS, pdefault=2.0, cdim=LENGTH, cdomain=None, rdim=FORCE)
    dims.update(declared)
    N = sp.Symbol("N", real=True)

    class Spring(Problem):
        name, title, source = "spring", "Block on a spring, on a floor", "test: by hand"
        parameters = (Parameter(m, dims["pdim"], dims["pdefault"], (0.1, 10.0)),
                      Parameter(k, STIFFNESS, 50.0, (1.0, 500.0)),
                      Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)))
        coordinates = (Coordinate(x, dims["cdim"], (-0.5, 0.5), domain=dims["cdomain"]),)
        reactions = (Reaction("N", dims["rdim"], "floor on block, up"),)

        def newton_euler(self):
            return EquationSet("newton_euler", (x,), (-k * x - m * D(x, 2), N - m * g),
                               unknowns=(N,))

        def lagrange(self):
            lg = Lagrangian(coordinates=[x])
            lg.kinetic("T", m * D(x)**2 / 2)
            lg.potential("V", k * x**2 / 2)
            return lg.equations()

    return compare(Spring(), points=2)


def _steady(h):
    from dualmech.model.steady import steady_conditions
    return steady_conditions(PEND, [], {m: h})


def _steady_rate(h):
    from dualmech.model.steady import steady_rates
    return steady_rates(PEND, [], h)


def _inputs(h):
    from dualmech.model.inverse import required_inputs
    return required_inputs(PEND, [h], {th: t})


def _inputs_motion(h):
    from dualmech.model.inverse import required_inputs
    return required_inputs(PEND, [k], {th: h})


def _peak(h):
    from dualmech.model.inverse import peak
    return peak(h, (0.0, 1.0))


def _peak_params(h):
    from dualmech.model.inverse import peak
    return peak(sp.sin(m * t), (0.0, 1.0), {m: h})


def _numeric_params(h):
    from dualmech.numeric import NumericModel
    return NumericModel(PEND, {m: h, k: 1.0}).accelerations(0.0, [0.1], [0.0])


def _state_function(h):
    from dualmech.numeric import StateFunction
    return StateFunction([h], [th], {m: 1.0})


def _dotted(h):
    from dualmech.verify.display import dotted
    return dotted(h)


def _tidy(h):
    from dualmech.verify.display import tidy
    return tidy(h)


#: name -> call taking the hostile value; every expression-taking argument of the public API
CASES = {
    # kinematics
    "rot_x(angle)": lambda h: rot_x(h),
    "rot_y(angle)": lambda h: rot_y(h),
    "rot_z(angle)": lambda h: rot_z(h),
    "rot_axis(axis, angle)": lambda h: rot_axis((0, 0, 1), h),
    "rot_axis(axis component)": lambda h: rot_axis((h, 0, 0), th),
    "rot_axis(axis)": lambda h: rot_axis(h, th),
    "skew(component)": lambda h: skew([h, 0, 0]),
    "skew(w)": lambda h: skew(h),
    "Frame.child(rotation)": lambda h: O.child("B", h),
    "Frame.child(rotation entry)": lambda h: O.child("B", [[h, 0, 0], [0, 1, 0], [0, 0, 1]]),
    "Frame.child(origin)": lambda h: Point.origin(O.child("B", None, h)).vel(O),
    "Frame.vector(component)": lambda h: O.vector(h, 0, 0),
    "Frame.vector(components)": lambda h: O.vector(h),
    "Frame.vector([components])": lambda h: O.vector([h, 0, 0]),
    "Vector(components)": lambda h: Vector(O, h),
    "Vector(component)": lambda h: Vector(O, [h, 0, 0]),
    "Vector.from_se(component)": lambda h: Vector.from_se(O, [h, 0, 0], {}),
    "Vector.dot_se(other)": lambda h: O.x.dot_se(h),
    "Vector * scalar": lambda h: O.x * h,
    "scalar * Vector": lambda h: h * O.x,
    "Vector / scalar": lambda h: O.x / h,
    "Vector.diff(var)": lambda h: (th * O.x).diff(h, O),
    "Vector.subs(old, new)": lambda h: (m * O.x).subs(m, h),
    "Vector.subs({old: new})": lambda h: (m * O.x).subs({m: h}),
    "Point.locate(r)": lambda h: Point.origin(O).locate("Q", h).vel(O),
    # bodies and inertia helpers
    "Particle(mass)": lambda h: Particle("p", h, PT).kinetic_energy(O),
    "RigidBody(mass)": lambda h: RigidBody("b", h, PT, A, sp.eye(3)).kinetic_energy(O),
    "RigidBody(inertia)": lambda h: RigidBody("b", m, PT, A, h),
    "RigidBody(inertia entry)": lambda h: RigidBody("b", m, PT, A, [[h, 0, 0], [0, 1, 0],
                                                                    [0, 0, 1]]),
    "thin_rod(m)": lambda h: thin_rod(h, 1),
    "thin_rod(length)": lambda h: thin_rod(m, h),
    "thin_disk(radius)": lambda h: thin_disk(m, h),
    "solid_cylinder(radius)": lambda h: solid_cylinder(m, h, 1),
    "solid_sphere(m)": lambda h: solid_sphere(h, 1),
    "cuboid(b)": lambda h: cuboid(m, 1, h, 1),
    "point_mass(m)": lambda h: point_mass(h),
    "parallel_axis(d)": lambda h: parallel_axis(sp.eye(3), m, h),
    "parallel_axis(mass)": lambda h: parallel_axis(sp.eye(3), h, sp.Matrix([1, 0, 0])),
    "parallel_axis(inertia)": lambda h: parallel_axis(h, m, sp.Matrix([1, 0, 0])),
    "composite(mass)": lambda h: composite([(h, sp.eye(3), [0, 0, 0])]),
    "composite(inertia)": lambda h: composite([(m, h, [0, 0, 0])]),
    "composite(centre)": lambda h: composite([(m, sp.eye(3), h)]),
    "MassProperties.inertia_about(point)":
        lambda h: MassProperties(m, sp.zeros(3, 1), sp.eye(3)).inertia_about(h),
    # the direct form
    "NewtonEuler.force(vector)": lambda h: _ne(lambda ne: ne.force("f", BALL, h)),
    "NewtonEuler.torque(vector)": lambda h: _ne(lambda ne: ne.torque("f", ROD, h)),
    "NewtonEuler.gravity(g)": lambda h: _ne(lambda ne: ne.gravity(h)),
    "NewtonEuler.linear_spring(k)":
        lambda h: _ne(lambda ne: ne.linear_spring("s", BALL, h, th, O.x)),
    "NewtonEuler.linear_spring(extension)":
        lambda h: _ne(lambda ne: ne.linear_spring("s", BALL, k, h, O.x)),
    "NewtonEuler.linear_spring(direction)":
        lambda h: _ne(lambda ne: ne.linear_spring("s", BALL, k, th, h)),
    "NewtonEuler.spring_between(k)": lambda h: _ne(lambda ne: ne.spring_between(
        "s", h, 1, (BALL, PT), (None, Point.origin(O)))),
    "NewtonEuler.spring_between(free_length)": lambda h: _ne(lambda ne: ne.spring_between(
        "s", k, h, (BALL, PT), (None, Point.origin(O)))),
    "NewtonEuler.linear_damper(c)":
        lambda h: _ne(lambda ne: ne.linear_damper("c", BALL, h, D(th), O.x)),
    "NewtonEuler.linear_damper(rate)":
        lambda h: _ne(lambda ne: ne.linear_damper("c", BALL, k, h, O.x)),
    "NewtonEuler.torsional_spring(kt)":
        lambda h: _ne(lambda ne: ne.torsional_spring("s", ROD, h, th, O.z)),
    "NewtonEuler.torsional_spring(angle)":
        lambda h: _ne(lambda ne: ne.torsional_spring("s", ROD, k, h, O.z)),
    "NewtonEuler.torsional_damper(ct)":
        lambda h: _ne(lambda ne: ne.torsional_damper("c", ROD, h, D(th), O.z)),
    "NewtonEuler.reaction(direction)": lambda h: _ne(lambda ne: ne.reaction("N", BALL, h)),
    "NewtonEuler.reaction_torque(direction)":
        lambda h: _ne(lambda ne: ne.reaction_torque("M", ROD, h)),
    "NewtonEuler.linear_momentum(direction)":
        lambda h: _ne(lambda ne: ne.linear_momentum(BALL, h)),
    "NewtonEuler.angular_momentum(direction)":
        lambda h: _ne(lambda ne: ne.angular_momentum(ROD, h)),
    "NewtonEuler.equation(parts)":
        lambda h: _ne(lambda ne: ne.equation("e", {"a": h, "b": D(th, 2)})),
    # the indirect form
    "Lagrangian.kinetic(T)": lambda h: _lg(lambda lg: lg.kinetic("T2", h)),
    "Lagrangian.potential(V)": lambda h: _lg(lambda lg: lg.potential("V", h)),
    "Lagrangian.dissipation(R)": lambda h: _lg(lambda lg: lg.dissipation("R", h)),
    "Lagrangian.spring(k)": lambda h: _lg(lambda lg: lg.spring("s", h, th)),
    "Lagrangian.spring(extension)": lambda h: _lg(lambda lg: lg.spring("s", k, h)),
    "Lagrangian.damper(c)": lambda h: _lg(lambda lg: lg.damper("c", h, D(th))),
    "Lagrangian.damper(rate)": lambda h: _lg(lambda lg: lg.damper("c", k, h)),
    "Lagrangian.generalized_force(Q entry)":
        lambda h: _lg(lambda lg: lg.generalized_force("Q", [h])),
    "Lagrangian.generalized_force(Q)": lambda h: _lg(lambda lg: lg.generalized_force("Q", h)),
    "Lagrangian.force_at(force)": lambda h: _lg(lambda lg: lg.force_at("F", h, PT, O)),
    "Lagrangian.torque_on(torque)": lambda h: _lg(lambda lg: lg.torque_on("M", h, A, O)),
    "Lagrangian.gravity(g)": lambda h: _lg(lambda lg: lg.gravity(h, [BALL], O)),
    "Lagrangian.constraint(g)": lambda h: _lg(lambda lg: lg.constraint("c", h)),
    "Lagrangian.velocity_constraint(coefficients)":
        lambda h: _lg(lambda lg: lg.velocity_constraint("c", [h])),
    "Lagrangian.velocity_constraint(rest)":
        lambda h: _lg(lambda lg: lg.velocity_constraint("c", [1], h)),
    "Lagrangian.prescribe(motion)": lambda h: _lg(lambda lg: lg.prescribe(th, h)),
    "Lagrangian.prescribe(q)": lambda h: _lg(lambda lg: lg.prescribe(h, t)),
    # equation sets
    "EquationSet(equations)": lambda h: EquationSet("e", (th,), (h,)),
    "EquationSet(coordinates)": lambda h: EquationSet("e", (h,), (D(th, 2),)),
    "EquationSet(unknowns)": lambda h: EquationSet("e", (th,), (D(th, 2),), (h,)),
    "EquationSet.substitute(value)": lambda h: PEND.substitute({m: h}),
    "EquationSet.substitute(key)": lambda h: PEND.substitute({h: 1}),
    "EquationSet.change_coordinates(mapping)":
        lambda h: PEND.change_coordinates((th,), {th: h}),
    "EquationSet.equilibria(values)": lambda h: PEND.equilibria({m: h}),
    "EquationSet.linearize(equilibrium)": lambda h: PEND.linearize({th: h}),
    "EquationSet.natural_frequencies(values)":
        lambda h: PEND.natural_frequencies(None, {m: h, k: 1}),
    # declarations
    "Parameter(symbol)": lambda h: Parameter(h, MASS, 1.0, (0.5, 2.0)),
    "Parameter(default)": lambda h: _compare_with(pdefault=h),
    "Parameter(range)": lambda h: Parameter(m, MASS, 1.0, (h, 2.0)),
    "Parameter(dimension)": lambda h: _compare_with(pdim=h),
    "Coordinate(function)": lambda h: Coordinate(h, LENGTH, (0.0, 1.0)),
    "Coordinate(range)": lambda h: Coordinate(th, LENGTH, (0.0, h)),
    "Coordinate(rate_range)": lambda h: Coordinate(th, LENGTH, (0.0, 1.0), (h, 1.0)),
    "Coordinate(dimension)": lambda h: _compare_with(cdim=h),
    "Coordinate(domain)": lambda h: _compare_with(cdomain=h),
    "Coordinate(domain bound)": lambda h: _compare_with(cdomain=(h, 1)),
    "Reaction(dimension)": lambda h: _compare_with(rdim=h),
    "Published(printed)": lambda h: Published("p", "equation", (h,)),
    "Published(reference)": lambda h: Published("p", "expression", (m,), (h,)),
    "Published(kind)": lambda h: Published("p", h, (m,)),
    # steady motions, inverse dynamics, numbers, display
    "steady_conditions(values)": _steady,
    "steady_rates(solve_for)": _steady_rate,
    "required_inputs(inputs)": _inputs,
    "required_inputs(motion)": _inputs_motion,
    "peak(expr)": _peak,
    "peak(params)": _peak_params,
    "NumericModel(params)": _numeric_params,
    "StateFunction(exprs)": _state_function,
    "verify.display.dotted(expr)": _dotted,
    "verify.display.tidy(expr)": _tidy,
}

_EVALUATES = "evaluates the text (sympify without strict)"
_SILENT = "text accepted silently or refused with a Python-internal message"
#: open bugs: case -> (reason, hostile kinds affected; None = all)
KNOWN: dict = {}


def _params():
    out = []
    for name, call in CASES.items():
        reason, kinds = KNOWN.get(name, (None, None))
        for kind, value in HOSTILE.items():
            marks = []
            if reason and (kinds is None or kind in kinds):
                marks = [pytest.mark.xfail(strict=True, reason=reason)]
            out.append(pytest.param(call, value, id=f"{name}-{kind}", marks=marks))
    return out


@pytest.mark.parametrize("call, value", _params())
def test_text_is_refused_and_never_evaluated(call, value):
    assert_refused_clearly(call, value)


# -- names are data, never code -----------------------------------------------------------------
class _Named(Problem):
    """A block on a spring whose coordinate, parameter and reaction carry hostile names.

    Names reach generated code (the numeric right-hand side, the explanation's evaluator);
    they must stay names there.  ``factor = 2`` makes the Lagrangian wrong (``V = k x^2``), so
    the explanation of a mismatch runs too.
    """

    name, title, source = "named", "Block on a spring with hostile names", "test: by hand"
    q = coordinate(HOSTILE["code"])
    mass = sp.Symbol(HOSTILE["code"] + "m", positive=True)
    force = sp.Symbol(HOSTILE["code"] + "N", real=True)
    parameters = (Parameter(mass, MASS, 1.0, (0.5, 2.0)),
                  Parameter(k, STIFFNESS, 1.0, (0.5, 2.0)))
    coordinates = (Coordinate(q, LENGTH, (-1.0, 1.0)),)
    reactions = (Reaction(force.name, FORCE, "floor on block, up"),)
    factor = 1

    def newton_euler(self):
        q, mass = self.q, self.mass
        return EquationSet("newton_euler", (q,), (-k * q - mass * D(q, 2), self.force - mass),
                           unknowns=(self.force,))

    def lagrange(self):
        lg = Lagrangian(coordinates=[self.q])
        lg.kinetic("T", self.mass * D(self.q)**2 / 2)
        lg.potential("V", self.factor * k * self.q**2 / 2)
        return lg.equations()


class _NamedWrong(_Named):
    factor = 2


def test_hostile_names_are_never_code():
    """Compare (right and wrong), explain and simulate with hostile names: nothing runs."""
    from dualmech.verify.check import compare
    from dualmech.numeric import simulate
    right = compare(_Named(), points=2)
    assert right.equivalent
    wrong = compare(_NamedWrong(), points=2)
    assert not wrong.equivalent
    assert wrong.mismatches and all(str(mm) for mm in wrong.mismatches)
    traj = simulate(_Named(), t_span=(0.0, 0.1), samples=3)
    # m q'' = -k q from q0 = 0.2 (60 % into the range), at rest; m = k = 1: q = 0.2 cos t
    assert traj.q[0, -1] == pytest.approx(0.2 * math.cos(0.1), rel=1e-7)
    assert traj.reactions[_Named.force.name] == pytest.approx([1.0] * 3)


# -- declarations -------------------------------------------------------------------------------
def test_parameter_given_text_says_to_use_a_symbol():
    with pytest.raises(TypeError, match=r"sp\.Symbol\('m'"):
        Parameter("m", MASS, 1.0, (0.5, 2.0))


def test_coordinate_given_text_says_to_use_coordinate():
    with pytest.raises(TypeError, match=r"coordinate\('theta'\)"):
        Coordinate("theta", LENGTH, (0.0, 1.0))


def test_unused_declarations_are_mistakes_named_in_one_error():
    from dualmech.model.problem import ProblemError

    class Stale(_Named):
        name = "stale"
        reactions = _Named.reactions + (Reaction("F_typo", FORCE, "nowhere"),)
        extra_coordinates = (Coordinate(coordinate("y"), LENGTH, (0.0, 1.0)),)

    with pytest.raises(ProblemError) as info:
        Stale().validate()
    msg = str(info.value)
    assert "2 mistake(s)" in msg
    assert "reaction `F_typo` is declared but no model uses it" in msg
    assert "coordinate `y` is declared but no model uses it" in msg


# -- simulate, problem_parameters, compare: their own arguments ----------------------------------
@pytest.fixture(scope="module")
def pendulum():
    from dualmech.problems import get
    return get("simple_pendulum")   # parameters M, a, g


@pytest.mark.parametrize("key, suggested", [("gg", "g"), ("G", "g"), (sp.Symbol("A"), "a"),
                                            ("m", "M")])
def test_misspelt_parameter_suggests_the_close_one(pendulum, key, suggested):
    from dualmech.numeric import simulate
    with pytest.raises(ValueError) as info:
        simulate(pendulum, t_span=(0.0, 0.1), params={key: 1.0})
    msg = str(info.value)
    assert "`params`" in msg and f"did you mean {suggested!r}" in msg
    assert "M, a, g" in msg


def test_unknown_parameter_lists_the_known_ones(pendulum):
    from dualmech.numeric import right_hand_side
    with pytest.raises(ValueError, match=r"unknown parameter 'L'.*M, a, g"):
        right_hand_side(pendulum, {"L": 2.0})


@pytest.mark.parametrize("value, says", [
    (-1.0, r"outside the admissible range \[1, 20\]"), (25.0, r"outside .*\[1, 20\]"),
    (math.nan, "must be finite"), (math.inf, "must be finite"), (-math.inf, "must be finite"),
    ("9.81 m/s^2", "is not a number"), (1j, "is not a number"), (None, "is not a number"),
    (HOSTILE["code"], "is not a number"),
    pytest.param(True, "number"),
])
def test_bad_parameter_values_are_refused_with_the_name(pendulum, value, says):
    from dualmech.numeric import problem_parameters
    with pytest.raises(ValueError, match=says) as info:
        problem_parameters(pendulum, {"g": value})
    assert "`params`: g" in str(info.value)


def test_ranges_may_be_left_on_purpose(pendulum):
    from dualmech.numeric import problem_parameters
    g = sp.Symbol("g", positive=True)
    assert problem_parameters(pendulum, {"g": 25.0}, check_ranges=False)[g] == 25.0


@pytest.mark.parametrize("params", [
    [("g", 9.0)], "g=9.0", 9.0,
])
def test_params_that_are_not_a_mapping_are_refused(pendulum, params):
    from dualmech.numeric import problem_parameters
    with pytest.raises(TypeError, match="`params`"):
        problem_parameters(pendulum, params)


@pytest.mark.parametrize("t_span, says", [
    ((0.0, 0.0), "empty"), ((1.0, 1.0), "empty"), ((0.0, math.inf), "finite"),
    ((0.0, math.nan), "finite"), ((-math.inf, 0.0), "finite"), ((math.nan, 1.0), "finite"),
    ((), "two numbers"), ((0.0,), "two numbers"), ((0.0, 1.0, 2.0), "two numbers"),
    (None, "two numbers"), ("0,1", "two numbers"), (5.0, "two numbers"),
])
def test_bad_time_spans_are_refused(pendulum, t_span, says):
    from dualmech.numeric import simulate
    with pytest.raises(ValueError, match=says) as info:
        simulate(pendulum, t_span=t_span)
    assert "`t_span`" in str(info.value)


@pytest.mark.parametrize("y0, says", [
    ([math.nan, 0.0], "finite"), ([0.1], "must hold 2 numbers"),
    pytest.param(["a", "b"], "`y0`"),
])
def test_bad_initial_states_are_refused(pendulum, y0, says):
    from dualmech.numeric import simulate
    with pytest.raises(ValueError, match=says) as info:
        simulate(pendulum, t_span=(0.0, 0.1), y0=y0)
    assert "`y0`" in str(info.value)


@pytest.mark.parametrize("samples", [1, 0, -3, 2.5, True, "10"])
def test_bad_sample_counts_are_refused(pendulum, samples):
    from dualmech.numeric import simulate
    with pytest.raises(ValueError, match="`samples`"):
        simulate(pendulum, t_span=(0.0, 0.1), samples=samples)


@pytest.mark.parametrize("points", [0, -1, 1.5, True, "3", None])
def test_points_must_be_a_positive_integer(pendulum, points):
    from dualmech.verify.check import compare
    with pytest.raises(ValueError, match="`points` must be a positive integer"):
        compare(pendulum, points=points)


class _WorkStarted(Exception):
    """Raised by a stand-in for the judge: the argument check let the call through."""


def test_absurd_point_counts_are_refused_before_any_work(pendulum, monkeypatch):
    from dualmech.verify import check

    def judge(*args, **kwargs):
        raise _WorkStarted
    monkeypatch.setattr(check, "judge", judge)
    with pytest.raises(ValueError, match="`points`"):
        check.compare(pendulum, points=10**100)


# -- the library's own converters never parse text ----------------------------------------------
def _bridge_init(h):
    from dualmech.model._algebra import Bridge
    return Bridge([h])


def _bridge_se(h):
    from dualmech.model._algebra import Bridge
    return Bridge().se(h)


def _bridge_sp(h):
    from dualmech.model._algebra import Bridge
    return Bridge().sp(h)


def _to_se(h):
    from dualmech.model._algebra import to_se
    return to_se(h)


@pytest.mark.parametrize("convert", [_bridge_init, _bridge_se, _bridge_sp, _to_se],
                         ids=["Bridge(exprs)", "Bridge.se", "Bridge.sp", "to_se"])
@pytest.mark.parametrize("kind", sorted(HOSTILE))
def test_internal_converters_refuse_text_before_any_parser(convert, kind):
    """The sympify calls of the derivation's sympy/symengine bridge take the library's own
    expressions only: ``strict=True`` (and ``to_se``'s check) refuse text, so even a string
    that reached them by mistake is never parsed (the marker file is never written)."""
    MARKER.unlink(missing_ok=True)
    with pytest.raises((TypeError, ValueError, sp.SympifyError)):
        convert(HOSTILE[kind])
    assert not MARKER.exists()
