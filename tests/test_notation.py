"""Textbook notation (dualmech.model.notation): dots, primes, LaTeX, machine text, MathML.

Reference for the LaTeX: ``sympy.physics.vector.vlatex``, the printer sympy's own mechanics
package uses for dynamic symbols (an independent implementation).  Reference for the machine
form: reading it back (sympy's parser, on our own trusted output) gives the same expression.
"""
import json

import pytest
import sympy as sp
from sympy.parsing.sympy_parser import parse_expr
from sympy.physics.vector import dynamicsymbols, vlatex

from dualmech import coordinate, t
from dualmech.model import notation
from dualmech.cli.main import main
from dualmech.problems import get

th, q1, x = coordinate("theta"), coordinate("q1"), coordinate("x_B")
m, l, g = sp.symbols("m l g", positive=True)

EXPRESSIONS = [
    m * l**2 * th.diff(t, 2) + m * g * l * sp.sin(th),
    m * l * th.diff(t)**2 * sp.cos(q1) - q1.diff(t, 2) * x,
    x.diff(t, 2) + 2 * q1.diff(t) * th.diff(t) / l,
    sp.sqrt(th.diff(t)**2 + q1.diff(t)**2) * sp.exp(-q1),
]


@pytest.mark.parametrize("expr", EXPRESSIONS, ids=range(len(EXPRESSIONS)))
def test_latex_is_the_one_sympy_mechanics_writes(expr):
    as_dynamic = expr.xreplace({t: dynamicsymbols._t})
    assert notation.latex(expr) == vlatex(as_dynamic)


def test_latex_names():
    th1 = coordinate("theta1")
    assert notation.latex(th1.diff(t, 2)) == r"\ddot{\theta}_{1}"
    assert notation.latex(th1.diff(t), "primes") == r"\theta'_{1}"
    assert notation.latex(th**2) == r"\theta^{2}"


@pytest.mark.parametrize("expr", EXPRESSIONS, ids=range(len(EXPRESSIONS)))
def test_machine_text_reads_back_to_the_same_expression(expr):
    names = {}
    for q in (th, q1, x):
        n = q.func.__name__
        names.update({n: q, n + "_d": q.diff(t), n + "_dd": q.diff(t, 2)})
    names.update({"m": m, "l": l, "g": g})
    back = parse_expr(notation.machine(expr), local_dict=names)
    assert sp.simplify(back - expr) == 0
    assert "Derivative" not in notation.machine(expr) and "(t)" not in notation.machine(expr)


def test_plain_text_uses_primes():
    assert notation.text(m * th.diff(t, 2) + th.diff(t)**2) == "m*theta'' + theta'**2"


def test_textbook_line_has_no_python_syntax():
    """One line a teacher writes on the board: powers as ^, products as spaces, the letters
    of :func:`pretty` (Greek, subscript digits), rates as dots or primes."""
    e = m * l**2 * th.diff(t, 2) + m * g * l * sp.sin(th) - q1.diff(t)**2 / (2 * l)
    assert notation.plain(e) == "g l m sin(\u03b8) + l^2 m \u03b8\u0308 - q\u0307\u2081^2/(2 l)"
    assert notation.plain(e, "primes") == ("g l m sin(\u03b8) + l^2 m \u03b8\u2032\u2032 "
                                           "- q\u2081\u2032^2/(2 l)")
    omega, c_t = sp.symbols("omega c_t")
    assert notation.plain((omega * t)**sp.Rational(3, 2) * c_t * x) == \
        "c\u209c (\u03c9 t)^(3/2) x_B"
    assert notation.plain(sp.Symbol("N1") / sp.sqrt(m)) == "N\u2081/sqrt(m)"
    f = sp.Function("f")(t)
    assert notation.plain(th.diff(t) - f, coordinates=[th]) == "-f(t) + \u03b8\u0307"
    assert notation.sentence(("equals ", th.diff(t)**2, ", not 0"), "primes") == \
        "equals \u03b8\u2032^2, not 0"


def test_check_text_follows_the_notation(capsys):
    # hand: theta'' = -g sin(theta)/a for the simple pendulum, T = M (a theta'^2 + g cos theta)
    assert main(["check", "simple_pendulum", "--notation", "primes"]) == 0
    out = capsys.readouterr().out
    assert "\u03b8\u2032\u2032 = -g sin(\u03b8)/a" in out
    assert "T = M (a \u03b8\u2032^2 + g cos(\u03b8))" in out
    assert main(["check", "simple_pendulum"]) == 0
    out = capsys.readouterr().out
    assert "\u03b8\u0308 = -g sin(\u03b8)/a" in out and "**" not in out


