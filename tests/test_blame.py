"""Hand-broken models of the catalogue's problems: ``compare`` must blame the right derivation.

Issue 6, points 2, 3, 4 and 7.  Each test subclasses a catalogue problem and replaces one
derivation by a deliberately wrong version, the way a student would get it wrong (a factor
dropped from ``T``, a dashpot on the wrong coordinate, a reaction drawn along the wrong axis,
a multiplier scaled by a constraint written twice as large).  With three or more derivations
the ones that agree outvote the odd one, which the verdict names; with two (a tie) both are
suspects.  ``compare`` never raises on a wrong model, a single derivation is "NOT CHECKED",
and printed "equations of motion" that determine nothing are wrong.

Reference values are hand derivations, written in each test: the residual of a wrong
equation on the true motion is the term the mistake added or removed, and the report's value
at its state is checked against that term evaluated at the same state (to rounding).

Cases that expose an open bug are ``xfail(strict=True)`` with the reason.
"""
from __future__ import annotations

import dataclasses
import json
import math
import re

import pytest
import sympy as sp

from dualmech import problems
from dualmech import Lagrangian, NewtonEuler, Particle, t
from dualmech.cli.main import main
from dualmech.verify.check import compare
from dualmech.model.dimensions import FORCE
from dualmech.model.problem import Published, Reaction
from dualmech.problems import block_on_wedge as bw
from dualmech.problems import cart_pendulum as cp
from dualmech.problems import pendulum_on_mass as pm
from dualmech.problems import toy_car as tc
from dualmech.problems.falling_container import FallingContainer
from dualmech.problems.mass_spring_gravity import MassSpringGravity
from dualmech.problems.satellite_polar import SatellitePolar
from dualmech.problems.simple_pendulum import SimplePendulum

D = lambda q, n=1: q.diff(t, n)  # noqa: E731
TOY_CAR_OTHERS = {"newton_euler", "angular_momentum", "multiplier", "referee",
                  "referee (angular_momentum)"}


# -- the hand-broken problems --------------------------------------------------------------------
class ToyCarNoCos2(tc.ToyCar):
    """The Lagrangian drops the ``cos^2(theta)`` of the track's rotation: ``T = m R^2 (theta'^2
    + phi'^2) / 2``.  Three other derivations agree: ``lagrange`` is the odd one."""

    def lagrange(self):
        lg = Lagrangian(coordinates=[tc.theta, tc.phi])
        lg.kinetic("T of car", tc.m * tc.R**2 * (D(tc.theta)**2 + D(tc.phi)**2) / 2)
        lg.potential("gravity", -tc.m * tc.g * tc.R * sp.cos(tc.theta) * sp.cos(tc.phi))
        return lg.equations()


class ToyCarTrackAlongI(tc.ToyCar):
    """The track's force drawn along ``i_B`` (the direction of travel) instead of ``k_B``."""

    def newton_euler(self):
        f = tc.frames()
        car = Particle("car", tc.m, f.car)
        ne = NewtonEuler(coordinates=[tc.theta, tc.phi], ground=f.O)
        ne.gravity(-tc.g * f.O.z)
        ne.reaction("F_r", car, f.B.x)
        for axis in (f.B.x, f.B.y, f.B.z):
            ne.linear_momentum(car, axis)
        return ne.equations()


class ToyCarTwoNormals(tc.ToyCar):
    """Two unknown forces along ``k_B``: the motion is right, the reactions undetermined."""

    reactions = tc.ToyCar.reactions + (Reaction("F_s", FORCE, "along k_B, drawn twice"),)

    def newton_euler(self):
        f = tc.frames()
        car = Particle("car", tc.m, f.car)
        ne = NewtonEuler(coordinates=[tc.theta, tc.phi], ground=f.O)
        ne.gravity(-tc.g * f.O.z)
        ne.reaction("F_r", car, f.B.z)
        ne.reaction("F_s", car, f.B.z)
        for axis in (f.B.x, f.B.y, f.B.z):
            ne.linear_momentum(car, axis)
        return ne.equations()


