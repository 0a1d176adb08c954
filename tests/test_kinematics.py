"""Frames, rotation matrices, angular velocity, the transport theorem and point kinematics.

Symbolic claims are decided exactly: small expressions by ``simplify``, larger ones by
evaluation at random rational points (:class:`dualmech.exact.form.ExactForm`).
"""
from __future__ import annotations

import random

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from dualmech.model.equations import to_plain
from dualmech.exact.form import ExactForm
from dualmech.model.kinematics import (Frame, Point, RelativeMotion, Vector, coordinate, rot_axis,
                                      rot_x, rot_y, rot_z, skew, t, unskew)

a = sp.Symbol("a", real=True)
ROTATIONS = {"x": rot_x, "y": rot_y, "z": rot_z}


def is_zero_matrix(m) -> bool:
    return all(sp.simplify(x) == 0 for x in sp.Matrix(m))


def vanishes_exactly(exprs, coordinates=(), points: int = 3, seed: int = 0) -> bool:
    """True when every expression is identically zero, decided by the library's exact method.

    Coordinates ``q(t)`` and their derivatives become plain symbols, then
    :class:`~dualmech.exact.form.ExactForm` evaluates at random rational points.  A nonzero value is
    a certain counter-example; the chance of missing one is below ``degree/2**62`` per point.
    """
    plain = [to_plain(e, coordinates) for e in exprs]
    symbols = sorted(set().union(*(e.free_symbols for e in plain)), key=str)
    form = ExactForm.build(plain, symbols)
    assert form.method == "exact", "these expressions should stay in the rational world"
    rng = random.Random(seed)
    return all(v == 0 for _ in range(points) for v in form.evaluate(form.sample(rng)))


def vanishes_at_rational_points(exprs, coordinates=(), points: int = 2, seed: int = 0) -> bool:
    """The same decision for large expressions, by direct substitution (no degree bound).

    Each distinct trigonometric argument gets its own random rational point of the unit
    circle, every other symbol a random rational.  Treating the arguments as independent is
    stricter than needed (an identity that relied on, say, an angle-addition formula would be
    reported nonzero) and never lets a wrong identity through: a nonzero rational function
    vanishes at a random point with probability about ``degree / 2**40``.
    """
    rng = random.Random(seed)
    rational = lambda: sp.Rational(rng.randrange(-2**20, 2**20), rng.randrange(1, 2**20))  # noqa: E731
    plain = [to_plain(e, coordinates) for e in exprs]
    trig = set().union(*(e.atoms(sp.sin, sp.cos) for e in plain))
    arguments = sorted({f.args[0] for f in trig}, key=sp.default_sort_key)
    for _ in range(points):
        circle = {}
        for arg in arguments:
            u = rational()
            circle[sp.sin(arg)] = 2 * u / (1 + u**2)
            circle[sp.cos(arg)] = (1 - u**2) / (1 + u**2)
        at = [e.xreplace(circle) for e in plain]
        assert not any(e.has(sp.Function) for e in at), "unexpected function left"
        symbols = set().union(*(e.free_symbols for e in at))
        point = {s: rational() for s in symbols}
        if any(e.xreplace(point) != 0 for e in at):
            return False
    return True


# -- elementary rotations -------------------------------------------------------------
@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_elementary_rotation_is_proper_orthogonal(axis):
    R = ROTATIONS[axis](a)
    assert is_zero_matrix(R.T * R - sp.eye(3))
    assert sp.simplify(R.det()) == 1


@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_elementary_rotation_fixes_its_axis(axis):
    e = sp.eye(3)[:, "xyz".index(axis)]
    assert ROTATIONS[axis](a) * e == e


def test_rotation_columns_are_the_rotated_axes():
    # rot_z(a) turns x towards y: its first column is the new x axis in the old frame
    assert rot_z(a)[:, 0] == sp.Matrix([sp.cos(a), sp.sin(a), 0])
    assert rot_x(a)[:, 1] == sp.Matrix([0, sp.cos(a), sp.sin(a)])
    assert rot_y(a)[:, 2] == sp.Matrix([sp.sin(a), 0, sp.cos(a)])


