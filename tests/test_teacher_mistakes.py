"""Two-model teacher problems with injected mistakes: the diagnosis names the quantity and term.

Issue 25, points 2 and 5.  The problems live in ``tests/corpus/teacher_mistakes/`` -- files a
teacher writes outside the catalogue (a rod on a pushed cart, a bead on a spinning parabola,
a ladder on a smooth floor and wall), each with two models only (``newton_euler`` and
``lagrange``), so that the vote names nobody.  Each variant there injects one mistake (a
missing transport term in T, a wrong inertia, the sign of a load or a potential, a reaction
drawn the wrong way, moments about a moving point taken as if it were fixed); its docstring
derives by hand the term that is wrong, and ``MISTAKES`` records the quantity and the term a
diagnosis must name.  Asserted for each: the quantity and that exact term (compared
symbolically) are named, and no statement the diagnosis calls certain names another
quantity or blames the model that holds no mistake.  The share named is reported and must
reach 90 %.
"""
from __future__ import annotations

import functools
import importlib.util
from pathlib import Path

import pytest
import sympy as sp

from dualmech.verify.check import compare
from _diagnosis_match import names as _names, same as _same

CORPUS = Path(__file__).parent / "corpus" / "teacher_mistakes"
LAGRANGE_PARTS = {"kinetic", "potential", "lagrange"}


