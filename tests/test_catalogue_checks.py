"""The checks every catalogue problem passes: one test per check and problem (ids: the names).

Every problem's own file, ``tests/test_<module>.py``, keeps only what was derived by hand for
that problem (reactions solved on paper, the source's errata, special states); what every
problem must do is checked here:

* its declaration validates and lists the derivations expected of it;
* every derivation gives the reference derivation's motion, decided exactly (the method is
  named);
* every declared reaction is recovered as a function of the state, every derivation that
  carries it gives the same one, and it is carried by two derivations at least;
* each printed answer of the source gets the verdict derived by hand;
* the dimensions of every derived equation and reaction are consistent.

The expected derivations and verdicts are in ``tests/_catalogue_expected.py``: a new problem
needs an entry there.
"""
import pytest

from _catalogue_expected import BOUND, MODELS, VERDICTS, catalogue_params
from dualmech import t
from dualmech.problems import declarations, get

NAMES = [d.name for d in declarations()]


def test_the_catalogue_and_its_expectations_name_the_same_problems():
    assert len(NAMES) == len(set(NAMES))
    missing = sorted(set(NAMES) - set(MODELS) | set(NAMES) - set(VERDICTS))
    assert not missing, f"add {missing} to MODELS and VERDICTS in tests/_catalogue_expected.py"
    assert set(MODELS) == set(VERDICTS) == set(NAMES), "an expectation names no problem"


@pytest.fixture
def comparison(request, compared):
    return compared(request.node.callspec.params["name"])


@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_declaration_validates(name):
    problem = get(name)
    problem.validate()
    assert problem.model_names == MODELS.get(name)


@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_every_derivation_has_the_reference_motion_exactly(name, comparison):
    problem = comparison.problem
    assert comparison.equivalent, str(comparison)
    motion = [p for p in comparison.pairs if p.kind == "motion"]
    assert [p.reference for p in motion] == [problem.reference] * len(motion)
    assert [p.candidate for p in motion] == [n for n in problem.model_names
                                             if n != problem.reference]
    for p in comparison.pairs:
        # exact: evaluation at random rational points, a false "equal" below 1e-60 (or the
        # problem's own bound, BOUND, where its degree leaves 8 points short of that)
        assert p.method == "exact", (p.kind, p.candidate, p.method)
        assert p.equivalent and p.bound < BOUND.get(problem.name, 1e-60), str(p)


def _carriers(problem) -> dict:
    """Declared reaction -> the derivations that have it as an unknown, in declaration order."""
    return {r.name: [n for n, m in problem.models().items()
                     if r.name in {u.name for u in m.unknowns}] for r in problem.reactions}


@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_every_reaction_is_recovered_and_its_derivations_agree(name, comparison):
    problem = comparison.problem
    carriers = _carriers(problem)
    assert comparison.reaction_derivations == carriers
    # a second derivation: another model, or the referee Kane's method derives from the
    # direct model's declarations (the bicycle's joint reactions: no multiplier model has them)
    refereed = {r for r, held in comparison.referee_derivations.items() if held}
    single = [r for r, held in carriers.items() if len(held) < 2 and r not in refereed]
    assert not single, f"{single}: derive each reaction a second time (e.g. as a multiplier)"
    assert comparison.not_cross_checked == []
    # recovered: a function of the state and the parameters, no acceleration, no unknown --
    # or, past the display budget (DESIGN.md: verdict first, display on demand), said so
    recovered = comparison.reactions
    if carriers and not recovered:
        assert any(n.startswith("reactions not solved symbolically")
                   for n in comparison.display_notes), comparison.display_notes
    else:
        assert set(recovered) == set(carriers)
    allowed = set(problem.parameter_symbols) | {t}
    for r, value in recovered.items():
        assert not value.has(*[q.diff(t, 2) for q in problem.coordinate_functions]), r
        assert value.free_symbols <= allowed, (r, value.free_symbols - allowed)
    compared = set()
    for p in (p for p in comparison.pairs if p.kind == "reactions"):
        assert p.equivalent and p.method == "exact", str(p)
        held = {p.reference, *p.candidate.split(", ")}
        assert all(set(carriers[r]) == held for r in p.reactions), (p.reactions, held)
        compared |= set(p.reactions)
    assert compared | {r for r in refereed if len(carriers[r]) < 2} == set(carriers)


@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_printed_answers_get_the_verdicts_derived_by_hand(name, comparison):
    published = comparison.published
    assert {v.label: v.verdict for v in published} == VERDICTS.get(name)
    # a stability claim is judged on the exact linearisation (eigenvalues by mpmath), every
    # other printed answer by the exact rational-point test
    from dualmech.verify.stability_claims import METHOD, STABILITY_KINDS
    kinds = {p.label: p.kind for p in comparison.problem.published()}
    assert [v.method for v in published] == [METHOD if kinds[v.label] in STABILITY_KINDS
                                             else "exact" for v in published]


@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_dimensions_of_every_equation_and_reaction_are_consistent(name, comparison):
    assert comparison.dimension_issues == []

