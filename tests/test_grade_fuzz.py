"""No answer ends in an internal error: classic, hostile and expensive answers, graded through
the bounded sandbox for several problems and quantities.

``tests/corpus/hostile_answers.txt`` keeps answers that once broke a grader (zero divisions,
nested vectors, vectors inside functions, accelerations under roots, multiple angles of a
thousand, towers of exponentials, tautologies); hypothesis adds random combinations of such
pieces.  Every answer must come back as a :class:`~dualmech.grade.result.Grade` -- a verdict,
or a refusal that says what to change -- never as "internal error", and a refusal for cost
must name a sub-expression of the answer.
"""
from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dualmech.grade.sandbox import GradingPool

CORPUS = [line.rstrip("\n") for line in
          (Path(__file__).parent / "corpus" / "hostile_answers.txt").read_text().splitlines()
          if line.strip() and not line.startswith("#")]

# (problem, quantity): an equation set, a reaction, a Lagrangian, a generalised force
CASES = [("toy_car", None), ("toy_car", "F_r"), ("simple_pendulum", "L"),
         ("simple_pendulum", "Q_theta")]

PIECES = ["theta", "phi", "theta''", "phi'", "R", "m*g", "0", "1", "pi/2", "(theta - theta)",
          "[1, 2]", "sin(1000*theta)", "exp(exp(theta))", "sqrt(phi'')", "tan(pi/2)",
          "log(0)", "10^30", "1e-30"]


@pytest.fixture(scope="module")
def pool():
    with GradingPool(2, seconds=1.0, memory_mb=256) as p:
        yield p


def _check(text: str, g) -> None:
    assert g.status in ("right", "wrong", "invalid"), (text, g.status)
    assert g.summary, text
    assert "internal error" not in g.summary, (text, g.summary)
    if g.summary.startswith("too costly to grade: `"):
        named = g.summary.split("`")[1]
        compact = text.replace(" ", "")
        assert named.replace(" ", "") in compact or named == "", (text, named)


@pytest.mark.parametrize("problem,quantity", CASES)
def test_corpus_never_ends_in_an_internal_error(pool, problem, quantity):
    futures = [(a, pool.submit(problem, a, quantity)) for a in CORPUS]
    for text, f in futures:
        _check(text, f.result())


def test_corpus_says_nothing_is_wrong(pool):
    # tautologies hold for any motion: they are wrong, never right (issue: "An answer must
    # say something"); each is a single equation of toy_car
    for text in ["0 = 0", "t = t", "theta'' = theta''", "m*g - m*g = 0",
                 "sin(theta)^2 + cos(theta)^2 = 1"]:
        g = pool.grade("toy_car", text)
        assert g.status == "wrong" and "holds for any motion" in g.summary, (text, g.summary)


def test_costly_answers_are_refused_with_the_sub_expression(pool):
    for text, named in [("sin(1000*theta) = 0", "sin(1000*theta)"),
                        ("sin(100000*theta) = 0", "sin(100000*theta)"),
                        ("(sin(999*theta)^5)^14 = 0", "sin(999*theta)"),
                        ("sin(25*theta)^24 = 0", "sin(25*theta)^24"),
                        ("exp(exp(exp(exp(theta)))) = 0", "exp(exp(theta))")]:
        g = pool.grade("toy_car", text)
        assert g.status == "invalid", (text, g.summary)
        assert g.summary.startswith(f"too costly to grade: `{named}`"), (text, g.summary)


@settings(max_examples=10, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(parts=st.lists(st.sampled_from(PIECES), min_size=1, max_size=4),
       ops=st.lists(st.sampled_from(["+", "-", "*", "/", "^2*", "="]), min_size=3, max_size=3),
       wrap=st.sampled_from(["{}", "sin({})", "sqrt({})", "({})^3", "[{}, 1]", "1/({})"]),
       case=st.sampled_from(CASES))
def test_fuzz_combinations(pool, parts, ops, wrap, case):
    text = parts[0]
    for op, p in zip(ops, parts[1:]):
        text = f"{text} {op} {p}" if op != "=" or "=" not in text else f"{text} + {p}"
    text = wrap.format(text)
    _check(text, pool.grade(case[0], text, case[1]))


def test_a_map_that_multiplies_the_angles_is_graded_within_the_limits(pool):
    # theta = 150*s: rewriting the correct equations in s would expand sin(150*s); the answer
    # is graded (wrong, diagnosed in theta) inside the pool's time and memory ceilings
    g = pool.grade("simple_pendulum", "s'' + s = 0; where s = theta/150")
    assert g.status == "wrong" and "too costly" not in g.summary, g.summary


#: the notation the second corpus of students' answers brought (implicit products under a
#: power, a dot before an index, subscript digits, vulgar fractions), pushed to its limits
NEW_NOTATION = CORPUS[CORPUS.index("mR^2 theta'' + mgR sin(theta) = 0"):]


def test_new_notation_is_bounded_in_time_and_memory():
    """Graded in this process (no sandbox), each answer of the new notation costs at most
    a second of CPU and 64 MB of Python allocations at its peak (tracemalloc), for an
    equation set and for a Lagrangian."""
    import time
    import tracemalloc

    from dualmech.grade import Grader
    graders = [(Grader("toy_car"), None), (Grader("simple_pendulum"), "L")]
    for grader, quantity in graders:
        grader.grade("theta'' = 0", quantity)          # the problem's context, built once
    worst = (0.0, 0, "")
    for text in NEW_NOTATION:
        for grader, quantity in graders:
            tracemalloc.start()
            t0 = time.process_time()
            g = grader.grade(text, quantity)
            seconds = time.process_time() - t0
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
            _check(text, g)
            assert seconds < 1.0 and peak < 64 * 2**20, (text, seconds, peak, g.summary)
            worst = max(worst, (seconds, peak, text))
    assert len(NEW_NOTATION) >= 20, NEW_NOTATION
    print(f"worst: {worst[0]:.3f} s CPU, {worst[1] / 2**20:.1f} MB peak: {worst[2]!r}")