@pytest.mark.parametrize("axis", ["x", "y", "z"])
def test_rot_axis_on_a_coordinate_axis_is_the_elementary_rotation(axis):
    e = list(sp.eye(3)[:, "xyz".index(axis)])
    assert is_zero_matrix(rot_axis(e, a) - ROTATIONS[axis](a))


def test_rot_axis_about_a_rational_unit_axis_is_proper_orthogonal():
    n = [sp.Rational(3, 13), sp.Rational(4, 13), sp.Rational(12, 13)]
    R = rot_axis(n, a)
    assert is_zero_matrix(R.T * R - sp.eye(3))
    assert sp.simplify(R.det()) == 1
    assert is_zero_matrix(R * sp.Matrix(n) - sp.Matrix(n))


def test_rot_axis_rejects_a_non_unit_axis():
    with pytest.raises(ValueError, match="unit vector"):
        rot_axis([1, 1, 0], a)


def test_rot_axis_rejects_a_wrong_length_axis():
    with pytest.raises(ValueError, match="3 components"):
        rot_axis([1, 0], a)


def test_skew_is_the_cross_product_and_unskew_inverts_it():
    u = sp.Matrix(sp.symbols("u1:4"))
    v = sp.Matrix(sp.symbols("v1:4"))
    assert skew(u) * v == u.cross(v)
    assert unskew(skew(u)) == u


# -- frames and direction cosines ------------------------------------------------------
def toy_car_frames():
    """MIT 2.003J quiz 1: track A turns by phi about I, car frame B by theta about j_A."""
    phi, theta = coordinate("phi"), coordinate("theta")
    O = Frame.ground("O")
    A = O.child("A", rot_x(phi))
    B = A.child("B", rot_y(theta))
    return O, A, B, phi, theta


def test_unit_vectors_of_the_toy_car_match_source_001_part_1():
    O, A, B, phi, theta = toy_car_frames()
    c, s = sp.cos, sp.sin
    assert B.x.express(O).components == sp.Matrix([c(theta), s(theta) * s(phi),
                                                   -s(theta) * c(phi)])
    assert B.y.express(O).components == sp.Matrix([0, c(phi), s(phi)])
    assert B.z.express(O).components == sp.Matrix([s(theta), -c(theta) * s(phi),
                                                   c(theta) * c(phi)])


def test_dcm_chain_composes_and_inverts():
    O, A, B, phi, theta = toy_car_frames()
    assert B.dcm(O) == rot_x(phi) * rot_y(theta)
    assert O.dcm(B) == (rot_x(phi) * rot_y(theta)).T
    assert is_zero_matrix(A.dcm(O) * B.dcm(A) - B.dcm(O))
    assert B.dcm(B) == sp.eye(3)


def test_dcm_between_sibling_frames_goes_through_the_common_parent():
    O = Frame.ground("O")
    A = O.child("A", rot_z(a))
    C = O.child("C", rot_z(2 * a))
    assert is_zero_matrix(A.dcm(C) - rot_z(-a))


def test_vector_arithmetic_converts_to_the_left_frame():
    O, A, B, phi, theta = toy_car_frames()
    v = B.z + O.x
    assert v.frame is B
    assert is_zero_matrix(v.express(O).components - (B.z.express(O).components
                                                     + sp.Matrix([1, 0, 0])))


def test_frames_from_different_grounds_do_not_mix():
    A = Frame.ground("A")
    B = Frame.ground("B")
    with pytest.raises(ValueError, match="different chains"):
        A.dcm(B)


def test_non_3x3_rotation_is_rejected():
    with pytest.raises(ValueError, match="3x3"):
        Frame.ground().child("bad", sp.eye(2))


# -- angular velocity -------------------------------------------------------------------
def test_zyz_euler_angles_give_the_textbook_body_rates():
    """Source 002, section 5: body rates of z-y-z Euler angles (phi, theta, psi)."""
    phi, theta, psi = coordinate("phi"), coordinate("theta"), coordinate("psi")
    O = Frame.ground("O")
    body = O.child("1", rot_z(phi)).child("2", rot_y(theta)).child("body", rot_z(psi))
    w = body.ang_vel_in(O).express(body).components
    d = lambda q: q.diff(t)  # noqa: E731
    s, c = sp.sin, sp.cos
    expected = sp.Matrix([d(theta) * s(psi) - d(phi) * s(theta) * c(psi),
                          d(theta) * c(psi) + d(phi) * s(theta) * s(psi),
                          d(psi) + d(phi) * c(theta)])
    assert is_zero_matrix(w - expected)


