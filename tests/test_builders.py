"""The two builders (dualmech.model.direct, dualmech.model.lagrange) on small systems derived by hand."""
import pytest
import sympy as sp

from dualmech import (Frame, Lagrangian, ModelError, NewtonEuler, Particle, Point, RigidBody,
                      coordinate, rot_z, t, thin_rod)
from dualmech.verify.check import compare_models

m, k, g, R, w, L0, c, l = sp.symbols("m k g R omega L0 c l", positive=True)
th, psi, x, y = coordinate("theta"), coordinate("psi"), coordinate("x"), coordinate("y")


def test_bead_on_spinning_hoop_with_prescribed_rotation():
    """Source 000, example 13: theta'' = (omega^2 cos(theta) - g/R) sin(theta).

    The hoop turns about the vertical at the prescribed rate omega (psi = omega t); the bead is
    at R (sin th cos psi, sin th sin psi, -cos th).
    """
    lg = Lagrangian(coordinates=[th, psi])
    pos = sp.Matrix([R * sp.sin(th) * sp.cos(psi), R * sp.sin(th) * sp.sin(psi),
                     -R * sp.cos(th)])
    v = pos.diff(t)
    lg.kinetic("bead", m * (v.T * v)[0, 0] / 2)
    lg.potential("gravity", m * g * pos[2])
    lg.prescribe(psi, w * t)
    eqs = lg.equations()
    assert eqs.coordinates == (th,)
    acc = eqs.accelerations_solved()[th.diff(t, 2)]
    assert sp.simplify(acc - (w**2 * sp.cos(th) - g / R) * sp.sin(th)) == 0
    # equilibria: the bottom, and cos(theta) = g / (R omega^2) when the hoop spins fast
    # (sympy's solve misses theta = pi here; linearize confirms it is an equilibrium)
    found = [sp.simplify(e[th]) for e in eqs.equilibria()]
    assert 0 in found
    off_axis = [f for f in found if f != 0]
    assert len(off_axis) == 2
    for f in off_axis:
        assert sp.simplify(sp.cos(f) - g / (R * w**2)) == 0
    K_top = eqs.linearize({th: sp.pi})[2]
    # hand: d/dth (m g R sin th - m R^2 w^2 sin th cos th) at pi = -m R (g + R w^2) < 0:
    # the top is always unstable
    assert sp.simplify(K_top[0] + m * R * (g + R * w**2)) == 0
    K_bottom = eqs.linearize()[2]
    assert sp.simplify(K_bottom[0] - m * R * (g - R * w**2)) == 0  # unstable when R w^2 > g


def test_spring_between_points_with_free_length():
    """A mass on a spring of free length L0 from a fixed anchor, both coordinates free.

    Hand: m x'' = -k (r - L0) x / r, m y'' = -k (r - L0) y / r - m g, r = sqrt(x^2 + y^2).
    """
    O = Frame.ground()
    P = Point.origin(O).locate("P", x * O.x + y * O.y)
    bob = Particle("bob", m, P)
    ne = NewtonEuler(coordinates=[x, y], ground=O)
    ne.gravity(-g * O.y)
    ne.spring_between("spring", k, L0, (bob, P), (None, Point.origin(O)))
    ne.linear_momentum(bob, O.x)
    ne.linear_momentum(bob, O.y)
    lg = Lagrangian(coordinates=[x, y])
    lg.kinetic("T", m * (x.diff(t)**2 + y.diff(t)**2) / 2)
    lg.spring("spring", k, sp.sqrt(x**2 + y**2) - L0)
    lg.gravity(-g * O.y, [bob], O)
    r = compare_models(lg.equations(), ne.equations())
    assert r.equivalent and r.method == "exact"      # the square root: an exact algebraic number
    wrong = NewtonEuler(coordinates=[x, y], ground=O)
    wrong.gravity(-g * O.y)
    wrong.spring_between("spring", k, 0, (bob, P), (None, Point.origin(O)))  # free length lost
    wrong.linear_momentum(bob, O.x)
    wrong.linear_momentum(bob, O.y)
    bad = compare_models(lg.equations(), wrong.equations())
    assert not bad.equivalent and bad.mismatches


