"""Standard inertias, the parallel-axis theorem, composites, momenta and error messages."""
from __future__ import annotations

import random

import pytest
import sympy as sp

from dualmech.model.bodies import (MassProperties, Particle, RigidBody, composite, cuboid,
                                  parallel_axis, point_mass, solid_cylinder, solid_sphere,
                                  thin_disk, thin_rod)
from dualmech.model.equations import to_plain
from dualmech.exact.form import ExactForm
from dualmech.model.kinematics import Frame, Point, coordinate, rot_x, rot_y, rot_z, t

m, r, L, a, b, c = sp.symbols("m r L a b c", positive=True)


def is_zero_matrix(M) -> bool:
    return all(sp.simplify(x) == 0 for x in sp.Matrix(M))


def vanishes_exactly(exprs, coordinates, points: int = 3) -> bool:
    """Identically zero, decided at random rational points (see dualmech.exact.form)."""
    plain = [to_plain(e, coordinates) for e in exprs]
    symbols = sorted(set().union(*(e.free_symbols for e in plain)), key=str)
    form = ExactForm.build(plain, symbols)
    assert form.method == "exact"
    rng = random.Random(0)
    return all(v == 0 for _ in range(points) for v in form.evaluate(form.sample(rng)))


# -- standard shapes --------------------------------------------------------------------
@pytest.mark.parametrize("shape, expected", [
    (thin_rod(m, L, axis="x"), sp.diag(0, m * L**2 / 12, m * L**2 / 12)),
    (thin_rod(m, L), sp.diag(m * L**2 / 12, m * L**2 / 12, 0)),
    (thin_disk(m, r, normal="y"), sp.diag(m * r**2 / 4, m * r**2 / 2, m * r**2 / 4)),
    (thin_disk(m, r), sp.diag(m * r**2 / 4, m * r**2 / 4, m * r**2 / 2)),
    (solid_cylinder(m, r, L, axis="x"),
     sp.diag(m * r**2 / 2, m * (3 * r**2 + L**2) / 12, m * (3 * r**2 + L**2) / 12)),
    (solid_sphere(m, r), sp.diag(*[2 * m * r**2 / 5] * 3)),
    (cuboid(m, a, b, c), sp.diag(m * (b**2 + c**2) / 12, m * (a**2 + c**2) / 12,
                                 m * (a**2 + b**2) / 12)),
    (point_mass(m), sp.zeros(3, 3)),
], ids=["rod-x", "rod-z", "disk-normal-y", "disk-normal-z", "cylinder-x", "sphere", "cuboid",
        "point"])
def test_standard_inertias(shape, expected):
    assert is_zero_matrix(shape - expected)


def test_thin_disk_obeys_the_perpendicular_axis_theorem():
    I = thin_disk(m, r, normal="z")
    assert sp.simplify(I[0, 0] + I[1, 1] - I[2, 2]) == 0


def test_cylinder_of_zero_radius_is_a_rod_and_of_zero_length_a_disk():
    assert is_zero_matrix(solid_cylinder(m, 0, L, axis="y") - thin_rod(m, L, axis="y"))
    assert is_zero_matrix(solid_cylinder(m, r, 0, axis="y") - thin_disk(m, r, normal="y"))


@pytest.mark.parametrize("maker", [lambda: thin_rod(m, L, axis="w"),
                                   lambda: thin_disk(m, r, normal="X"),
                                   lambda: solid_cylinder(m, r, L, axis="")],
                         ids=["rod", "disk", "cylinder"])
def test_bad_axis_name_is_rejected_with_the_choices(maker):
    with pytest.raises(ValueError, match=r"must be one of 'x', 'y', 'z'"):
        maker()