class SimplePendulumWeightReversed(SimplePendulum):
    """The moment of the weight about the pivot with the wrong sign (the bob's weight drawn
    upwards in the moment balance); three derivations agree."""

    def angular_momentum(self):
        wrong = super().angular_momentum().flipped("gravity on bob")
        return dataclasses.replace(wrong, name="angular_momentum")


class CartPendulumDashpotOnX(cp.CartPendulum):
    """The torsional dashpot's dissipation written with ``x'`` instead of ``theta'``."""

    def lagrange(self):
        x, th = cp.x, cp.theta
        lg = Lagrangian("lagrange", coordinates=[x, th])
        lg.kinetic("T of cart", cp.m * D(x)**2 / 2)
        lg.kinetic("T of bob", cp.m0 * (D(x)**2 + (cp.l * D(th))**2
                                        + 2 * D(x) * cp.l * D(th) * sp.cos(th)) / 2)
        lg.potential("spring", cp.k * x**2 / 2)
        lg.potential("torsional spring", cp.k_t * th**2 / 2)
        lg.potential("gravity", cp.m0 * cp.g * cp.l * (1 - sp.cos(th)))
        lg.dissipation("dashpot", cp.c * D(x)**2 / 2)
        lg.dissipation("torsional dashpot", cp.c_t * D(x)**2 / 2)     # the mistake
        bob = sp.Matrix([x + cp.l * sp.sin(th), -cp.l * sp.cos(th)])
        force = sp.Matrix([cp.drive, 0])
        lg.generalized_force("drive", [force.dot(bob.diff(q)) for q in (x, th)])
        return lg.equations()


class FallingContainerDashpotFlipped(FallingContainer):
    """The direct model in ``(y1, y2)`` with the dashpot's force on both bodies reversed."""

    def newton_euler_y(self):
        wrong = super().newton_euler_y().flipped("dashpot")
        return dataclasses.replace(wrong, name="newton_euler_y")


class PendulumOnMassStiffSpring(pm.PendulumOnMass):
    """``V`` of the spring written ``k y^2`` (the 1/2 dropped); only two derivations: a tie
    (the catalogue's multiplier model, a third derivation, is left out here)."""

    extra_models = ()
    extra_coordinates = ()

    def coordinate_maps(self):
        return {}

    def lagrange(self):
        lg = Lagrangian(coordinates=[pm.y, pm.theta])
        for key, T in pm.kinetic_energy().items():
            lg.kinetic(key, T)
        for key, V in pm.potential_energy().items():
            lg.potential(key, 2 * V if key == "spring" else V)
        return lg.equations()


class BlockOnWedgeHalfNormal(bw.BlockOnWedge):
    """The constraint written ``2 d1 = 0``: the motion is right, its multiplier is ``N1 / 2``."""

    def lagrange_multipliers(self):
        s, c = sp.sin(bw.alpha), sp.cos(bw.alpha)
        wedge = sp.Matrix([bw.q2, bw.d2])
        block = wedge + bw.q1 * sp.Matrix([c, -s]) + bw.d1 * sp.Matrix([s, c])
        lg = Lagrangian("lagrange_multipliers", coordinates=[bw.q1, bw.q2, bw.d1, bw.d2])
        lg.kinetic("T of wedge", bw.M * (D(wedge).T * D(wedge))[0, 0] / 2)
        lg.kinetic("T of block", bw.m * (D(block).T * D(block))[0, 0] / 2)
        lg.potential("gravity", bw.M * bw.g * wedge[1] + bw.m * bw.g * block[1])
        lg.constraint("N1", 2 * bw.d1)                                   # the mistake
        lg.constraint("N2", bw.d2)
        return lg.equations()


class SatelliteLagrangeOnly(SatellitePolar):
    """One derivation only: nothing to compare it with."""

    name = "satellite_lagrange_only"

    @property
    def model_names(self):
        return ["lagrange"]