def test_pretty_uses_dots_or_primes_and_never_function_notation():
    e = sp.Eq(m * l * th.diff(t, 2) + q1.diff(t)**2 * sp.sin(th), 0, evaluate=False)
    dots = notation.pretty(e)
    assert "θ\u0308" in dots and "q\u0307\u2081" in dots
    primes = notation.pretty(e, "primes")
    assert "θ\u2032\u2032" in primes and "q\u2081\u2032" in primes
    for s in (dots, primes):
        assert "(t)" not in s and "d/dt" not in s and "Derivative" not in s


def test_forcing_functions_keep_their_time_argument_when_coordinates_are_named():
    f = sp.Function("f")(t)
    assert notation.text(th.diff(t, 2) - f, coordinates=[th]) == "-f(t) + theta''"


def test_unknown_notation_is_refused_with_the_choices():
    with pytest.raises(ValueError, match="dots, primes"):
        notation.pretty(th, "fluxions")


def test_equation_set_pretty_and_repr_follow_the_notation():
    eqs = get("simple_pendulum").model("lagrange")
    assert "θ̈" in eqs.pretty() and r"\ddot{\theta}" in eqs.pretty(latex=True)
    assert "θ′′" in eqs.pretty(notation="primes")
    assert repr(eqs) == "<EquationSet lagrange in (theta): M*a**2*theta'' + M*a*g*sin(theta) = 0>"
    assert r"\ddot{\theta}" in eqs._repr_latex_()


def test_show_prints_dots_or_primes(capsys):
    assert main(["show", "simple_pendulum"]) == 0
    out = capsys.readouterr().out
    assert "θ̈" in out and "θ̇" in out and "(t)" not in out and "d/dt" not in out
    assert main(["show", "simple_pendulum", "--notation", "primes"]) == 0
    out = capsys.readouterr().out
    assert "θ′′" in out and "θ̈" not in out
    assert main(["show", "simple_pendulum", "--latex"]) == 0
    out = capsys.readouterr().out
    assert r"\ddot{\theta}" in out and r"\frac{d" not in out


def test_json_carries_a_machine_form_beside_the_human_one(capsys):
    main(["check", "simple_pendulum", "--json"])
    d = json.loads(capsys.readouterr().out)
    assert d["eom"] == ["M*a**2*theta'' + M*a*g*sin(theta)"]
    assert d["machine"]["eom"] == ["M*a**2*theta_dd + M*a*g*sin(theta)"]
    # the string tension T = M (a theta'^2 + g cos theta), from the free-body diagram
    assert d["machine"]["reactions"]["T"] == "M*(a*theta_d**2 + g*cos(theta))"


# -- Jupyter rich display ---------------------------------------------------------------------
def test_comparison_displays_its_verdict_and_typeset_reactions():
    from dualmech.verify.check import compare
    c = compare(get("simple_pendulum"))
    assert repr(c).startswith("<Comparison simple_pendulum: all derivations agree")
    page = c._repr_html_()
    assert "all derivations agree" in page and page.count("<math") >= 2   # theta'', T
    assert "<mi>&#952;&#775;</mi>" in page          # T = M (a theta-dot^2 + g cos theta)
    assert "Derivative" not in page and "(t)" not in page


def test_problem_grade_and_chart_display(tmp_path):
    from dualmech.grade import grade
    from dualmech.report.charts import trajectory_chart
    p = get("simple_pendulum")
    card = p._repr_html_()
    assert "Cambridge 3C5" in card and "<math" in card and "002_df41972c66c4514e" not in card
    g = grade("simple_pendulum", "theta'' - g/a*sin(theta)")      # the sign of gravity flipped
    html = g._repr_html_()
    assert '<b class="wrong">WRONG</b>' in html and "wrong sign" in html
    assert "&#x27;&#x27;" in html and "theta'' -" not in html        # the answer is escaped
    chart = trajectory_chart(get("wheel_on_pivot"), tmp_path, 0.5)
    shown = chart._repr_html_()
    assert shown.count('src="data:image/png;base64,') == 1
    assert shown.count("<figcaption>") == 1 and "F_z stays at 19.62 N" in shown
