"""An honest mutation score (dualmech.verify.mutation): what raises or gets no verdict is reported
apart, `points` is validated, one derivation alone is refused, `_identical` never calls
a mutant identical without evaluating it, a survivor is called equivalent only when it
gives its original's motion and every one of its reactions, and an unknown reaction's flipped
sign is caught by the reactions comparison."""
import pytest
import sympy as sp

from dualmech import EquationSet, coordinate, t
from dualmech.verify.mutation import (MutationReport, _against_original, _equivalent, _identical,
                                     _in_ref, mutation_report)
from dualmech.problems import get


@pytest.mark.parametrize("points", [0, -1, 1.5, True, "3", 10**6])
def test_points_is_validated(points):
    with pytest.raises(ValueError, match="`points` must be an integer from 1 to 1000"):
        mutation_report(get("simple_pendulum"), points=points)


def test_single_derivation_problem_is_refused():
    p = get("simple_pendulum")

    class Single(type(p)):
        def models(self):
            return {"lagrange": super().models()["lagrange"]}

    with pytest.raises(ValueError, match="single derivation"):
        mutation_report(Single())


def test_errored_and_undetermined_mutants_are_not_kills():
    r = MutationReport("x", killed=[("a", ["m: differs"])], survived=["b"],
                       errored=[("c", "ValueError: boom")],
                       undetermined=[("d", "no verdict")])
    assert r.total == 2 and r.kill_rate == 0.5
    text = str(r)
    assert "1/2 mutants caught (50 %)" in text and "1 errored, 1 undetermined" in text
    assert "ERRORED: c: ValueError: boom" in text and "UNDETERMINED: d" in text
    empty = MutationReport("y", errored=[("c", "boom")])
    assert empty.total == 0 and empty.kill_rate != empty.kill_rate    # nan: nothing judged
    assert "no verdict" in str(empty)


def test_identical_is_not_claimed_when_no_sample_can_be_evaluated():
    # every sample divides by zero: sin^2 + cos^2 - 1 is exactly 0 at the rational points
    # of the unit circle -- so nothing shows the two are the same
    x = coordinate("x")
    zero = sp.sin(x)**2 + sp.cos(x)**2 - 1
    a = EquationSet("a", (x,), (x.diff(t, 2) + sp.sin(x) / zero,))
    b = EquationSet("b", (x,), (x.diff(t, 2),))
    assert _identical(b, a, ()) is False


def test_mutants_that_raise_are_counted_apart(monkeypatch):
    import dualmech.verify.mutation as mutation
    real = mutation.judge
    calls = {"n": 0}

    def flaky(*args, **kwargs):
        calls["n"] += 1
        if calls["n"] == 2:   # (call 1 judges the unbroken derivations)
            raise ValueError("a mutant the comparator cannot take")
        return real(*args, **kwargs)

    monkeypatch.setattr(mutation, "judge", flaky)
    r = mutation_report(get("simple_pendulum"), points=1)
    assert len(r.errored) == 1 and "cannot take" in r.errored[0][1]
    assert r.errored[0][0] not in [d for d, _ in r.killed]
    assert r.kill_rate == 1.0


def test_equivalent_mutants_are_reported_apart_and_not_counted():
    r = MutationReport("x", killed=[("a", ["m: differs"])],
                       equivalent=["m: flip the sign of `constraint N`"])
    assert r.total == 1 and r.kill_rate == 1.0
    text = str(r)
    assert "1/1 mutants caught" in text and "1 equivalent (same motion and reactions)" in text
    assert "EQUIVALENT: m: flip the sign of `constraint N`" in text


def _against_itself(problem, model: str, edit):
    from dualmech.verify.check import claims_of
    from dualmech.verify.sampling import Context
    original = problem.in_reference_coordinates(problem.model(model))
    mutant = _in_ref(problem, edit(problem.model(model)), problem.model(model))
    ctx = Context(problem.model(problem.reference).coordinates, problem.parameter_symbols,
                  problem)
    j = _against_original(original, mutant, ctx, 3, 0, claims_of(problem).get(model))
    return _equivalent(j, original, mutant)


def test_a_flipped_multiplier_is_equivalent_only_where_it_vanishes():
    # block_in_pipe: N = 0 identically, so -N is N; restrained_pendulum: H is not zero, so
    # the flipped constraint gives another H -- a wrong model, never an equivalent one
    flip = lambda name: lambda m: m.flipped(f"constraint {name}")  # noqa: E731
    assert _against_itself(get("block_in_pipe"), "multiplier", flip("N")) is True
    assert _against_itself(get("restrained_pendulum"), "multiplier", flip("H")) is False
    # a dropped multiplier loses the reaction: not equivalent either, even where it is zero
    drop = lambda m: m.without("constraint N")  # noqa: E731
    assert _against_itself(get("block_in_pipe"), "multiplier", drop) is False


@pytest.mark.slow
def test_every_unknown_reaction_of_every_model_gets_a_sign_flip():
    from dualmech.verify.mutation import mutants
    p = get("compound_double_pendulum")
    flips = {m.description: m for m in mutants(p) if "sign of unknown" in m.description}
    expected = {f"{name}: flip the sign of unknown `{u}`"
                for name, model in p.models().items() for u in model.unknowns}
    assert set(flips) == expected and len(expected) == 4     # R_x, R_y in two models each


def test_a_flipped_unknown_reaction_keeps_the_motion_and_negates_the_reaction():
    # independent of the comparator: solve both models symbolically (toy_car is small)
    from dualmech.verify.mutation import mutants
    p = get("toy_car")
    model = p.model("newton_euler")
    (flip,) = [m for m in mutants(p) if m.description == "newton_euler: flip the sign of "
               "unknown `F_r`"]
    F_r = model.unknowns[0]
    before, after = model.solve(), flip.equations.solve()
    for a in model.accelerations:
        assert sp.simplify(before[a] - after[a]) == 0
    assert sp.simplify(before[F_r] + after[F_r]) == 0 and sp.simplify(before[F_r]) != 0


@pytest.fixture(scope="module")
def toy_car_report():
    return mutation_report(get("toy_car"))


@pytest.mark.parametrize("model", ["newton_euler", "multiplier"])
def test_a_flipped_unknown_reaction_is_caught_by_the_reactions_alone(toy_car_report, model):
    # the car's motion cannot change (F_r is only renamed), so the catch must be the
    # comparison of F_r with the other model that derives it -- and nothing else
    killed = dict(toy_car_report.killed)
    assert killed[f"{model}: flip the sign of unknown `F_r`"] == ["reaction F_r"]