class SatellitePrintedSets(SatellitePolar):
    """Printed "equations of motion" built from the verified ones: ``(e1, 2 e1)`` and
    ``(0, 0)`` and ``(e1)`` determine nothing; ``(e2, e1 + e2)`` and ``e1`` alone are right."""

    def published(self):
        e1, e2 = self.model("lagrange").equations
        zero = sp.Integer(0)
        return [Published("(e1, 2 e1)", "motion", (e1, 2 * e1)),
                Published("0 = 0, 0 = 0", "motion", (zero, zero)),
                Published("e1 alone", "motion", (e1,)),
                Published("(e2, e1 + e2)", "motion", (e2, e1 + e2)),
                Published("e1 as an equation", "equation", (e1,))]


class MassSpringZeroEqualsZero(MassSpringGravity):
    """``0 = 0`` printed as the equation of motion of a one-coordinate problem."""

    def published(self):
        return [Published("0 = 0", "motion", (sp.Integer(0),))]


# -- their comparisons, built once -------------------------------------------------------------
_CACHE: dict = {}


def compared(cls):
    if cls not in _CACHE:
        _CACHE[cls] = compare(cls())
    return _CACHE[cls]


def assert_readable(c) -> None:
    """No self-contradicting line and the notation people read (``ẋ``, not Derivative or
    Python's ``**`` and ``*``; ``x'`` in JSON)."""
    text = str(c)
    assert not re.search(r"\*\*|[\w)]\*[\w(]|\w_d?dot\b", text), text
    for mm in c.mismatches:
        residual = mm.residual.strip()
        assert residual != "0", f"{mm.model} [{mm.equation}] differs with a residual of 0"
        if mm.state and math.isfinite(mm.value):
            assert mm.value != 0, f"{mm.model} [{mm.equation}] differs with value 0 at a state"
    assert "Derivative(" not in text
    assert "Derivative(" not in json.dumps(c.to_dict())


def mismatches_of(c, model: str) -> dict:
    return {mm.equation: mm for mm in c.mismatches if mm.model == model}


def state_value(state: dict, name: str) -> float:
    return float(state[name])


# -- three or more derivations: the odd one is named -----------------------------------------
def test_toy_car_lagrangian_without_cos2_is_the_odd_one():
    c = compared(ToyCarNoCos2)
    j = c.judgement
    assert not c.equivalent
    assert j.odd == ["lagrange"]
    assert set(j.majority) == TOY_CAR_OTHERS
    assert c.verdict_line() == ("DISAGREEMENT: `lagrange` disagrees with `newton_euler`, "
                                "`angular_momentum`, `multiplier`, `referee` and `referee "
                                "(angular_momentum)`, which agree with each other")
    wrong = mismatches_of(c, "lagrange")
    assert set(wrong) == {"Lagrange, theta", "Lagrange, phi"}
    assert {mm.model for mm in c.mismatches} == {"lagrange"}


def test_toy_car_lagrangian_without_cos2_residuals_are_the_dropped_terms():
    """By hand, on the true motion (``theta''``, ``phi''`` of the right equations):
    the wrong theta equation ``m R^2 theta'' + m g R sin(theta) cos(phi)`` leaves
    ``-m R^2 phi'^2 sin(theta) cos(theta)``; the wrong phi equation ``m R^2 phi'' + m g R
    cos(theta) sin(phi)`` leaves it with ``phi'' = (2 R sin cos theta' phi' - g cos(theta)
    sin(phi)) / (R cos^2(theta))``."""
    wrong = mismatches_of(compared(ToyCarNoCos2), "lagrange")
    s = wrong["Lagrange, theta"].state
    m, R, th, ph1 = (s[k] for k in ("m", "R", "theta", "phi'"))
    expect = -m * R**2 * ph1**2 * math.sin(th) * math.cos(th)
    assert wrong["Lagrange, theta"].value == pytest.approx(expect, rel=1e-9, abs=1e-12)
    s = wrong["Lagrange, phi"].state
    m, R, g, th, ph, th1, ph1 = (s[k] for k in ("m", "R", "g", "theta", "phi", "theta'",
                                                 "phi'"))
    phdd = (2 * R * math.sin(th) * math.cos(th) * th1 * ph1
            - g * math.cos(th) * math.sin(ph)) / (R * math.cos(th)**2)
    expect = m * R**2 * phdd + m * g * R * math.cos(th) * math.sin(ph)
    assert wrong["Lagrange, phi"].value == pytest.approx(expect, rel=1e-9, abs=1e-12)
    assert_readable(compared(ToyCarNoCos2))