def test_rolling_disk_velocity_constraint_multiplier_is_the_friction_force():
    """Disk (m, radius R, I = m R^2/2) rolling down a slope alpha: x' = R psi'.

    Hand: x'' = 2/3 g sin(alpha), friction f = m g sin(alpha)/3 (up the slope).  With the
    constraint x' - R psi' = 0 and multiplier lam: m x'' = m g sin(alpha) + lam, so lam = -f.
    """
    alpha = sp.Symbol("alpha", positive=True)
    lg = Lagrangian(coordinates=[x, psi])
    lg.kinetic("T", m * x.diff(t)**2 / 2 + m * R**2 / 4 * psi.diff(t)**2)
    lg.potential("gravity", -m * g * sp.sin(alpha) * x)
    lam = lg.velocity_constraint("lam", [1, -R])
    sol = lg.equations().solve()
    assert sp.simplify(sol[x.diff(t, 2)] - 2 * g * sp.sin(alpha) / 3) == 0
    assert sp.simplify(sol[lam] + m * g * sp.sin(alpha) / 3) == 0


def test_compound_pendulum_euler_about_fixed_point_and_moving_point_agree():
    """A thin rod (m, length l) pinned at its end: Euler about the pin and about the centre.

    Hand: (m l^2 / 3) th'' + m g (l/2) sin(th) = 0.
    """
    O = Frame.ground()
    A = O.child("A", rot_z(th))
    pin = Point.origin(O)
    C = pin.locate("C", -l / 2 * A.y)
    rod = RigidBody("rod", m, C, A, thin_rod(m, l, axis="y"))
    about_pin = NewtonEuler("pin", coordinates=[th], ground=O)
    about_pin.gravity(-g * O.y)
    about_pin.reaction_vector("P", rod, O, "xy", at=pin)
    about_pin.angular_momentum(rod, O.z, about=pin)
    about_centre = NewtonEuler("centre", coordinates=[th], ground=O)
    about_centre.gravity(-g * O.y)
    about_centre.reaction_vector("P", rod, O, "xy", at=pin)
    about_centre.linear_momentum(rod, O.x)
    about_centre.linear_momentum(rod, O.y)
    about_centre.angular_momentum(rod, O.z)
    hand = Lagrangian(coordinates=[th])
    hand.kinetic("T", m * l**2 / 6 * th.diff(t)**2)
    hand.potential("V", -m * g * l / 2 * sp.cos(th))
    ref = hand.equations()
    # about the pin the reaction has no moment: one equation, no unknown left over
    pin_eqs = about_pin.equations()
    assert compare_models(ref, sp_free(pin_eqs)).equivalent
    assert compare_models(ref, about_centre.equations()).equivalent


def sp_free(eqs):
    """The pin model's reaction unknowns never appear in its one equation: drop them."""
    from dualmech import EquationSet
    used = [u for u in eqs.unknowns if any(e.has(u) for e in eqs.equations)]
    return EquationSet(eqs.name, eqs.coordinates, eqs.equations, tuple(used), eqs.labels)


def test_torque_needs_a_rigid_body_and_generalized_force_length_is_checked():
    O = Frame.ground()
    bob = Particle("bob", m, Point.origin(O).locate("P", x * O.x))
    ne = NewtonEuler(coordinates=[x], ground=O)
    with pytest.raises(ModelError, match="needs a rigid body"):
        ne.torque("motor", bob, O.z)
    with pytest.raises(ModelError, match="has no equations"):
        ne.equations()
    lg = Lagrangian(coordinates=[x])
    with pytest.raises(ModelError, match="needs 1 entries"):
        lg.generalized_force("F", [1, 2])
    with pytest.raises(ModelError, match="no energy"):
        lg.equations()


@pytest.mark.parametrize("text", ["__import__('os').system('true')", "x**2"])
def test_text_is_refused_never_evaluated(text):
    lg = Lagrangian(coordinates=[x])
    with pytest.raises(TypeError, match="text is never evaluated"):
        lg.potential("V", text)
    from dualmech import EquationSet
    with pytest.raises(TypeError, match="text is never evaluated"):
        EquationSet("e", (x,), (text,))
