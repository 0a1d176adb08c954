"""The fast routes a large model takes must give what the slow ones give.

Each test sets a fast route against the route it replaced (or against a hand value):

* the linear structure ``A [q''; lambda] = b`` of rows held in symengine, read by
  differentiation instead of expansion (:func:`dualmech.model.equations._linear_parts`);
* the cache key of generated code for rows held in symengine (:func:`dualmech.numeric._cache.digest`);
* the exact state matrix of a steady motion at a rational parameter on FLINT
  (:func:`dualmech.model.stability._reduce_rational`) against sympy's LU route;
* the zero-row test of the reaction display (:func:`dualmech.verify.check._nonzero_row`);
* a velocity constraint given as its expression (:meth:`Lagrangian.velocity_constraint`).
"""
from __future__ import annotations

import pytest
import symengine as se
import sympy as sp

from dualmech import Lagrangian, coordinate, get, rate
from dualmech.model import stability
from dualmech.model.equations import ModelError, _linear_parts
from dualmech.model.kinematics import t
from dualmech.numeric._cache import digest
from dualmech.verify.check import _nonzero_row
from dualmech.verify.stability_claims import _symbol

u, v, x, y, s = se.symbols("u v x y s")


def test_linear_parts_reads_coefficients_without_expanding():
    row = (x + y) * (u * s + 2) - v * x
    A, rhs, bad = _linear_parts(row, [u, v], {u, v})
    assert bad == []
    assert se.expand(A[0] - (x + y) * s) == 0 and A[1] == -x
    assert se.expand(rhs + 2 * (x + y)) == 0


def test_linear_parts_expands_a_row_linear_only_once_multiplied_out():
    # (u + x)(u + y) s - u^2 s = (x + y) s u + x y s: linear, but its derivative holds u
    A, rhs, bad = _linear_parts((u + x) * (u + y) * s - u**2 * s, [u, v], {u, v})
    assert bad == []
    assert se.expand(A[0] - (x + y) * s) == 0 and A[1] == 0
    assert se.expand(rhs + x * y * s) == 0


def test_linear_parts_names_the_unknowns_a_row_is_nonlinear_in():
    _, _, bad = _linear_parts(u * v + x, [u, v], {u, v})
    assert set(bad) == {u, v}
    _, _, bad = _linear_parts(u**2 * x + v, [u, v], {u, v})
    assert bad == [u]


def test_held_rows_digest_tells_apart_what_makes_different_code():
    a = se.RealDouble(0.1)
    b = se.RealDouble(0.1 + 2.0**-56)      # prints as 0.1 too
    assert str(a) == str(b)
    assert digest([a * x]) != digest([b * x])
    t = se.Symbol("t")
    assert digest([se.Function("q")(t)]) != digest([se.Function("p")(t)])
    assert digest([se.Rational(1, 3) * x]) == digest([se.Rational(1, 3) * x])
    assert digest([se.sin(x) * y]) != digest([se.cos(x) * y])


def test_held_model_digest_follows_the_symbols_assumptions():
    th = coordinate("theta")

    def model(positive: bool):
        m = sp.Symbol("m", positive=positive) if positive else sp.Symbol("m")
        lg = Lagrangian(coordinates=[th])
        lg.kinetic("T", m * rate(th)**2 / 2)
        lg.potential("V", -m * sp.cos(th))
        return lg.equations()

    one, other = model(True), model(False)
    assert digest(one.equations) == digest(model(True).equations)
    assert digest(one.equations) != digest(other.equations)


def _disk_linearisation():
    """The rolling disk's linearisation about upright rolling, symbolic in its speed."""
    p = get("rolling_disk")
    values = {sym: stability.exact_number(val) for sym, val in p.defaults().items()}
    steady = p.steady_motion
    symbol = _symbol(p, steady)
    return stability.linearize_about(p.model(p.reference), steady.about, values, symbol,
                                     generic=sp.Rational(3, 5)), symbol


def test_steady_state_matrix_on_flint_equals_sympys_lu_route():
    """The rolling disk's lean/heading matrix at rational speeds, both routes (the hand
    value of the lean eigenvalues is checked by tests/test_stability.py)."""
    lin, symbol = _disk_linearisation()
    for speed in (sp.Rational(1, 2), sp.Rational(7, 4), sp.Integer(3)):
        fast = stability._reduce_rational(lin._parts, {symbol: speed})
        assert fast is not None
        slow = lin.symbolic.subs(symbol, speed).applyfunc(sp.cancel)
        assert fast == slow