def test_simple_pendulum_moment_balance_with_the_weight_reversed():
    """By hand: the balance is ``-M a^2 theta'' - M g a sin(theta) = 0``; reversing the weight
    leaves ``2 M g a sin(theta)`` (in magnitude) on the true motion."""
    c = compared(SimplePendulumWeightReversed)
    j = c.judgement
    assert j.odd == ["angular_momentum"]
    assert set(j.majority) == {"newton_euler", "lagrange", "multiplier", "referee"}
    assert c.verdict_line() == ("DISAGREEMENT: `angular_momentum` disagrees with `lagrange`, "
                                "`newton_euler`, `multiplier` and `referee`, which agree with "
                                "each other")
    (wrong,) = c.mismatches
    assert (wrong.model, wrong.equation) == ("angular_momentum", "sum tau_pivot . O.z (bob)")
    s = wrong.state
    assert abs(wrong.value) == pytest.approx(2 * s["M"] * s["g"] * s["a"]
                                             * abs(math.sin(s["theta"])), rel=1e-9)
    assert_readable(c)


def test_cart_pendulum_dashpot_on_the_wrong_coordinate():
    """By hand: ``R`` with ``c_t x'^2/2`` adds ``c_t x'`` to the x equation and drops
    ``c_t theta'`` from the theta equation, so on the true motion they leave ``c_t x'`` and
    ``-c_t theta'``."""
    c = compared(CartPendulumDashpotOnX)
    j = c.judgement
    assert j.odd == ["lagrange"]
    assert set(j.majority) == {"newton_euler", "lagrange_multipliers", "referee"}
    assert c.verdict_line() == ("DISAGREEMENT: `lagrange` disagrees with `newton_euler`, "
                                "`lagrange_multipliers` and `referee`, which agree with each "
                                "other")
    wrong = mismatches_of(c, "lagrange")
    assert set(wrong) == {"Lagrange, x", "Lagrange, theta"}
    s = wrong["Lagrange, x"].state
    assert wrong["Lagrange, x"].value == pytest.approx(s["c_t"] * s["x'"], rel=1e-9)
    s = wrong["Lagrange, theta"].state
    assert wrong["Lagrange, theta"].value == pytest.approx(-s["c_t"] * s["theta'"], rel=1e-9)
    for mm in wrong.values():
        assert mm.residual.strip() != "0"


def test_cart_pendulum_dashpot_residuals_are_simplified():
    from dualmech.verify.display import dotted
    wrong = mismatches_of(compared(CartPendulumDashpotOnX), "lagrange")
    assert wrong["Lagrange, x"].residual == dotted(cp.c_t * D(cp.x))
    assert wrong["Lagrange, theta"].residual == dotted(-cp.c_t * D(cp.theta))


def test_cart_pendulum_report_uses_primes_not_derivative():
    assert_readable(compared(CartPendulumDashpotOnX))