# -- parallel-axis theorem ----------------------------------------------------------------
def test_parallel_axis_rod_about_its_end():
    # hand value: m L^2/12 + m (L/2)^2 = m L^2/3 across, 0 along
    I = parallel_axis(thin_rod(m, L, axis="x"), m, sp.Matrix([L / 2, 0, 0]))
    assert is_zero_matrix(I - sp.diag(0, m * L**2 / 3, m * L**2 / 3))


def test_parallel_axis_disk_about_a_rim_point():
    # hand value: about a tangent axis 5/4 m r^2, about the parallel normal axis 3/2 m r^2
    I = parallel_axis(thin_disk(m, r, normal="z"), m, sp.Matrix([r, 0, 0]))
    assert is_zero_matrix(I - sp.diag(m * r**2 / 4, 5 * m * r**2 / 4, 3 * m * r**2 / 2))


def test_parallel_axis_off_axis_offset_gives_products_of_inertia():
    # hand value with d = (1, 2, 0): I += m [[4, -2, 0], [-2, 1, 0], [0, 0, 5]]
    I = parallel_axis(sp.zeros(3, 3), m, sp.Matrix([1, 2, 0]))
    assert I == m * sp.Matrix([[4, -2, 0], [-2, 1, 0], [0, 0, 5]])


def test_parallel_axis_sign_of_the_offset_does_not_matter():
    d = sp.Matrix([a, -b, c])
    I = solid_sphere(m, r)
    assert is_zero_matrix(parallel_axis(I, m, d) - parallel_axis(I, m, -d))


# -- composites ---------------------------------------------------------------------------
def mit_quiz2_pendulum() -> MassProperties:
    """Rod (m, length 4r) hanging from A along -j, disk (2m, radius r) centred 5r below A."""
    return composite([(m, thin_rod(m, 4 * r, axis="y"), sp.Matrix([0, -2 * r, 0])),
                      (2 * m, thin_disk(2 * m, r, normal="z"), sp.Matrix([0, -5 * r, 0]))])


def test_mit_quiz2_rod_and_disk_about_the_pivot():
    """Source 001 quiz 2 prints 331/6 for the first entry; the sum is 335/6.

    About i_A: rod 4/3 + 4 (centre 2r below A), disk 1/2 + 50 (2m * (5r)^2 / (m r^2))
    = 16/3 + 101/2 = 335/6.  About k_A: 16/3 + (1 + 50) = 169/3.  About j_A: the disk, 1/2.
    """
    total = mit_quiz2_pendulum()
    assert total.mass == 3 * m
    assert total.center == sp.Matrix([0, -4 * r, 0])
    I_A = total.inertia_about(sp.zeros(3, 1))
    assert is_zero_matrix(I_A - m * r**2 * sp.diag(sp.Rational(335, 6), sp.Rational(1, 2),
                                                    sp.Rational(169, 3)))
    assert I_A[0, 0] != m * r**2 * sp.Rational(331, 6)


def test_composite_inertia_about_its_own_centre():
    total = mit_quiz2_pendulum()
    # about the centre (4r below A): I_A - 3m (4r)^2 across the rod
    expected = m * r**2 * sp.diag(sp.Rational(335, 6) - 48, sp.Rational(1, 2),
                                  sp.Rational(169, 3) - 48)
    assert is_zero_matrix(total.inertia - expected)


def test_composite_of_one_part_is_that_part():
    one = composite([(m, solid_sphere(m, r), sp.Matrix([a, b, c]))])
    assert one.mass == m
    assert one.center == sp.Matrix([a, b, c])
    assert is_zero_matrix(one.inertia - solid_sphere(m, r))


def test_composite_of_two_halves_of_a_rod_is_the_rod():
    halves = composite([(m / 2, thin_rod(m / 2, L / 2, axis="x"), sp.Matrix([-L / 4, 0, 0])),
                        (m / 2, thin_rod(m / 2, L / 2, axis="x"), sp.Matrix([L / 4, 0, 0]))])
    assert is_zero_matrix(halves.inertia - thin_rod(m, L, axis="x"))


