r"""The grader on problems whose models hold a surd constant (``cos 30 deg = sqrt(3)/2``).

Square roots of rational constants are evaluated exactly in the field ``Q(sqrt p_1, ...)``
(:class:`dualmech.exact.surds.Surd`, over prime radicands), and ``sin``/``cos`` of multiples
of ``pi/12`` with them, so T, V, L and Q on such a problem get an exact verdict where they
were refused ("the fast exact evaluator cannot handle" its models).  Every expected value
below is derived by hand in the problem files' docstrings:
``tests/corpus/surd_problems/wedge_30.py`` (a block on a free 30-degree wedge: ``T = (M + m)
X'^2/2 + (sqrt(3)/2) m X' s' + m s'^2/2``) and ``tests/corpus/teacher_problems/forced_block.py``
(a push at 30 degrees: ``Q_x = sqrt(3) F/2``).
"""
from __future__ import annotations

import subprocess
import sys
import time
from fractions import Fraction
from pathlib import Path

import pytest
import sympy as sp

from dualmech.exact.surds import Surd
from dualmech.grade import Grader
from dualmech.grade.formula import Env, Formula, NotExactHere
from dualmech.grade.roots import MAX_ROOTS, surd_constant
from dualmech.grade.parser import parse
from dualmech.grade.vocabulary import Vocabulary

CORPUS = Path(__file__).resolve().parent / "corpus"
WEDGE = CORPUS / "surd_problems" / "wedge_30.py"
BLOCK = CORPUS / "teacher_problems" / "forced_block.py"
RIGHT_T = "(M+m) X'^2/2 + √3/2 m X' s' + m s'^2/2"


@pytest.fixture(scope="module")
def wedge():
    return Grader(str(WEDGE))


@pytest.fixture(scope="module")
def block():
    return Grader(str(BLOCK))


# -- the exact values ---------------------------------------------------------------------------
def _value(text: str, symbols=()):
    f = Formula.from_node(parse(text)[0].lhs, Vocabulary.build(parameters=list(symbols)))
    return f, f.evaluate(Env({}, atoms={}))


def test_square_roots_of_constants_are_exact_over_prime_radicands():
    r3 = Surd.root(3)
    f, v = _value("sqrt(12)/4")
    assert f.exact and v == r3 / 2          # sqrt(12) = 2 sqrt(3)
    assert _value("sqrt(6)")[1] == Surd.root(2) * r3   # one field for sqrt 6, 2 and 3
    assert _value("sqrt(3/4)")[1] == r3 / 2
    assert _value("3^(3/2)")[1] == 3 * r3
    assert _value("1/sqrt(3)")[1] == r3 / 3
    assert _value("sqrt(9/4)")[1] == Fraction(3, 2)   # a square: rational
    assert _value("sqrt(3)/2")[1] != Fraction(1, 2)   # the slip the grader must see


def test_angles_in_twelfths_of_pi_are_exact():
    r2, r3 = Surd.root(2), Surd.root(3)
    assert _value("cos(pi/6)")[1] == r3 / 2 and _value("sin(pi/6)")[1] == Fraction(1, 2)
    assert _value("sin(pi/4)")[1] == r2 / 2
    assert _value("cos(pi/12)")[1] == (r2 * r3 + r2) / 4        # (sqrt 6 + sqrt 2)/4
    assert _value("tan(pi/3)")[1] == r3
    assert _value("cos(5*pi/6)")[1] == -r3 / 2


def test_what_stays_inexact():
    x = sp.Symbol("x", positive=True)
    assert surd_constant(("rpow", ("s", x), Fraction(1, 2))) is None     # a root of a symbol
    assert surd_constant(("rpow", ("c", Fraction(2)), Fraction(1, 3))) is None   # a cube root
    assert surd_constant(("rpow", ("c", Fraction(-3)), Fraction(1, 2))) is None  # imaginary
    many = " + ".join(f"sqrt({p})" for p in (2, 3, 5, 7, 11)[:MAX_ROOTS + 1])
    assert not _value(many)[0].exact       # 2**5 coordinates: left to mpmath, never slow
    # a root of a symbol is kept exact where its radicand is no rational square there, and
    # leaves the exact method where it is (sqrt(x^2) = |x|: tests/test_grade_state_roots.py)
    root = Formula.from_sympy(sp.sqrt(x))
    assert root.exact and root.state_roots
    assert root.evaluate(Env({x: Fraction(2)})) == Surd.root(2)
    with pytest.raises(NotExactHere):
        root.evaluate(Env({x: Fraction(4)}))


# -- T, V, L and Q on the 30-degree wedge -------------------------------------------------------
def test_a_right_kinetic_energy_with_a_surd_is_accepted_exactly(wedge):
    r = wedge.grade(RIGHT_T, "KE")
    assert r.right and r.method.startswith("exact rational-point test"), r
    assert wedge.grade("(M+m) X'^2/2 + cos(pi/6) m X' s' + m s'^2/2", "KE").right