def test_check_text_of_a_disagreement_is_in_textbook_notation():
    """``dualmech check``'s text: residuals, terms, states and the dimension audit in the
    textbook's letters.  By hand (as above): residuals c_t x' and -c_t theta'; c_t is a
    torsional dashpot (N m s = M L^2 T^-1), so c_t x' has M L^3 T^-2 in a force equation."""
    c = compared(CartPendulumDashpotOnX)
    dots, primes = c.text(), c.text("primes")
    assert "residual after the best combination: c\u209c x\u0307" in dots
    assert "residual after the best combination: -c\u209c \u03b8\u0307" in dots
    assert "residual after the best combination: -c\u209c \u03b8\u2032" in primes
    assert ("lagrange [Lagrange, x]: term c\u209c x\u0307 has dimension M L^3 T^-2 where the "
            "rest has M L T^-2") in dots
    state = re.search(r"at (.*): residual", dots).group(1)
    assert "\u03b8\u0307=" in state and "theta" not in state
    s = mismatches_of(c, "lagrange")["Lagrange, x"].state    # the dashpot's term, valued
    value = s["c_t"] * s["x'"]
    assert f"{value:+.6g}  c\u209c x\u0307\n" in dots
    assert c.mismatches[0].to_dict()["residual"] == "c_t*x'"   # JSON keeps its plain form
    assert str(c) == dots and "\u2032" not in dots and "\u0307" not in primes


def test_falling_container_direct_model_in_other_coordinates_is_the_odd_one():
    """By hand: the dashpot pushes the container by ``+c y2'`` and m2 by ``-c y2'``
    (``y2' = x2' - x1'``); reversed, the container's balance leaves ``-2 c y2'``, m2's
    ``+2 c y2'``."""
    c = compared(FallingContainerDashpotFlipped)
    j = c.judgement
    assert j.odd == ["newton_euler_y"]
    assert set(j.majority) == {"lagrange", "newton_euler", "lagrange_y", "referee"}
    wrong = mismatches_of(c, "newton_euler_y")
    assert set(wrong) == {"sum F . O.y (container)", "sum F . O.y (m2)"}
    for label, sign in (("sum F . O.y (container)", -2), ("sum F . O.y (m2)", 2)):
        s = wrong[label].state
        rate = s["y2'"] if "y2'" in s else s["x2'"] - s["x1'"]
        assert wrong[label].value == pytest.approx(sign * s["c"] * rate, rel=1e-9)
    assert_readable(c)


def test_falling_container_odd_model_is_explained_in_its_own_coordinates():
    wrong = mismatches_of(compared(FallingContainerDashpotFlipped), "newton_euler_y")
    for mm in wrong.values():
        assert "y2'" in mm.state and "x2'" not in mm.state
        assert "x1" not in mm.residual and "x2" not in mm.residual
        assert all("x1" not in term and "x2" not in term for term, _ in mm.terms)


# -- a wrong direct model: a verdict, not an exception ---------------------------------------
def test_track_force_along_the_wrong_axis_is_reported_not_raised():
    c = compared(ToyCarTrackAlongI)
    j = c.judgement
    assert not c.equivalent
    assert j.odd == ["newton_euler"]
    # its referee shares the wrong direction: its balances contradict each other, so it
    # withdraws; the angular-momentum model's referee votes
    assert set(j.majority) == {"lagrange", "angular_momentum", "multiplier",
                               "referee (angular_momentum)"}
    assert c.verdict_line().startswith(
        "DISAGREEMENT: `newton_euler` disagrees with `lagrange`, `angular_momentum`, "
        "`multiplier` and `referee (angular_momentum)`, which agree with each other")
    assert {mm.model for mm in c.mismatches} == {"newton_euler"}
    # the k_B balance has no unknown left to balance it
    assert "sum F . B.z (car)" in c.verdict_line()
    assert_readable(c)


def test_undetermined_reactions_are_a_mismatch_of_the_direct_model():
    c = compared(ToyCarTwoNormals)
    assert not c.equivalent
    assert c.judgement.odd == ["newton_euler"]
    assert "do not determine the reactions F_r, F_s" in c.verdict_line()
    assert {mm.model for mm in c.mismatches} == {"newton_euler"}


def test_undetermined_reactions_do_not_make_the_motion_different():
    c = compared(ToyCarTwoNormals)
    motion = next(p for p in c.pairs if p.kind == "motion" and p.candidate == "newton_euler")
    assert "NOT equivalent" not in str(motion).splitlines()[0]


