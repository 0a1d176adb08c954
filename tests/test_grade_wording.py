"""Feedback in a person's words (issue 28, point 4): kinds of term from what a term is made
of, shown expressions reduced, and LaTeX echoed as the student typed it."""
from __future__ import annotations

import sympy as sp

from dualmech.grade import Grader
from dualmech.grade.audit import display
from dualmech.grade.kinds import category
from dualmech.grade.tidy import tidy


def test_a_torque_is_a_torque_not_a_spring():
    # Q3 is declared TORQUE, which has a torsional stiffness's units (N m = N m / rad with
    # the angle dropped); it enters the psi row as a generalised force
    g = Grader("rigid_body_euler_angles")
    ctx = g.context
    (Q3,) = [p for p in ctx.parameters if p.name == "Q3"]
    assert category(Q3, ctx) == "an applied torque term"
    r = g.grade("C*(psi'' + phi''*cos(theta) - phi'*theta'*sin(theta)) - (A - B)*"
                "(-phi'*sin(theta)*cos(psi) + theta'*sin(psi))*(phi'*sin(theta)*sin(psi)"
                " + theta'*cos(psi)) = 0")
    assert [(e.kind, e.category) for e in r.edits] == [("missing", "an applied torque term")]


def test_a_term_from_the_kinetic_energy_without_rates_is_not_centripetal():
    # bead on a hoop spun at omega (prescribed): -m R^2 w^2 sin cos comes from T = m R^2
    # w^2 sin^2/2 -- the centrifugal term; gravity only where g is
    ctx = Grader("bead_on_hoop").context
    th = sp.Symbol("theta", real=True)
    R, m, w, g = sp.symbols("R m omega g", positive=True)
    assert category(-R**2*m*w**2*sp.sin(th)*sp.cos(th), ctx) == "a centrifugal term"
    assert category(R*g*m*sp.sin(th), ctx) == "a gravity term"
    # a term on gravity's state part that is not gravity: never called gravity
    assert category(-R*w**2*sp.sin(th), ctx) == "a centrifugal term"


def test_the_pivot_shaking_term_is_named_by_its_origin():
    ctx = Grader("kapitza_pendulum").context
    th, t = sp.Symbol("theta", real=True), sp.Symbol("t", real=True)
    a, W, l, m = sp.symbols("a Omega l m", positive=True)
    assert category(-a*W**2*sp.cos(W*t)*sp.sin(th), ctx) == "a term of the prescribed motion"


def test_shown_expressions_are_reduced():
    m, al = sp.symbols("m alpha", positive=True)
    assert tidy(1/(m*sp.sin(al)**2 + m*sp.cos(al)**2)) == 1/m
    assert display(1/(m*sp.sin(al)**2 + m*sp.cos(al)**2)) == "1/m"
    g, k, l = sp.symbols("g k l", positive=True)
    assert display(g*l*m + k*l*m) == "l*m*(g + k)"
    x = sp.Symbol("x")
    assert display(-g*sp.sin(x)) == "-g*sin(x)"      # nothing to reduce: as it was


def test_latex_is_echoed_as_typed():
    r = Grader("simple_pendulum").grade(r"a\ddot{\theta} - g\sin\theta = 0")
    (e,) = r.edits
    assert (e.kind, e.term, e.correct) == ("sign", r"-g \sin\theta", r"g \sin\theta")
    r = Grader("rigid_rod_pendulum").grade(r"m l^2 \ddot{\theta} + \frac{m g l}{2} \sin\theta = 0")
    (e,) = r.edits
    assert e.kind == "coefficient" and r"\ddot{\theta}" in e.term and r"\frac{" in e.correct
    r = Grader("block_on_wedge").grade(r"M \ddot{q}_2 + m \ddot{q}_1 \cos\alpha = 0")
    assert any(r"\ddot{q}_2" in e.term + e.correct for e in r.edits), str(r)


def test_unicode_letters_are_echoed_as_typed():
    r = Grader("simple_pendulum").grade("a θ̈ + g cos(θ) = 0")
    (e,) = r.edits
    assert "θ" in e.term and "theta" not in e.term + e.correct
