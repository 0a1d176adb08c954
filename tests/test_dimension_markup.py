"""Dimensions on the pages are typeset: upright base letters with their exponents as MathML
superscripts (``M L^2 T^-2`` as M L² T⁻²), every other character of the sentence escaped, and
only where the library wrote a dimension -- a printed formula's ``L^2`` stays text."""
import re

import pytest

from dualmech.verify.check import compare
from dualmech.problems import get
from dualmech.report.mathml import dimension, text_html
from dualmech.report.pages import html_page

M = '<mi mathvariant="normal">M</mi>'
L2 = '<msup><mi mathvariant="normal">L</mi><mrow><mn>2</mn></mrow></msup>'
T_2 = '<msup><mi mathvariant="normal">T</mi><mrow><mo>&#8722;</mo><mn>2</mn></mrow></msup>'
GAP = '<mspace width="0.2em"/>'
HOSTILE = '<script>alert("x")</script>'


def test_a_dimension_is_upright_letters_with_superscript_exponents():
    assert dimension("M L^2 T^-2") == (
        '<math xmlns="http://www.w3.org/1998/Math/MathML"><mrow>'
        f"{M}{GAP}{L2}{GAP}{T_2}</mrow></math>")
    half = dimension("M^1/2 L")
    assert "<msup><mi mathvariant=\"normal\">M</mi><mrow><mn>1</mn><mo>/</mo><mn>2</mn>" in half


@pytest.mark.parametrize("text", ["L M", "M M", "x", "T^", "M L^2x", "1", ""])
def test_anything_else_is_not_a_dimension(text):
    assert dimension(text) is None


def test_in_a_sentence_only_the_dimensions_are_typeset_and_the_rest_is_escaped():
    s = f"the term `{HOSTILE}` has dimension M L T^-2 where the rest has M L^2 T^-2; ok"
    out = text_html(s)
    assert "<script>" not in out and "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;" in out
    assert out.count("<math") == 2 and f"{M}{GAP}{L2}{GAP}{T_2}" in out
    assert out.endswith("</math>; ok") and "^" not in out


@pytest.mark.parametrize("text", ["Example 14: k2 L^2 th - k2 L y = 0", "Q = int_0^L f dx",
                                  "(169 M L^2 + 4 m)", "has L M^2"])
def test_a_printed_formula_is_left_as_text(text):
    assert text_html(text) == text.replace("<", "&lt;")


def test_the_report_page_typesets_every_dimension():
    page = html_page([compare(get("toy_car"))], {}, None, 1.0)
    shown = re.sub(r"<pre>.*?</pre>", "", page, flags=re.S)     # the text report is text
    # toy_car's printed (B) answers mix M L T^-2 and M L^2 T^-2 terms (quiz 1, part B)
    assert f"{M}{GAP}{L2}{GAP}{T_2}" in shown
    assert not re.search(r"\b[MLT]\^-?\d", re.sub(r"<math.*?</math>", "", shown, flags=re.S))


def test_web_feedback_and_preview_typeset_dimensions():
    from dualmech.web.catalog import ProblemInfo
    from dualmech.web.pages import feedback_html
    from dualmech.web.preview import preview
    html = feedback_html(None, {"status": "wrong", "summary": "",
                                "dimension_issues": [f"`{HOSTILE}` has M L^2 T^-2"]})
    assert "<script>" not in html and f"{M}{GAP}{L2}{GAP}{T_2}" in html
    p = preview(ProblemInfo.build("simple_pendulum"), "a*theta'' + a*g = 0")
    # a*theta'' is L T^-2 and a*g is L^2 T^-2 (a a length, g an acceleration)
    assert p["dimensions"] == ["the terms do not share one dimension: `a*theta''` has "
                               "L T^-2; `a*g` has L^2 T^-2"]
    (typeset,) = p["dimensions_html"]
    assert typeset.startswith("the terms do not share one dimension: `a*theta&#x27;&#x27;` "
                              "has <math") and typeset.count("<math") == 2
    assert f"{L2}{GAP}{T_2}" in typeset