@pytest.mark.parametrize("text, term, correct", [
    # a 1/2 where sqrt(3)/2 belongs (sin for cos of 30 degrees)
    ("(M+m) X'^2/2 + m X' s'/2 + m s'^2/2", "X'*m*s'/2", "sqrt(3)*X'*m*s'/2"),
    # the 1/2 dropped from sqrt(3)/2
    ("(M+m) X'^2/2 + √3 m X' s' + m s'^2/2", "sqrt(3)*X'*m*s'", "sqrt(3)*X'*m*s'/2"),
], ids=["half-for-root3-half", "dropped-half"])
def test_a_wrong_surd_coefficient_in_T_is_rejected_and_named(wedge, text, term, correct):
    r = wedge.grade(text, "KE")
    assert r.status == "wrong" and r.method.startswith("exact rational-point test"), r
    assert [(e.kind, e.term, e.correct, e.category) for e in r.edits] == \
        [("coefficient", term, correct, "a kinetic-energy term")], r


def test_V_and_L_and_the_equations_on_the_wedge(wedge):
    assert wedge.grade("-m g s/2", "PE").right
    wrong = wedge.grade("-m g s √3/2", "PE")          # cos 30 where sin 30 belongs
    assert [(e.kind, e.correct) for e in wrong.edits] == [("coefficient", "-g*m*s/2")]
    assert wedge.grade(RIGHT_T + " + m g s/2", "L").right
    assert wedge.grade("(M+m) X'' + √3/2 m s'' = 0; m s'' + √3/2 m X'' - m g/2 = 0").right
    eom = wedge.grade("(M+m) X'' + 1/2 m s'' = 0; m s'' + √3/2 m X'' - m g/2 = 0")
    assert [(e.kind, e.correct) for e in eom.edits] == [("coefficient", "sqrt(3)*m*s''/2")]


def test_a_reaction_with_a_surd_is_named_not_an_internal_error(wedge):
    # N = (sqrt(3)/2) m g + m X''/2: the ratio of a wrong coefficient is a surd (it was
    # "unhashable type: 'Surd'")
    assert wedge.grade("√3/2 m g + m X''/2", "N").right
    r = wedge.grade("m g/2 + m X''/2", "N")
    assert [(e.kind, e.term, e.correct) for e in r.edits] == \
        [("coefficient", "g*m/2", "sqrt(3)*g*m/2")], r


# -- the 30-degree push (forced_block): refused before, graded now ------------------------------
def test_T_V_and_Q_of_the_pushed_block_are_graded(block):
    # each was "NOT GRADED: `forced_block` has models the fast exact evaluator cannot
    # handle; T, V, L and Q are not graded for it."
    for text, quantity in (("½ m ẋ²", "KE"), ("k x²/2", "PE"), ("sqrt(3)/2 F", "Q_x"),
                           ("F cos(pi/6)", "Q_x"), ("m x'^2/2 - k x^2/2", "L")):
        r = block.grade(text, quantity)
        assert r.right and "exact" in r.method, (text, r)
    r = block.grade("F", "Q_x")      # the push counted whole: sqrt(3)/2 dropped
    assert [(e.kind, e.term, e.correct, e.category) for e in r.edits] == \
        [("coefficient", "F", "sqrt(3)*F/2", "an applied force term")], r
    assert not block.grade("F/2", "Q_x").right      # sin 30 for cos 30


def test_the_command_grades_a_surd_kinetic_energy():
    out = subprocess.run([sys.executable, "-m", "dualmech", "grade", str(WEDGE), "--quantity",
                          "KE", "--answer", "(M+m) X'^2/2 + m X' s'/2 + m s'^2/2"],
                         capture_output=True, text=True, timeout=300)
    assert out.stdout.startswith("WRONG") and "sqrt(3)*X'*m*s'/2" in out.stdout, \
        out.stdout + out.stderr


def test_hostile_roots_stay_bounded(wedge):
    hostile = ["(sqrt(2)+sqrt(3)+sqrt(5)+sqrt(7)+sqrt(11))^12 m X' s'",
               "(sqrt(2)+sqrt(3)+sqrt(5)+sqrt(7))^40 m X' s'",
               "sqrt(" + "7" * 29 + ") m X' s'",
               "sqrt(" + "9" * 70 + ") m X' s'"]
    four = "(sqrt(2)+sqrt(3)+sqrt(5)+sqrt(7))^24"     # 16 coordinates, exponent at its limit
    cases = [(h, "KE", ("wrong", "invalid")) for h in hostile] + [
        (f"{four} * {four} * {four} X'' = 0; s'' = 0", None, ("wrong",)),
        # the right X equation times that factor: still right, decided exactly
        (f"{four} (M+m) X'' + {four} sqrt(3)/2 m s'' = 0; m s'' + √3/2 m X'' - m g/2 = 0",
         None, ("right",))]
    for text, quantity, status in cases:
        t0 = time.perf_counter()
        r = wedge.grade(text, quantity)
        assert r.status in status and "internal error" not in r.summary, r
        assert time.perf_counter() - t0 < 5.0, text


def test_a_stored_context_may_hold_exact_square_roots():
    # a catalogue problem with a surd constant keeps Surd values at its points; the reader
    # that refuses every class but plain data must read them back (and still refuse others)
    import pickle

    from dualmech.grade.stored_contexts import _Reader
    value = {"x": Surd.root(3) / 2 + Fraction(1, 5)}
    assert _Reader(pickle.dumps(value)).load()["x"] == value["x"]
    with pytest.raises(pickle.UnpicklingError):
        _Reader(pickle.dumps(Path("."))).load()
