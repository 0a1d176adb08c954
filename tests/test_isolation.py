"""One faulty piece never sinks the rest: a bad printed answer is reported on that answer,
a wrong model (T = 0) is a mismatch with a reason, a name where a problem belongs is a
TypeError that shows the fix."""
import pytest
import sympy as sp

from dualmech import Lagrangian
from dualmech.verify.check import compare
from dualmech.model.problem import Published
from dualmech.problems.copying_machine import CopyingMachine
from dualmech.problems.coupled_pendulums import CoupledPendulums
from dualmech.problems.restrained_pendulum import RestrainedPendulum, g, l, m, theta


class _UndeclaredMu(RestrainedPendulum):
    """A printed answer that uses a symbol the problem does not declare."""

    def published(self):
        mu = sp.Symbol("mu", positive=True)
        return super().published() + [Published("friction", "expression", (mu * m * g,),
                                                (m * g,))]


def test_undeclared_symbol_is_reported_on_that_answer_and_the_rest_stands():
    c = compare(_UndeclaredMu())
    assert c.equivalent and c.verdict_line().startswith("all derivations agree")
    verdicts = {v.label: v for v in c.published}
    assert verdicts["friction"].verdict == "unchecked"
    assert "undeclared symbol(s) mu" in verdicts["friction"].detail
    # every other printed answer keeps the verdict it has without the faulty one
    plain = {v.label: v.verdict for v in compare(RestrainedPendulum()).published}
    assert {k: v.verdict for k, v in verdicts.items() if k != "friction"} == plain


class _UndecidableOne(RestrainedPendulum):
    """A printed answer the comparator cannot evaluate (an undefined function of the state)."""

    def published(self):
        f = sp.Function("f")
        return super().published() + [Published("odd", "expression", (f(theta) * m,), (m,))]


def test_an_undecidable_answer_does_not_make_the_others_undecidable():
    c = compare(_UndecidableOne())
    verdicts = {v.label: v for v in c.published}
    assert verdicts["odd"].verdict == "unchecked" and "f(theta)" in verdicts["odd"].detail
    plain = {v.label: v.verdict for v in compare(RestrainedPendulum()).published}
    assert {k: v.verdict for k, v in verdicts.items() if k != "odd"} == plain


class _NoKineticEnergy(RestrainedPendulum):
    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[theta])
        lg.potential("gravity", m * g * l * (1 - sp.cos(theta)))
        return lg.equations()


class _CopyingNoT(CopyingMachine):
    """Every Lagrangian model with T = 0: the static rows leave y'' free."""

    def lagrange(self):
        eqs = super().lagrange()
        return eqs.substitute({sym: 0 for sym in eqs.equations[0].free_symbols
                               if str(sym) == "m2"})


class _CoupledNoT(CoupledPendulums):
    """T = 0 in the Lagrangian model; the printed answers are built from that model."""

    def lagrange(self):
        eqs = super().lagrange()
        return eqs.substitute({sym: 0 for e in eqs.equations for sym in e.free_symbols
                               if str(sym) == "m"})


@pytest.mark.parametrize("cls", [_NoKineticEnergy, _CopyingNoT, _CoupledNoT],
                         ids=["pendulum", "copying_machine", "coupled_pendulums"])
def test_a_model_without_kinetic_energy_is_a_mismatch_with_a_reason(cls):
    c = compare(cls())                  # never raises on a wrong model
    assert not c.equivalent
    assert "lagrange" in c.verdict_line()
    text = str(c)
    assert "NOT equivalent" in text
    assert all(v.verdict == "unchecked" for v in c.published)
    assert c.to_dict()["equivalent"] is False


def test_a_name_where_a_problem_belongs_is_a_type_error_showing_the_fix():
    with pytest.raises(TypeError, match=r"compare\(dualmech\.problems\.get\('toy_car'\)\)"):
        compare("toy_car")
    with pytest.raises(TypeError, match="must be a Problem"):
        compare(42)
