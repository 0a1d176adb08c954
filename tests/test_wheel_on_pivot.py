"""Wheel rolling round a pivot (problems/wheel_on_pivot.py): steady motion, contact force and
pivot force, each derived at least twice."""
import pytest
import sympy as sp

from dualmech import NewtonEuler, t
from dualmech.verify.check import compare
from dualmech.problems.wheel_on_pivot import WheelOnPivot, a, direct_form, frames, g, l, m, phi, tau

problem = WheelOnPivot()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
F_x, F_y, F_z, R_x, R_y, R_z = sp.symbols("F_x F_y F_z R_x R_y R_z", real=True)
W = D(phi)  # the precession rate Omega on the motion


@pytest.fixture
def comparison(compared):
    return compared("wheel_on_pivot")


J = 3 * m * l**2 / 2 + m * a**2 / 4     # inertia about the vertical, rolling included (hand)


def test_steady_exactly_when_nothing_drives_the_axle():
    # J phi'' = tau: every constant rate phi' = Omega is a motion iff tau = 0
    (acc,) = problem.model("lagrange").accelerations_solved().values()
    assert sp.simplify(acc - tau / J) == 0
    assert acc.subs(tau, 0) == 0


def test_the_wheels_contact_point_is_at_rest():
    # rolling built into the frames (psi = -(l/a) phi): v_G + w x (C - G) = 0
    f = frames()
    v_C = f.G.vel(f.O) + f.W.ang_vel_in(f.O).cross(f.C.pos_from(f.G))
    assert v_C.is_zero()


def _solved(model):
    sol = model.solve()
    return {u.name: sp.simplify(sol[u]) for u in model.unknowns}


@pytest.mark.slow
def test_reactions_are_the_hand_ones():
    # hand (module docstring), phi'' = tau/J: F = (0, -m l phi''/2, m g + m a W^2/2),
    # R = (-m l W^2, 3 m l phi''/2, -m a W^2/2); on the steady motion (tau = 0) F_y = R_y = 0
    hand = {"F_x": 0, "F_y": -m * l * tau / J / 2, "F_z": m * g + m * a * W**2 / 2,
            "R_x": -m * l * W**2, "R_y": 3 * m * l * tau / J / 2, "R_z": -m * a * W**2 / 2}
    got = _solved(problem.model("newton_euler"))
    assert {k: sp.simplify(v - hand[k]) for k, v in got.items()} == {k: 0 for k in hand}
    am = _solved(problem.model("angular_momentum"))
    assert {k: sp.simplify(v - hand[k]) for k, v in am.items()} == {k: 0 for k in am}


def test_printed_relation_holds_whichever_way_the_radial_force_is_split():
    # the other closure: no axial force in the axle (R_x = 0), friction carries m l W^2
    ne, f = direct_form("newton_euler", closure="R_x")
    for axis in (f.A.x, f.A.y, f.A.z):
        ne.linear_momentum(f.wheel, axis)
        ne.angular_momentum(f.wheel, axis)
    other = _solved(ne.equations())
    assert sp.simplify(other["F_x"] + m * l * W**2) == 0
    assert sp.simplify(other["F_z"] - m * g - 3 * m * a * W**2 / 2) == 0
    printed = m * a * l * W**2 / 2 - a * F_x - (F_z - m * g) * l
    for sol in (other, _solved(problem.model("newton_euler"))):
        assert sp.simplify(printed.subs({F_x: sol["F_x"], F_z: sol["F_z"]})) == 0


def test_all_three_routes_give_the_same_contact_force(comparison):
    held = comparison.reaction_derivations
    assert {k: held[k] for k in ("F_y", "F_z")} == {
        r: ["newton_euler", "angular_momentum", "multiplier", "pivot_multiplier"]
        for r in ("F_y", "F_z")}


def test_freed_pivot_gives_the_hand_pivot_and_contact_forces():
    # hand (module docstring): the u_x, u_y, u_z rows on the motion are -m l W^2 = R_x,
    # m l phi'' = R_y + F_y, m g = R_z + F_z; with phi'' = tau/J and F from the other rows
    model = problem.in_reference_coordinates(problem.model("pivot_multiplier"))
    assert {u.name for u in model.unknowns} == {"R_x", "R_y", "R_z", "F_y", "F_z"}
    hand = {"F_y": -m * l * tau / J / 2, "F_z": m * g + m * a * W**2 / 2,
            "R_x": -m * l * W**2, "R_y": 3 * m * l * tau / J / 2, "R_z": -m * a * W**2 / 2}
    got = _solved(model)
    assert {k: sp.simplify(v - hand[k]) for k, v in got.items()} == {k: 0 for k in hand}


def test_pivot_force_is_derived_twice_and_compared(comparison):
    held = comparison.reaction_derivations
    assert {k: held[k] for k in ("R_x", "R_y", "R_z")} == {
        r: ["newton_euler", "pivot_multiplier"] for r in ("R_x", "R_y", "R_z")}
    assert "NOT CROSS-CHECKED" not in str(comparison)
    (pair,) = [p for p in comparison.pairs if p.kind == "reactions" and "R_x" in p.reactions]
    assert pair.reactions == ("R_x", "R_y", "R_z")


class _PivotForceOnThePivot(WheelOnPivot):
    """The direct form with ``R_x`` drawn the wrong way: the axle's pull on the pivot (along
    ``-i``) taken for the pivot's force on the axle, the other components right.  Renaming an
    unknown cannot change the motion; only the second derivation of ``R`` can see it."""

    def newton_euler(self):
        f = frames()
        ne = NewtonEuler("newton_euler", coordinates=[phi], ground=f.O)
        ne.gravity(-g * f.O.z)
        ne.torque("drive", f.wheel, tau * f.O.z)
        F = ne.reaction_vector("F", f.wheel, f.A, at=f.C)
        ne.reaction("R_x", f.wheel, -f.A.x, at=f.o)          # the sign error
        ne.reaction("R_y", f.wheel, f.A.y, at=f.o)
        ne.reaction("R_z", f.wheel, f.A.z, at=f.o)
        ne.equation("closure: F_x = 0", {"closure F_x": F.dot(f.A.x)})
        for axis in (f.A.x, f.A.y, f.A.z):
            ne.linear_momentum(f.wheel, axis)
        for axis in (f.A.x, f.A.y, f.A.z):
            ne.angular_momentum(f.wheel, axis)
        return ne.equations()


@pytest.mark.slow
def test_a_sign_error_in_the_direct_pivot_force_is_caught_naming_R_x():
    broken = compare(_PivotForceOnThePivot())
    assert all(p.equivalent for p in broken.pairs if p.kind == "motion")   # motion untouched
    assert not broken.equivalent
    bad = [p for p in broken.pairs if p.kind == "reactions" and not p.equivalent]
    assert [p.reactions for p in bad] == [("R_x", "R_y", "R_z")]
    assert {mm.equation for mm in bad[0].mismatches} == {"reaction R_x"}
    assert "DIFFERENT" in str(broken) and "all derivations agree" not in str(broken)
    # the contact force, which the sign error does not touch, still agrees three ways
    assert all(p.equivalent for p in broken.pairs if p.kind == "reactions"
               and "R_x" not in p.reactions)
    # the broken R_x is the right one negated: +m l W^2
    ne = broken.problem.model("newton_euler")
    assert sp.simplify(_solved(ne)["R_x"] - m * l * W**2) == 0