def test_reactions_of_agreeing_models_are_not_called_different():
    c = compared(ToyCarNoCos2)
    holders = [p for p in c.pairs if p.kind == "reactions"]
    assert holders, "toy_car: newton_euler and multiplier both give F_r"
    for p in holders:
        assert "DIFFERENT" not in str(p), str(p)


@pytest.mark.parametrize("cls", [ToyCarTrackAlongI, BlockOnWedgeHalfNormal])
def test_a_pair_seen_at_one_point_does_not_claim_certainty(cls):
    c = compared(cls)
    for p in c.pairs:
        if p.equivalent:
            line = str(p).splitlines()[0]
            # a bound of 0 prints "< 1e-300": certainty that one point cannot give (no bound
            # at all, or a positive one, is honest)
            assert not (p.bound == 0 and p.points < 20), line
            assert "<= <" not in line


# -- two derivations: both are suspects ----------------------------------------------------------
class _NoReferee:
    referee = False   # two derivations only: the tie path of the vote


def test_two_derivations_that_disagree_are_both_suspects():
    """By hand: ``V = k y^2`` adds ``k y`` to the y equation only."""
    c = compared(type("TwoOnly", (_NoReferee, PendulumOnMassStiffSpring), {}))
    j = c.judgement
    assert set(j.odd) == {"lagrange", "newton_euler"}
    assert j.majority == ()
    assert "no majority, every side is a suspect" in c.verdict_line()
    lagrange = mismatches_of(c, "lagrange")
    assert set(lagrange) == {"Lagrange, y"}
    s = lagrange["Lagrange, y"].state
    assert lagrange["Lagrange, y"].value == pytest.approx(s["k"] * s["y"], rel=1e-9)
    direct = mismatches_of(c, "newton_euler")
    assert direct and set(direct) <= set(c.problem.model("newton_euler").labels)
    assert_readable(c)


def test_the_referee_breaks_the_tie_and_names_the_wrong_lagrangian():
    """The same problem with its referee: ``lagrange`` is named, and the note says the
    majority shares the direct model's declarations."""
    c = compared(PendulumOnMassStiffSpring)
    assert c.judgement.odd == ["lagrange"]
    assert set(c.judgement.majority) == {"newton_euler", "referee"}
    assert "may lie in a shared declaration of `newton_euler`" in c.verdict_line()


def test_a_reaction_outvoted_only_by_the_direct_model_and_its_referee_stays_a_tie():
    """The direct model and its referee share the declarations: agreeing on N1 they do not
    outvote the multiplier model (the mistake could be a shared load), so both are
    suspects and the note says why."""
    c = compared(BlockOnWedgeHalfNormal)
    (fault,) = c.judgement.reaction_faults
    assert fault.name == "N1" and set(fault.suspects) == {"newton_euler",
                                                          "lagrange_multipliers"}
    assert fault.agreeing == ()
    assert "may lie in a shared declaration of `newton_euler`" in c.verdict_line()


def test_a_reaction_given_differently_by_its_two_holders():
    """By hand: with the constraint ``2 d1 = 0`` the multiplier is ``N1 / 2``; N2 is right."""
    c = compared(type("TwoOnly", (_NoReferee, BlockOnWedgeHalfNormal), {}))
    j = c.judgement
    assert not c.equivalent
    assert not j.faults   # the motion is right in every derivation
    assert [r.name for r in j.reaction_faults] == ["N1"]
    assert set(j.reaction_faults[0].suspects) == {"newton_euler", "lagrange_multipliers"}
    assert c.verdict_line() == ("DISAGREEMENT: reaction N1: `newton_euler` and "
                                "`lagrange_multipliers` give different values")
    motion = [p for p in c.pairs if p.kind == "motion"]
    assert motion and all(p.equivalent for p in motion)


def test_a_reaction_tie_is_reported_once_per_suspect():
    c = compared(type("TwoOnly", (_NoReferee, BlockOnWedgeHalfNormal), {}))
    lines = [p for p in c.pairs if p.kind == "reactions"]
    assert len(lines) == 1
    assert {mm.model for mm in c.mismatches} == {"newton_euler", "lagrange_multipliers"}