def test_flint_route_declines_an_irrational_value():
    lin, symbol = _disk_linearisation()
    assert stability._reduce_rational(lin._parts, {symbol: sp.sqrt(2)}) is None


def test_a_zero_row_is_found_and_a_nonzero_one_kept():
    th = coordinate("theta")
    m, g, l = sp.symbols("m g l", positive=True)
    lg = Lagrangian(coordinates=[th])
    lg.kinetic("T", m * l**2 * rate(th)**2 / 2)
    lg.potential("V", -m * g * l * sp.cos(th))
    eqs = lg.equations()
    held = eqs.plain_matrix_se()
    assert _nonzero_row(held, 0, eqs.equations.se[0])
    A, b, names = held
    q = se.Symbol(eqs.states[0].q.name)
    zero_b = se.DenseMatrix(1, 1, [se.sin(q)**2 + se.cos(q)**2 * 0 - se.sin(q) * se.sin(q)])
    zero_A = se.DenseMatrix(1, A.cols, [se.Integer(0)] * A.cols)
    assert not _nonzero_row((zero_A, zero_b, names), 0, zero_b[0])
    # zero only once multiplied out: the expansion decides
    tricky = (q + 1) * (q - 1) - q**2 + 1
    assert not _nonzero_row((zero_A, se.DenseMatrix(1, 1, [tricky]), names), 0, tricky)


def test_velocity_constraint_as_an_expression_equals_its_coefficients():
    x, phi, psi = coordinate("x"), coordinate("phi"), coordinate("psi")
    r = sp.Symbol("r", positive=True)

    def model(as_expression: bool):
        lg = Lagrangian(coordinates=[x, phi, psi])
        lg.kinetic("T", (rate(x)**2 + rate(phi)**2 + rate(psi)**2) / 2)
        if as_expression:
            lg.velocity_constraint("F", rate(x) - r * sp.cos(psi) * rate(phi))
        else:
            lg.velocity_constraint("F", [1, -r * sp.cos(psi), 0])
        return lg.equations()

    one, other = model(True), model(False)
    for a, b in zip(one.equations, other.equations):
        assert sp.expand(a - b) == 0
    assert sp.expand(one.equations[-1] - (x.diff(t, 2) - r * sp.cos(psi) * phi.diff(t, 2)
                                          + r * sp.sin(psi) * psi.diff(t) * phi.diff(t))) == 0
    assert one.constraints[0].expression == other.constraints[0].expression


def test_velocity_constraint_expression_must_be_linear_in_rates():
    x, phi = coordinate("x"), coordinate("phi")
    lg = Lagrangian(coordinates=[x, phi])
    lg.kinetic("T", (rate(x)**2 + rate(phi)**2) / 2)
    lg.velocity_constraint("F", rate(x) * rate(phi))
    with pytest.raises(ModelError, match="not linear in the rates"):
        lg.equations()
    lg = Lagrangian(coordinates=[x, phi])
    lg.kinetic("T", (rate(x)**2 + rate(phi)**2) / 2)
    lg.velocity_constraint("F", x - phi)
    with pytest.raises(ModelError, match="holds no rate"):
        lg.equations()



def test_a_text_value_is_refused_never_parsed(tmp_path):
    lin, symbol = _disk_linearisation()
    marker = tmp_path / "ran"
    hostile = f"__import__('pathlib').Path({str(marker)!r}).touch()"
    with pytest.raises(TypeError):
        stability._reduce_rational(lin._parts, {symbol: hostile})
    with pytest.raises(TypeError):
        lin.at(hostile)
    assert not marker.exists()


def test_the_algebra_bridge_refuses_text_before_any_parser_sees_it(tmp_path):
    """Bridge(), Bridge.se, Bridge.sp and names_of take library expressions only: a string is
    refused by sympify(strict=True) before symengine's parser (Bridge.se) could read it."""
    import sympy as sp
    from dualmech.model._algebra import Bridge, names_of
    marker = tmp_path / "touched"
    hostile = f"__import__('pathlib').Path({str(marker)!r}).touch()"
    for call in (lambda: Bridge([hostile]), lambda: Bridge().se(hostile),
                 lambda: Bridge().sp(hostile), lambda: names_of(hostile)):
        with pytest.raises(sp.SympifyError):
            call()
    assert not marker.exists()
