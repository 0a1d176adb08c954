"""Every answer is hostile until parsed: nothing it says is executed, nothing escapes, bounds hold.

Guards installed for the whole module record any call of ``eval``/``exec``/``compile`` whose
source contains an answer's text, and any text reaching ``sympy.sympify`` or ``parse_expr``;
the tests assert that none happened.  Side effects the classic attacks would cause (a file
written, a module-level flag set) are checked too.  The fuzz tests throw more than ten thousand
generated strings -- random Unicode, and soups of the grammar's own tokens -- at the parser and
the name resolution, and a few hundred through the whole grader.
"""
from __future__ import annotations

import builtins
import importlib
import os
import random
import tempfile

import pytest
import sympy
import sympy.parsing.sympy_parser as sympy_parser
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dualmech.grade import LIMITS, Grader, grade
from dualmech.grade.formula import Formula
from dualmech.grade.parser import AnswerError, parse
from dualmech.grade.vocabulary import UnknownName

PWNED = os.path.join(tempfile.gettempdir(), "dualmech_grade_pwned")
FLAG = {"set": False}

ATTACKS = [
    f"__import__('os').system('touch {PWNED}')",
    f"open('{PWNED}', 'w').write('x')",
    "().__class__.__bases__[0].__subclasses__()",
    "x.__class__.__mro__",
    "__builtins__",
    "globals()['FLAG']",
    "lambda: 0",
    "lambda x: x",
    "exec('import os')",
    "eval('1+1')",
    "import os",
    "compile('1', 'f', 'eval')",
    "Symbol('x')",
    "sympify('theta')",
    "theta.__dict__",
    "9^9^9^9",
    "9**9**9**9",
    "2^(2^(2^(2^10)))",
    "theta^(10^10)",
    "((theta^24)^24)^24",
    "10^1000000",
    "1e999999999",
    "(" * 10000 + "theta" + ")" * 10000,
    "-" * 10000 + "theta",
    "sin(" * 2000 + "theta" + ")" * 2000,
    "theta" + "^theta" * 2000,
    "theta+" * 200000 + "theta",
    "a" * (1 << 20),
    "1" * 100000,
    "\x00\x01\x02",
    "theta\u202e'' = 0",
    "ｅｘｅｃ('1')",
    "θ̈" * 3000,
    ";" * 100000,
    "\\" * 1000,
    "\\frac{" * 500 + "1" + "}{2}" * 500,
    "theta'''''''''''",
    "sin(theta)^(1/3)",
    "1/(theta - theta)",
    "theta''^2 + theta'' = 0",
]


@pytest.fixture(scope="module", autouse=True)
def guards():
    """Record raw answer text reaching eval/exec/compile/sympify/parse_expr."""
    # sympy imports its units lazily (sp.simplify, on first use) and that import sympifies the
    # prefix names it defines ("yotta"): library text, not an answer's, so imported first
    importlib.import_module("sympy.physics.units")
    seen: list = []
    texts: list = []
    originals = (builtins.eval, builtins.exec, builtins.compile, sympy.sympify,
                 sympy_parser.parse_expr)

    def watch(fn, name):
        def wrapper(source, *args, **kwargs):
            filename = args[0] if args else kwargs.get("filename", "")
            from_file = isinstance(filename, str) and os.path.isfile(filename)
            if isinstance(source, (str, bytes)) and not from_file:  # (ast.parse of modules)
                src = source.decode(errors="replace") if isinstance(source, bytes) else source
                if any(len(t) > 10 and t in src for t in texts):
                    seen.append((name, src[:80]))
            return fn(source, *args, **kwargs)
        return wrapper

    def no_text(fn, name):
        def wrapper(a, *args, **kwargs):
            if isinstance(a, str):
                seen.append((name, a[:80]))
                raise AssertionError(f"text reached {name}: {a[:80]!r}")
            return fn(a, *args, **kwargs)
        return wrapper

    builtins.eval = watch(originals[0], "eval")
    builtins.exec = watch(originals[1], "exec")
    builtins.compile = watch(originals[2], "compile")
    sympy.sympify = no_text(originals[3], "sympify")
    sympy_parser.parse_expr = no_text(originals[4], "parse_expr")
    try:
        yield seen, texts
    finally:
        (builtins.eval, builtins.exec, builtins.compile, sympy.sympify,
         sympy_parser.parse_expr) = originals
    assert not seen, f"answer text reached {seen[:3]}"


@pytest.fixture(scope="module")
def grader():
    """The simple pendulum: its context is cheap to build."""
    g = Grader("simple_pendulum")
    g.grade("a*theta'' + g*sin(theta) = 0")  # build the per-problem work once
    return g


@pytest.mark.parametrize("text", ATTACKS, ids=lambda s: repr(s[:30]))
def test_classic_attacks_get_a_clear_error_and_nothing_runs(text, grader, guards):
    guards[1].append(text)
    r = grader.grade(text)
    assert r.status in ("invalid", "wrong")
    assert r.summary and "internal error" not in r.summary
    assert r.seconds <= LIMITS.seconds + 1.0   # the per-answer bound held
    assert not os.path.exists(PWNED)
    assert FLAG["set"] is False


def test_too_large_answers_say_which_bound(grader):
    assert "at most 4000" in grader.grade("theta+" * 1000).summary
    assert "larger than 24" in grader.grade("9^9^9^9").summary
    assert "nests" in grader.grade("(" * 60 + "theta" + ")" * 60).summary
    assert "degree" in grader.grade("((theta^20)^20)^2").summary


def test_time_limit_is_enforced():
    from dualmech.grade.parser import Limits
    tight = Grader("simple_pendulum", limits=Limits(seconds=0.0))
    r = tight.grade("a*theta'' + g*sin(theta) = 0")
    assert r.status == "invalid" and r.summary.startswith("too costly to grade")
    assert "more than 0 s" in r.summary


