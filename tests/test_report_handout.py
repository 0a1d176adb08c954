"""Reports to hand out: the students' page hides corrections, the teachers' page typesets
them; summary linked to sections; sources named by course; one caption per chart; charts
that have nothing to show say so.

Hand facts: read with a horizontal spring and dashpot (restrained_pendulum_horizontal, a rung
above the source's own arc-length model), the source's printed U, R and equation of motion are
wrong -- right only to first order in theta (tests/test_restrained_pendulum.py); the block on the wedge's
equation along the incline is m (q1'' + cos(alpha) q2'' - g sin(alpha)) = 0 once
sin^2 + cos^2 = 1 is used; the wheel on its pivot in steady motion has no vertical
acceleration, so the floor carries its weight: F_z = m g = 2 kg * 9.81 m/s^2 = 19.62 N.
"""
import re

import numpy as np
import pytest
import sympy as sp

from dualmech.verify.check import compare
from dualmech.problems import get
from dualmech.report import write_report
from dualmech.report.charts import trajectory_chart
from dualmech.report.pages import _shortest

NAMES = ("restrained_pendulum_horizontal", "block_on_wedge")


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    comparisons = [compare(get(n)) for n in NAMES]
    out = {}
    for audience in ("teachers", "students"):
        d = tmp_path_factory.mktemp(audience)
        w = write_report(comparisons, d, 1.0, progress=False, audience=audience)
        out[audience] = (w.html.read_text(encoding="utf-8"), w.markdown.read_text("utf-8"), w)
    return comparisons, out


def test_students_see_verdicts_but_no_corrections(pages):
    comparisons, out = pages
    page, md, _ = out["students"]
    wrong = [p for p in comparisons[0].published if p.verdict == "wrong"]
    assert len(wrong) == 3                              # R, U and the equation of motion
    for text in (page, md):
        assert "printed minus" not in text and "closest to" not in text
        assert "WRONG" in text and "<details>" not in text
        for p in wrong:
            assert p.where not in text or ":" not in p.where
    assert "<th>why</th>" not in page


def test_teachers_see_typeset_corrections(pages):
    comparisons, out = pages
    page = out["teachers"][0]
    assert page.count("<th>why</th>") == 2             # one printed-answer table per problem
    why = re.findall(r'<td class="wrong">WRONG</td><td>(.*?)</td></tr>', page)
    assert len(why) == 3
    assert all("<math" in w for w in why)               # the expressions are MathML ...
    assert not any("**" in w or "theta'" in w for w in why)   # ... not Python syntax


def test_summary_links_to_sections_and_sources_are_named_by_course(pages):
    _, out = pages
    page, md, _ = out["teachers"]
    for n in NAMES:
        assert f'<a href="#{n}">{n}</a>' in page and f'<h2 id="{n}">' in page
        assert f"[{n}](#{n})" in md
    assert "000_203248afac9714e6" not in page
    assert "source: Lecture notes, Lagrange&#x27;s method: Example 12" in page


def test_one_caption_per_chart(pages):
    _, out = pages
    page, _, written = out["teachers"]
    drawn = [c for c in written.charts.values() if not c.error]
    # each chart's caption once; each animation has its own (one sentence on the arrows)
    animations = [c for c in drawn if c.animation is not None]
    assert page.count("<figcaption>") - len(animations) == len(drawn) == 2
    first_note = drawn[0].notes[0]
    assert page.count(first_note[1:]) == 1


def test_displayed_equations_are_simplified_within_the_budget():
    p = get("block_on_wedge")
    eq = p.model(p.reference).equations[0]
    m, g, al = sp.symbols("m g alpha", positive=True)
    shown = _shortest(eq)
    q1, q2 = p.model(p.reference).coordinates
    t = list(q1.free_symbols)[0]
    hand = m * (q1.diff(t, 2) + sp.cos(al) * q2.diff(t, 2) - g * sp.sin(al))
    names = {s.name: s for s in shown.free_symbols}
    hand = hand.xreplace({m: names["m"], g: names["g"], al: names["alpha"]})
    assert sp.expand(shown - hand) == 0
    assert not (shown.has(sp.sin(names["alpha"])**2))


def test_a_difference_of_different_dimensions_is_not_shown():
    c = compare(get("pendulum_particle"))
    v = next(x for x in c.published if x.label == "acceleration, body")
    assert v.verdict == "wrong"
    assert "different dimensions" in v.detail and "printed minus" not in v.detail


def test_constant_curves_and_zero_reactions_are_said_not_drawn(tmp_path):
    chart = trajectory_chart(get("wheel_on_pivot"), tmp_path, 1.0)
    # the caption names them in the page's textbook text (subscripts where unicode has one)
    assert "F_x, F_y, R_x, R_y, R_z = 0 along the whole motion (not drawn)" in chart.notes
    assert "F_z stays at 19.62 N (not drawn)" in chart.notes      # m g, see above
    # its steady tilt, phi: the one panel of the motion, drawn flat (never an empty box)
    assert "φ stays at 0.6 rad (drawn flat: nothing on its panel varies)" in chart.notes


def test_drift_at_rounding_level_is_said_not_drawn(monkeypatch, tmp_path):
    from dualmech.numeric.studies import atlas
    from dualmech.numeric.studies.regimes import Drift
    seen = {}

    def keep(fig, stem, **kw):
        seen["texts"] = [x.get_text() for ax in fig.axes for x in ax.texts]
        seen["lines"] = [ln.get_label() for ax in fig.axes for ln in ax.get_lines()]
        return []

    monkeypatch.setattr("dualmech.numeric.charts.save", keep)
    tt = np.linspace(0, 1, 11)
    d = Drift("p", "m", "RK45", 1e-6, "m", {"none": tt, "projection": tt, "exact": tt},
              {"none": 1e-6 * tt, "projection": 1e-17 * np.ones(11), "exact": np.zeros(11)},
              {"none": 1.0, "projection": 0.0, "exact": 0.0})
    atlas._chart_drift(d, tmp_path / "drift")
    text = "\n".join(seen["texts"])
    assert "projection: at rounding level (max |g| = 1.0e-17 m)" in text
    assert "exact: exactly zero" in text
    assert len(seen["lines"]) == 1 and seen["lines"][0].startswith("none")