def test_composite_needs_parts():
    with pytest.raises(ValueError, match="at least one"):
        composite([])


# -- rigid bodies and particles -------------------------------------------------------------
def swinging_body():
    """A body turning by theta about the ground z axis, then psi about its own x axis; its
    mass centre sits at (L, b, 0) in the body frame, the hinge point B moves along X with x(t)."""
    theta, psi, x = coordinate("theta"), coordinate("psi"), coordinate("x")
    O = Frame.ground("O")
    body = O.child("A", rot_z(theta)).child("body", rot_x(psi))
    B = Point.origin(O).locate("B", x * O.x)
    C = B.locate("C", body.vector(L, b, 0))
    I_C = sp.Matrix([[a, c, 0], [c, b, 0], [0, 0, a + b]])
    return O, body, B, C, RigidBody("body", m, C, body, I_C), (theta, psi, x)


def test_angular_momentum_mit_form_equals_centre_form():
    """H_B = I_B w + m r_BC x v_B equals I_C w + r_BC x m v_C, for a moving point B."""
    O, frame, B, C, body, coords = swinging_body()
    w = body.angular_velocity(O).express(frame).components
    spin_C = frame.vector(body.inertia * w)
    centre_form = spin_C + C.pos_from(B).cross(m * C.vel(O))
    mit_form = body.angular_momentum(B, O)
    difference = (mit_form - centre_form).express(frame).components
    assert vanishes_exactly(difference, coords)
    # and the check is not vacuous: without the m r_BC x v_B term the forms differ
    spin_B = frame.vector(body.inertia_about(B) * w)
    assert not vanishes_exactly((spin_B - centre_form).express(frame).components, coords)


def test_angular_momentum_about_the_mass_centre_is_I_w():
    O, frame, B, C, body, _ = swinging_body()
    w = body.angular_velocity(O).express(frame).components
    H = body.angular_momentum(C, O).express(frame).components
    assert is_zero_matrix(H - body.inertia * w)


def test_inertia_about_a_point_uses_body_axes():
    O, frame, B, C, body, coords = swinging_body()
    d = sp.Matrix([L, b, 0])
    assert vanishes_exactly(body.inertia_about(B) - parallel_axis(body.inertia, m, d), coords)


def test_kinetic_energy_of_a_rigid_body_is_half_v_dot_p_plus_half_w_dot_h():
    O, frame, B, C, body, _ = swinging_body()
    w = body.angular_velocity(O)
    T = (C.vel(O).dot(body.linear_momentum(O)) + w.dot(body.angular_momentum(C, O))) / 2
    assert sp.simplify(body.kinetic_energy(O) - T) == 0


def test_particle_momenta_and_energy():
    theta = coordinate("theta")
    O = Frame.ground("O")
    arm = O.child("arm", rot_y(theta))
    P = Point.origin(O).locate("P", -L * arm.z)
    bob = Particle("bob", m, P)
    assert bob.masscenter is P
    assert is_zero_matrix((bob.linear_momentum(O) + m * L * theta.diff(t) * arm.x)
                          .express(arm).components)
    assert is_zero_matrix((bob.angular_momentum(Point.origin(O), O)
                           - m * L**2 * theta.diff(t) * arm.y).express(arm).components)
    assert sp.simplify(bob.kinetic_energy(O) - m * L**2 * theta.diff(t)**2 / 2) == 0


def test_non_symmetric_inertia_is_rejected():
    O = Frame.ground("O")
    with pytest.raises(ValueError, match="must be symmetric"):
        RigidBody("crooked", m, Point.origin(O), O, sp.Matrix([[1, 2, 0], [0, 1, 0], [0, 0, 1]]))


def test_inertia_must_be_3x3():
    O = Frame.ground("O")
    with pytest.raises(ValueError, match="must be 3x3"):
        RigidBody("flat", m, Point.origin(O), O, sp.eye(2))
