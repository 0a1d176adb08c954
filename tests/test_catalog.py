"""Every problem of the catalogue: every mutant is caught, the property holds at random states,
and its report is written in textbook notation (agreement, dimensions, reactions and printed
answers: tests/test_catalogue_checks.py)."""
import html
import re

import pytest
from hypothesis import given, settings

from dualmech.verify.mutation import mutation_report
from dualmech.testing import (assert_reactions_consistent, assert_same_motion, has_static_rows,
                              points)
from dualmech.problems import all_problems, get
from dualmech.report.pages import html_page, markdown_page
from dualmech.sources import source_name

from _catalogue_expected import catalogue_params

PROBLEMS = all_problems()
NAMES = [p.name for p in PROBLEMS]


@pytest.fixture(scope="module")
def comparisons(compared):
    """``comparisons(name)``: the catalogue's comparisons, shared with
    tests/test_catalogue_checks.py (which checks agreement, dimensions, reactions and printed
    answers for every problem); each made when a test first asks for it, so a problem whose
    tests are deselected (a slow one in the quick run) is not compared."""
    return compared


def test_catalogue_holds_the_four_named_problems():
    assert {"toy_car", "falling_container", "block_on_wedge", "pendulum_on_mass",
            "cart_pendulum"} <= set(NAMES)
    assert len(NAMES) == len(set(NAMES))


#: the generic mutation report judges every mutant of every model with a full verdict: the
#: bicycle's hundreds of mutants at minutes each do not fit a test run; the cross-check of its
#: reactions is mutation-tested by tests/test_referee_rolling.py instead
MUTATION = [pytest.param(n, marks=pytest.mark.skip(reason="hundreds of mutants, a verdict of "
                                                        "minutes each: see "
                                                        "tests/test_referee_rolling.py"))
            if n == "whipple_bicycle" else n for n in NAMES]


@pytest.mark.slow
@pytest.mark.parametrize("name", MUTATION)
def test_mutants_are_all_caught_naming_an_equation(name):
    report = mutation_report(get(name))
    assert report.total >= 10
    assert report.kill_rate == 1.0, str(report)
    for description, named in report.killed:
        assert named and all(n for n in named), description


@pytest.mark.slow
@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_property_both_forms_same_accelerations_and_consistent_reactions(name):
    problem = get(name)
    if has_static_rows(problem):
        pytest.skip("differential-algebraic: decided on the constraint manifold by compare()")

    @settings(max_examples=60)
    @given(points(problem))
    def check(point):
        assert_same_motion(problem, point)
        assert_reactions_consistent(problem, point)

    check()


# -- the report speaks textbook ------------------------------------------------------------
#: Python/sympy syntax that must never reach a page: a power, a product between two operands,
#: sympy's derivative, the plain state symbols of the derivations
PYTHON = re.compile(r"\*\*|[\w)\]]\*[\w(]|Derivative|\w_d?dot\b")
#: a rate written the other way: ASCII or unicode primes on a dotted page, dots on a primed one
OTHER_WAY = {"dots": re.compile(r"[\w\u2080-\u209c)]'|\u2032"), "primes": re.compile("[\u0307\u0308]")}


def _authored(c) -> list[str]:
    """What people wrote into the problem (titles, sources, labels, where an answer is printed,
    directions, notes) -- quoted as written, so it is not held to the printer's notation."""
    p = c.problem
    out = [p.title, source_name(p.source), *c.display_notes]
    out += [x for v in c.published for x in (v.label, v.where, v.where.split(":")[0])]
    out += [r.direction for r in p.reactions]
    out += [label for m in p.models().values() for label in m.labels]
    return sorted(filter(None, out), key=len, reverse=True)


def _generated(text: str, c, notation: str) -> str:
    """``text`` without the authored strings that would look like a leak themselves."""
    for s in _authored(c):
        if not (PYTHON.search(s) or OTHER_WAY[notation].search(s)):
            continue
        for quoted in (s, html.escape(s), s.replace("|", "\\|")):   # as written, HTML, Markdown
            text = text.replace(quoted, " ")
    return text


@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_report_pages_are_in_textbook_notation(comparisons, name, tmp_path):
    """Every expression of a problem's report section -- equations, reactions, why a printed
    answer is wrong (dimension audit included), the full text report -- is written in the
    report's notation: typeset on the HTML page, textbook text in the Markdown and in
    ``dualmech check``'s output, never Python's syntax."""
    c = comparisons(name)
    for notation in ("dots", "primes"):
        md = markdown_page([c], {}, 1.0, notation=notation)
        md = re.sub(r"\*\*[A-Z][a-z]+:\*\*", "", md)          # Markdown's bold "Verdict:"
        page = html_page([c], {}, tmp_path, 1.0, notation=notation)
        prose = html.unescape(re.sub(r"<[^>]+>", " ", re.sub(r"<math.*?</math>", " ", page,
                                                              flags=re.S)))
        for where, text in (("report.md", md), ("report.html", prose),
                            ("check", c.text(notation))):
            text = _generated(text, c, notation)
            leak = PYTHON.search(text) or OTHER_WAY[notation].search(text)
            assert leak is None, (f"{where} ({notation}) of {name}: "
                                  f"{text[max(leak.start() - 60, 0):leak.end() + 60]!r}")
        assert "Derivative" not in page and "(t)</mi>" not in page
    if any(v.verdict == "wrong" for v in c.published):   # the why column is typeset
        why = re.findall(r'<td class="wrong">WRONG</td><td>(.*?)</td></tr>', page)
        assert why and all("<math" in w for w in why if "closest to" in w or "equals" in w)


@pytest.mark.parametrize("name", catalogue_params(NAMES))
def test_report_names_sources_by_course(comparisons, name, tmp_path):
    """No page a person reads shows the archive's hashed file names; the JSON written beside
    the report keeps the file as ``source_file``."""
    c = comparisons(name)
    hashed = re.compile(r"\d{3}_[0-9a-f]{16}")
    for audience in ("teachers", "students"):
        shown = (markdown_page([c], {}, 1.0, audience) + html_page([c], {}, tmp_path, 1.0,
                                                                    audience) + c.text())
        assert not hashed.search(shown)
        assert source_name(c.problem.source) in html.unescape(shown)
    d = c.to_dict()
    file = c.problem.source.partition(": ")[0]
    assert d["source"] == source_name(c.problem.source)
    assert d["source_file"] == (file if hashed.fullmatch(file.removesuffix(".txt")) else None)