def test_angular_velocity_is_skew_of_RT_dR():
    """skew(w) = R^T dR/dt in body axes, computed directly from the whole chain."""
    phi, theta, psi = coordinate("phi"), coordinate("theta"), coordinate("psi")
    O = Frame.ground("O")
    body = O.child("1", rot_z(phi)).child("2", rot_x(theta)).child("body", rot_z(psi))
    R = body.dcm(O)
    W = R.T * R.diff(t)
    w = body.ang_vel_in(O).express(body).components
    assert vanishes_exactly(list(W - skew(w)), (phi, theta, psi))


def test_relative_angular_velocities_add():
    O, A, B, phi, theta = toy_car_frames()
    total = B.ang_vel_in(O)
    parts = A.ang_vel_in(O) + B.ang_vel_in(A)
    assert is_zero_matrix(total.express(O).components - parts.express(O).components)
    assert is_zero_matrix(A.ang_vel_in(O).express(O).components
                          - sp.Matrix([phi.diff(t), 0, 0]))
    assert is_zero_matrix(B.ang_vel_in(A).express(A).components
                          - sp.Matrix([0, theta.diff(t), 0]))
    assert is_zero_matrix((O.ang_vel_in(B) + B.ang_vel_in(O)).components)


def test_angular_velocity_of_a_frame_in_itself_is_zero():
    O, A, B, phi, theta = toy_car_frames()
    assert B.ang_vel_in(B).is_zero()


# -- point kinematics: the toy car -------------------------------------------------------
def test_toy_car_acceleration_matches_source_001_part_8():
    """a_m = R(phi'' cos th - 2 phi' th' sin th) j_B - R th'' i_B + R phi'^2 cos th k_A
    + R th'^2 k_B, with the car at r = -R k_B."""
    O, A, B, phi, theta = toy_car_frames()
    R = sp.Symbol("R", positive=True)
    car = Point.origin(O).locate("m", -R * B.z)
    ph1, ph2 = phi.diff(t), phi.diff(t, 2)
    th1, th2 = theta.diff(t), theta.diff(t, 2)
    printed = (R * (ph2 * sp.cos(theta) - 2 * ph1 * th1 * sp.sin(theta)) * B.y
               - R * th2 * B.x + R * ph1**2 * sp.cos(theta) * A.z + R * th1**2 * B.z)
    diff = car.acc(O) - printed
    assert is_zero_matrix(diff.express(B).components)


def test_toy_car_velocity_matches_source_001_part_3():
    O, A, B, phi, theta = toy_car_frames()
    R = sp.Symbol("R", positive=True)
    car = Point.origin(O).locate("m", -R * B.z)
    printed = R * (phi.diff(t) * sp.cos(theta) * B.y - theta.diff(t) * B.x)
    assert is_zero_matrix((car.vel(O) - printed).express(B).components)


def test_relative_motion_terms_add_up_to_the_acceleration():
    O, A, B, phi, theta = toy_car_frames()
    R = sp.Symbol("R", positive=True)
    s = coordinate("s")  # the car also slides along i_B: a genuine relative motion
    hub = Point.origin(O)
    car = hub.locate("m", -R * B.z + s * B.x)
    split = RelativeMotion.of(car, hub, A, O)
    total = split.total() - car.acc(O)
    assert vanishes_exactly(list(total.express(O).components), (phi, theta, s))
    assert set(split.terms()) == {"base", "tangential", "centripetal", "coriolis", "relative"}


