"""An honest mutation score (dualmech.mutation): what raises or gets no verdict is reported
apart, `points` is validated, one derivation alone is refused, and `_identical` never calls
a mutant identical without evaluating it."""
import pytest
import sympy as sp

from dualmech import EquationSet, coordinate, t
from dualmech.mutation import MutationReport, _identical, mutation_report
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
    import dualmech.mutation as mutation
    real = mutation.judge
    calls = {"n": 0}

    def flaky(*args, **kwargs):
        calls["n"] += 1
        if calls["n"] == 1:
            raise ValueError("a mutant the comparator cannot take")
        return real(*args, **kwargs)

    monkeypatch.setattr(mutation, "judge", flaky)
    r = mutation_report(get("simple_pendulum"), points=1)
    assert len(r.errored) == 1 and "cannot take" in r.errored[0][1]
    assert r.errored[0][0] not in [d for d, _ in r.killed]
    assert r.kill_rate == 1.0