def test_a_batch_goes_on_after_a_hostile_answer(grader):
    answers = ATTACKS[:5] + ["a*theta'' + g*sin(theta) = 0"]
    results = [grader.grade(a) for a in answers]
    assert results[-1].right


# -- fuzzing ------------------------------------------------------------------------------------
_VOC = None


def _vocabulary():
    global _VOC
    if _VOC is None:
        _VOC = Grader("toy_car").context.vocabulary
    return _VOC


def _parse_and_resolve(text: str) -> None:
    """Parse and resolve; only the grader's own clear errors may come out."""
    try:
        for eq in parse(text):
            Formula.from_node(eq.lhs, _vocabulary())
            if eq.rhs is not None:
                Formula.from_node(eq.rhs, _vocabulary())
    except (AnswerError, UnknownName):
        pass


TOKENS = ["theta", "phi", "theta'", "phi''", "m", "R", "g", "F_r", "t", "pi", "sin", "cos",
          "tan", "sqrt", "exp", "log", r"\frac", r"\dot", r"\ddot", r"\theta", r"\sin", "(",
          ")", "{", "}", "[", "]", ",", "+", "-", "*", "/", "^", "**", "=", ";", "\n", "2",
          "0", "1.5", "1e3", "'", "_", "_1", "__", "x", "thetadot", "ddphi", "θ", "·", " ",
          "lambda", "import", "__class__", ".", ":", "!", "9^9^9", "^-", "&", "\\\\"]
TOKEN_SOUP = st.lists(st.sampled_from(TOKENS), max_size=40).map("".join)
ANY_TEXT = st.text(max_size=120)
SETTINGS = settings(max_examples=100, deadline=None, database=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def _soup(rng, n: int) -> list[str]:
    return ["".join(rng.choice(TOKENS) for _ in range(rng.randint(0, 40))) for _ in range(n)]


@SETTINGS
@given(st.integers(0, 2 ** 64))
def test_fuzz_token_soup(seed):             # 100 x 60 = 6,000 strings of grammar tokens
    for text in _soup(random.Random(seed), 60):
        _parse_and_resolve(text)


@SETTINGS
@given(st.lists(ANY_TEXT, min_size=50, max_size=50))
def test_fuzz_any_text(batch):              # 100 x 50 = 5,000 strings of any Unicode
    for text in batch:
        _parse_and_resolve(text)


@settings(max_examples=60, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(batch=st.lists(TOKEN_SOUP, min_size=5, max_size=5))
def test_fuzz_whole_grader(batch, grader, guards):   # 300 strings graded end to end
    for text in batch:
        guards[1].append(text)
        r = grader.grade(text)
        assert r.status in ("right", "wrong", "invalid")
        assert "internal error" not in r.summary, (text, r.summary)
        assert r.seconds <= LIMITS.seconds + 1.0


def test_grade_accepts_only_text():
    r = grade("simple_pendulum", 12345)
    assert r.status == "invalid" and "text" in r.summary


# the comparator decides these (roots, static rows); correctness, not speed, is tested here
ROOMY = LIMITS.__class__(seconds=300.0)


# -- sampling where the problem lives ----------------------------------------------------------
X_FORM = ("M*x'' + c*x' - g*m*(l0 + x)/(2*sqrt(4*l^2 - (l0 + x)^2)) + k*x "
          "+ 2*l^2*m*x''/(8*l^2 - 2*(l0 + x)^2) "
          "+ 4*l^2*m*(l0 + x)*x'^2/(8*l^2 - 2*(l0 + x)^2)^2 = 0")


def test_two_rod_linkage_x_form_is_sampled_in_its_domain():
    # the project's own lagrange_x equation (problems/two_rod_linkage.py), typed in x: right
    # only where sqrt(4 l^2 - (l0 + x)^2) = 2 l sin(theta), i.e. on the declared domain
    # 0 < theta < pi; a point with sin(theta) < 0 would call it wrong
    g = Grader.of("two_rod_linkage", limits=ROOMY)
    assert g.grade(X_FORM).status == "right"
    r = g.grade(X_FORM.replace("+ k*x", "- k*x"))
    assert r.status == "wrong"
    # and diagnosed in x, against the lagrange_x row, though the student scaled the
    # denominators their own way (8 l^2 - 2 (l0 + x)^2 where the model has 4 l^2 - ...)
    assert [(e.kind, e.term, e.correct) for e in r.edits] == [("sign", "-k*x", "k*x")], str(r)


# -- static rows ----------------------------------------------------------------------------
COPYING = ("-F + b*y' - k2*(L*theta - y) + m2*y'' = 0; "
           "L*k2*(L*theta - y) + a^2*k1*theta = 0")


def test_copying_machine_static_row_is_graded():
    # problems/copying_machine.py: a massless bar, so the theta row has no acceleration; the
    # reference equations are right, a flipped spring sign in that row is wrong, and a
    # tautology says nothing
    g = Grader.of("copying_machine", limits=ROOMY)
    assert g.grade(COPYING).status == "right"
    r = g.grade(COPYING.replace("+ a^2*k1", "- a^2*k1"))
    assert r.status == "wrong"
    # explained equation by equation: the static row's flipped spring is named, the right
    # first equation is left alone
    assert [(e.kind, e.term, e.correct) for e in r.edits] == [
        ("sign", "-a^2*k1*theta", "a^2*k1*theta")], str(r)
    assert "equation 1" not in str(r), str(r)
    assert g.grade("L*k2*(L*theta - y) + a^2*k1*theta = 0").status == "right"
    r = g.grade("0 = 0")
    assert r.status == "wrong" and "holds for any motion" in r.summary