def test_relative_motion_coriolis_term_is_twice_w_cross_v_rel():
    O, A, B, phi, theta = toy_car_frames()
    R = sp.Symbol("R", positive=True)
    hub = Point.origin(O)
    car = hub.locate("m", -R * B.z)
    split = RelativeMotion.of(car, hub, A, O)
    # seen from the track A the car moves on a circle: v_rel = -R theta' i_B
    expected = 2 * phi.diff(t) * O.x.cross(-R * theta.diff(t) * B.x)
    assert is_zero_matrix((split.coriolis - expected).express(B).components)


def test_point_velocity_in_a_moving_frame_sees_only_relative_motion():
    O, A, B, phi, theta = toy_car_frames()
    R = sp.Symbol("R", positive=True)
    car = Point.origin(O).locate("m", -R * B.z)
    assert car.vel(B).is_zero()


# -- the transport theorem, property-based --------------------------------------------
# Unit axes with rational components, so everything stays in the rational world.
RATIONAL_AXES = [(sp.Rational(3, 13), sp.Rational(4, 13), sp.Rational(12, 13)),
                 (sp.Rational(2, 3), sp.Rational(-1, 3), sp.Rational(2, 3)),
                 (sp.Rational(-3, 5), 0, sp.Rational(4, 5)),
                 (sp.Rational(6, 7), sp.Rational(2, 7), sp.Rational(-3, 7))]
COORDINATES = [coordinate(n) for n in ("q1", "q2", "q3")]

small = st.integers(min_value=-3, max_value=3)


@st.composite
def angles(draw):
    """An angle: a coordinate q(t), or a small polynomial in t, or a coordinate plus t.

    No constant terms: ``sin(1)`` is not rational, and the exact check must stay exact.
    """
    kind = draw(st.sampled_from(["coordinate", "polynomial", "mixed"]))
    poly = draw(small) * t + draw(small) * t**2
    if kind == "polynomial":
        return poly if poly != 0 else t
    q = draw(st.sampled_from(COORDINATES))
    return q if kind == "coordinate" else q + draw(small) * t


@st.composite
def rotations(draw):
    angle = draw(angles())
    axis = draw(st.sampled_from(["x", "y", "z", "axis"]))
    if axis == "axis":
        return rot_axis(draw(st.sampled_from(RATIONAL_AXES)), angle)
    return ROTATIONS[axis](angle)


@st.composite
def components(draw):
    """A vector component: a small polynomial in t and one coordinate."""
    q = draw(st.sampled_from(COORDINATES))
    return draw(small) + draw(small) * t + draw(small) * q + draw(small) * q * t


@pytest.mark.slow
@settings(max_examples=25)
@given(chain=st.lists(rotations(), min_size=1, max_size=4),
       comps=st.tuples(components(), components(), components()),
       seed=st.integers(min_value=0, max_value=2**32 - 1))
def test_transport_theorem_equals_direct_differentiation(chain, comps, seed):
    ground = Frame.ground("G")
    frame = ground
    for i, R in enumerate(chain):
        frame = frame.child(f"F{i}", R)
    v = frame.vector(*comps)
    transported = v.dt(ground).express(ground).components
    direct = v.express(ground).components.diff(t)
    assert vanishes_at_rational_points(list(transported - direct), COORDINATES, seed=seed)
    # the derivative seen from the frame itself is plain component differentiation
    assert v.dt(frame).components == sp.Matrix(comps).diff(t)


def test_exact_check_catches_a_missing_transport_term():
    """The decision procedure used above is not vacuous: dropping w x v is detected."""
    O, A, B, phi, theta = toy_car_frames()
    v = B.vector(1, theta, 0)
    wrong = Vector(B, v.components.diff(t)).express(O).components
    direct = v.express(O).components.diff(t)
    assert not vanishes_exactly(list(wrong - direct), (phi, theta))
    assert not vanishes_at_rational_points(list(wrong - direct), (phi, theta))
    assert vanishes_at_rational_points(list(v.dt(O).express(O).components - direct),
                                       (phi, theta))


@pytest.mark.parametrize("method", ["dot", "cross", "outer", "dot_se"])
def test_vector_products_need_a_vector(method):
    O = Frame.ground("O")
    with pytest.raises(TypeError, match=f"Vector.{method}\\(\\) needs another Vector"):
        getattr(O.x, method)(3)