def _module(path: Path):
    spec = importlib.util.spec_from_file_location(f"teacher_{path.stem}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


MODULES = [_module(p) for p in sorted(CORPUS.glob("*.py"))]
CASES = [(cls, subject, term) for mod in MODULES for cls, subject, term in mod.MISTAKES]
#: mistakes that change a reaction only (a pulley's weight left out of its axle's balance)
REACTION_ONLY = [case for mod in MODULES for case in getattr(mod, "REACTION_ONLY", [])]
#: mistakes the diagnosis does not name yet, with the reason
OPEN: dict = {}


@functools.lru_cache(maxsize=None)
def diagnosed(cls):
    """The comparison of the two teacher models alone (no referee: the vote names nobody, so
    the diagnosis must stand on the energies and the edits)."""
    c = compare(type(cls.__name__, (cls,), {"referee": False})())
    return c, c.diagnosis


@functools.lru_cache(maxsize=None)
def refereed(cls):
    return compare(cls())


def named(cls, subject, term) -> bool:
    _, d = diagnosed(cls)
    return bool(d) and any(_names(s, subject, term) for s in d.statements)


def faulty_model(cls) -> str:
    """The model a variant breaks: the Lagrangian if it overrides a Lagrange part."""
    own = {k for k in vars(cls) if not k.startswith("_")}
    return "lagrange" if own & LAGRANGE_PARTS else "newton_euler"


@pytest.mark.parametrize("cls,subject,term", [
    pytest.param(*case, id=case[0].__name__,
                 marks=[pytest.mark.xfail(strict=True, reason=OPEN[case[0].__name__])]
                 if case[0].__name__ in OPEN else [])
    for case in CASES])
def test_the_mistake_is_named(cls, subject, term):
    c, d = diagnosed(cls)
    assert not c.equivalent, "the injected mistake must change the motion"
    assert c.judgement.majority == (), "two models: the vote names nobody"
    assert named(cls, subject, term), d.text() if d else "no diagnosis"


@pytest.mark.parametrize("cls,subject,term", CASES, ids=[c[0].__name__ for c in CASES])
def test_nothing_wrong_is_named_with_certainty(cls, subject, term):
    _, d = diagnosed(cls)
    for s in (d.statements if d else []):
        if not s.certain:
            continue
        if s.kind == "balance":     # "the error is in a balance of <direct model>"
            assert faulty_model(cls) == s.model, s.text()
        else:
            assert subject in s.subject, s.text()


def test_the_share_named_reaches_90_percent():
    hits = [named(*case) for case in CASES]
    share = sum(hits) / len(hits)
    print(f"named {sum(hits)} of {len(hits)} injected mistakes ({share:.0%})")
    assert len(hits) >= 12 and share >= 0.9


def test_the_correct_problems_have_nothing_to_diagnose():
    for mod in MODULES:
        base = next(c for c in vars(mod).values() if isinstance(c, type)
                    and c.__module__ == mod.__name__ and c.__name__[0] != "_"
                    and not any(c is m[0] for m in mod.MISTAKES))
        c = compare(base())
        assert c.equivalent and c.diagnosis is None, c.text()


def test_the_report_names_the_term_in_the_teachers_notation_within_the_width():
    """The text of ``dualmech check``: the diagnosis in dotted notation (``θ̇``, ``ẋ``, no
    ``Derivative``), every line but the verdict at most 100 columns (output not a terminal; unwrapped,
    the pin's reactions' "not cross-checked" line is 182)."""
    cls = next(c for c, *_ in CASES if c.__name__ == "NoTransportTerm")
    c, _ = diagnosed(cls)
    text = c.text()
    assert "diagnosis:" in text
    assert "T of rod: `lagrange` is missing the term l m cos(\u03b8) \u03b8\u0307 x\u0307/2" \
        in " ".join(line.strip() for line in text.splitlines())
    assert "Derivative" not in text and "theta" not in text.split("diagnosis:")[1]
    # (the verdict stays one line, for scripts that grep it)
    assert max(len(line) for line in text.splitlines()
               if not line.startswith("  verdict: ")) <= 100
    d = c.to_dict()["diagnosis"]["statements"][0]
    assert d["subject"] == "T of rod" and d["kind"] == "missing" and d["certain"]
    assert d["terms"] == [["missing", None, "l*m*cos(theta)*theta'*x'/2"]]


@pytest.mark.parametrize("cls", [c for c, *_ in CASES], ids=[c.__name__ for c, *_ in CASES])
def test_counter_example_states_lie_in_the_declared_ranges(cls):
    """Each row is shown at a state inside the problem's Coordinate and Parameter ranges
    (and t >= 0), unless the mismatch says it is outside them."""
    c, _ = diagnosed(cls)
    p = c.problem
    ranges = {str(q.symbol): q.range for q in p.parameters}
    for q in p.coordinates:
        ranges[q.name], ranges[q.name + "'"] = q.range, q.rate_range
    shown = [mm for mm in c.mismatches if mm.state]
    assert shown
    for mm in shown:
        if mm.outside:
            continue
        for name, value in mm.state.items():
            lo, hi = ranges.get(name, (0.0, float("inf")) if name == "t" else (-1e300, 1e300))
            assert lo <= value <= hi, (mm.equation, name, value)


def test_a_balance_row_is_shown_as_mass_times_acceleration_minus_applied():
    """newton_euler's rows are ``sum F - m a``; the text reverses them (and says so), so that
    a load reads with the sign it has in the Lagrangian's rows: the push on the cart, a
    term ``+F`` of ``sum F . O.x (cart)``, is shown ``-F`` (its value negated)."""
    cls = next(c for c, *_ in CASES if c.__name__ == "PushReversed")
    c, _ = diagnosed(cls)
    direct = [mm for mm in c.mismatches if mm.model == "newton_euler" and mm.sign == -1]
    assert direct
    for mm in direct:
        text = mm.text()
        assert "sign reversed to read: mass times acceleration minus applied = 0" in \
            " ".join(text.split())
        assert f"residual {-mm.value:.6g}" in text


@pytest.mark.parametrize("cls", [case[0] for case in CASES], ids=lambda c: c.__name__)
def test_with_the_referee_the_vote_names_the_faulty_model(cls):
    """With the Kane referee (derived from the direct model's declarations) the vote has a
    majority: a Lagrangian mistake is outvoted; a mistake in the direct model's balances is
    named by its own referee; one in a declaration the referee shares is said to possibly lie
    in that shared declaration -- never the Lagrangian named without that caution."""
    c = refereed(cls)
    j = c.judgement
    assert not c.equivalent
    text = "\n".join(j.notes) + "\n" + c.verdict_line()
    if faulty_model(cls) == "lagrange":
        assert j.odd == ["lagrange"] and "newton_euler" in j.majority, (j.odd, j.majority)
    elif "newton_euler" not in j.odd:
        assert "shared declaration" in text, (j.odd, j.majority, text)


@pytest.mark.parametrize("cls,reaction,change", REACTION_ONLY,
                         ids=[c[0].__name__ for c in REACTION_ONLY])
def test_a_reaction_only_mistake_is_caught_by_the_referee(cls, reaction, change):
    """A mistake that leaves the motion as it is and changes one reaction (a weight left out
    of a balance that only that reaction closes) is invisible to two models; the toolkit's
    own Kane referee, derived from the direct model's declarations, names the direct model,
    the reaction, and the residual of the faulty row: the hand-derived missing term."""
    assert diagnosed(cls)[0].equivalent, "two models alone cannot see a reaction-only slip"
    c = refereed(cls)
    assert not c.equivalent
    assert c.judgement.odd == ["newton_euler"], c.verdict_line()
    assert f"the reaction {reaction} differs" in c.verdict_line()
    rows = [mm for mm in c.mismatches if mm.model == "newton_euler"
            and mm.equation == f"reaction {reaction}"]
    assert rows, [mm.equation for mm in c.mismatches]
    residuals = [mm._resolved() for mm in rows]
    assert any(isinstance(r, sp.Expr) and (_same(r, change) or _same(r, -change))
               for r in residuals), residuals