# -- one derivation: nothing was checked ---------------------------------------------------------
def test_a_single_derivation_is_not_checked():
    c = compared(SatelliteLagrangeOnly)
    assert not c.equivalent
    assert c.verdict_line().startswith("NOT CHECKED")
    assert "agree" not in c.verdict_line()
    assert "all derivations agree" not in str(c)
    assert c.to_dict()["equivalent"] is False


# -- printed equation sets -------------------------------------------------------------------------
def test_printed_sets_that_determine_nothing_are_wrong_with_the_reason():
    verdicts = {v.label: v for v in compared(SatellitePrintedSets).published}
    for label in ("(e1, 2 e1)", "0 = 0, 0 = 0", "e1 alone"):
        assert verdicts[label].verdict == "wrong", label
        assert "does not determine every acceleration" in verdicts[label].detail
    assert verdicts["(e2, e1 + e2)"].verdict == "correct"
    assert verdicts["e1 as an equation"].verdict == "correct"
    (zero,) = compared(MassSpringZeroEqualsZero).published
    assert zero.verdict == "wrong"
    assert "does not determine every acceleration" in zero.detail


def test_printed_set_detail_counts_in_words():
    (zero,) = compared(MassSpringZeroEqualsZero).published
    assert "1 coordinates" not in zero.detail and "1 equation(s)" not in zero.detail


# -- the command line: exit statuses ---------------------------------------------------------------
@pytest.fixture
def broken_catalogue(monkeypatch):
    """The catalogue with the hand-broken problems (and nothing else) in it."""
    classes = {"toy_car_no_cos2": ToyCarNoCos2, "satellite_lagrange_only": SatelliteLagrangeOnly,
               "mass_spring_gravity": MassSpringGravity}

    def module_of(name):
        if name not in classes:
            raise KeyError(f"no problem named {name!r}; known problems: {', '.join(classes)}.")
        return problems.Declaration("test_blame", classes[name].__name__, name, name, "test",
                                    "", (), ())

    monkeypatch.setattr(problems, "module_of", module_of)
    monkeypatch.setattr(problems, "get", lambda name, **_: classes[name]())
    monkeypatch.setattr(problems, "all_problems", lambda: [cls() for cls in classes.values()])
    return classes


def test_check_exit_statuses_of_broken_models(broken_catalogue, capsys):
    assert main(["check", "mass_spring_gravity", "--points", "2"]) == 0
    assert main(["check", "toy_car_no_cos2", "--points", "2"]) == 1
    out = capsys.readouterr().out
    assert ("`lagrange` disagrees with `newton_euler`, `angular_momentum`, `multiplier`, "
            "`referee` and `referee (angular_momentum)`") in out
    status = main(["check", "satellite_lagrange_only", "--points", "2"])
    captured = capsys.readouterr()
    assert status == 1   # nothing was compared: not a success
    assert "NOT CHECKED" in captured.out and "Traceback" not in captured.err


def test_a_residual_that_cannot_be_solved_symbolically_says_so():
    """copying_machine's reference has a massless link (a static row): its accelerations have
    no symbolic solution, so the residual of a broken model says why it is not shown and
    the values at a state stand in for it (the drive's sign flipped in `reduced`)."""
    from dualmech.problems.copying_machine import CopyingMachine

    class DriveFlipped(CopyingMachine):
        def reduced(self):
            return dataclasses.replace(super().reduced().flipped("drive"), name="reduced")

    c = compare(DriveFlipped())
    assert c.judgement.odd == ["reduced"]
    (mm,) = c.mismatches
    assert mm.residual.startswith("(not solved symbolically:")
    assert "see the values below" in str(mm) and mm.terms
    F = next(v for term, v in mm.terms if term == "F")
    assert mm.state["F"] == pytest.approx(F)     # the drive term is the applied force itself
