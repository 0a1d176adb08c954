"""The n-link chain of rods (problems/n_link_pendulum.py): the joint forces of the direct form
derived a second time as multipliers of the rods freed in the plane, and compared."""
import pytest
import sympy as sp

from dualmech import NewtonEuler, RigidBody, t, thin_rod
from dualmech.verify.check import compare
from dualmech.problems.n_link_pendulum import NLinkRigidPendulum, g

D = lambda q, n=1: q.diff(t, n)  # noqa: E731


@pytest.fixture
def comparison(compared):
    c = compared("n_link_rigid_pendulum")
    assert len(c.problem.q) == 3     # the catalogue's chain has three rods
    return c


def test_chain_of_three_frees_each_rod_in_the_plane():
    p = NLinkRigidPendulum(3)
    assert len(p.model("multiplier").coordinates) == 9          # xc_i, yc_i, theta_i
    assert [u.name for u in p.model("multiplier").unknowns] == ["X1", "Y1", "X2", "Y2",
                                                                 "X3", "Y3"]
    assert NLinkRigidPendulum(3, cartesian=False).model_names == ["newton_euler", "lagrange"]


def test_one_rod_pivot_force_by_hand_from_both_derivations():
    # hand: I_O theta'' = -m g (l/2) sin(theta), I_O = m l^2/3; the centre at
    # (l/2)(sin, -cos) has a_C = (l/2)(theta'' cos - theta'^2 sin, theta'' sin + theta'^2 cos);
    # the pivot force on the rod is m a_C + (0, m g)
    p = NLinkRigidPendulum(1)
    (th,), (m,), (l,) = p.q, p.m, p.l
    acc = -3 * g * sp.sin(th) / (2 * l)
    W = D(th)
    hand = {"X1": m * l / 2 * (acc * sp.cos(th) - W**2 * sp.sin(th)),
            "Y1": m * l / 2 * (acc * sp.sin(th) + W**2 * sp.cos(th)) + m * g}
    for name in ("newton_euler", "multiplier"):
        model = p.in_reference_coordinates(p.model(name))
        sol = model.solve()
        assert sp.simplify(sol[D(th, 2)] - acc) == 0, name
        got = {u.name: sol[u] for u in model.unknowns}
        assert {k: sp.simplify(v - hand[k]) for k, v in got.items()} == {"X1": 0, "Y1": 0}, name


def test_joint_forces_are_derived_twice_and_compared(comparison):
    names = ["X1", "Y1", "X2", "Y2", "X3", "Y3"]
    assert comparison.reaction_derivations == {n: ["newton_euler", "multiplier"] for n in names}
    (pair,) = [p for p in comparison.pairs if p.kind == "reactions"]
    assert list(pair.reactions) == names


class _JointTwoFlipped(NLinkRigidPendulum):
    """The direct form with joint 2's ``X`` drawn along ``-x`` on rod 2 (and, consistently,
    ``+x`` on rod 1): a sign convention flipped for one joint force.  The motion cannot see it
    (the unknown is only renamed); the multiplier model's ``X2`` can."""

    def newton_euler(self):
        O, links, joints = self._frames()
        ne = NewtonEuler(coordinates=list(self.q), ground=O)
        rods = []
        for i, L in enumerate(links):
            centre = joints[i].locate(f"C{i + 1}", -self.l[i] / 2 * L.y)
            rods.append(RigidBody(f"rod {i + 1}", self.m[i], centre, L,
                                  thin_rod(self.m[i], self.l[i], axis="y")))
        ne.gravity(-g * O.y)
        for i, rod in enumerate(rods):
            above = rods[i - 1] if i else None
            x_axis = -O.x if i == 1 else O.x                 # the sign error, joint 2 only
            ne.reaction(f"X{i + 1}", rod, x_axis, at=joints[i], against=above,
                        against_at=joints[i])
            ne.reaction(f"Y{i + 1}", rod, O.y, at=joints[i], against=above,
                        against_at=joints[i])
        for rod in rods:
            ne.linear_momentum(rod, O.x)
            ne.linear_momentum(rod, O.y)
            ne.angular_momentum(rod, O.z)
        return ne.equations()


@pytest.mark.slow
def test_a_flipped_joint_force_in_the_direct_form_is_caught_naming_it():
    broken = compare(_JointTwoFlipped(3))
    assert all(p.equivalent for p in broken.pairs if p.kind == "motion")   # motion untouched
    assert not broken.equivalent
    (pair,) = [p for p in broken.pairs if p.kind == "reactions"]
    assert not pair.equivalent
    assert {mm.equation for mm in pair.mismatches} == {"reaction X2"}
    assert "DIFFERENT" in str(broken) and "all derivations agree" not in str(broken)


def test_the_chain_of_two_checks_too():
    c = compare(NLinkRigidPendulum(2))
    assert c.equivalent and c.not_cross_checked == [], str(c)
