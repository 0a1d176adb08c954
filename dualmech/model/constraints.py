r"""Constraint declarations of the direct form: checked, kept at their level, differentiated.

A direct model (:class:`~dualmech.model.direct.NewtonEuler`) declares the constraints its
motion keeps -- a holonomic ``g(q, t) = 0``, a velocity-level ``a(q, t) . q' + a0 = 0``, or
rolling without slipping -- instead of writing their acceleration-level rows by hand.  Each
declaration is checked here (one scalar, only the model's coordinates and their rates, linear
in the rates), kept as a :class:`~dualmech.model.equations.Constraint` at the level it was
written, and differentiated (in symengine) to the acceleration-level row the equations hold.

Rolling: the no-slip condition is on the velocity of the *material* point of the body that is
instantaneously at the contact, ``v_C + w x r_CP`` (``C`` the mass centre, ``w`` the body's
angular velocity), never on the velocity of the geometric contact point ``P``, which moves
along the ground as the body rolls (:func:`material_velocity`).

Example
-------
>>> import sympy as sp
>>> from dualmech import Frame, Point, RigidBody, coordinate, rot_z
>>> x, th = coordinate("x"), coordinate("theta"); m, r = sp.symbols("m r", positive=True)
>>> O = Frame.ground(); W = O.child("W", rot_z(-th))
>>> C = Point.origin(O).locate("C", x * O.x + r * O.y)
>>> wheel = RigidBody("wheel", m, C, W, sp.diag(1, 1, m * r**2 / 2))
>>> contact = C.locate("P", -r * O.y)
>>> sp.trigsimp(material_velocity(wheel, contact, O).dot(O.x))
-r*Derivative(theta(t), t) + Derivative(x(t), t)
"""
from __future__ import annotations

from typing import Sequence

import symengine as se
import sympy as sp
from sympy.core.function import AppliedUndef

from dualmech.model._algebra import names_of, time_se, to_se
from dualmech.model._expr import as_expr, refuse_jumps
from dualmech.model.bodies import RigidBody
from dualmech.model.equations import Constraint, ModelError, state_symbols, to_plain, \
    to_plain_se, from_plain, vanishes_identically
from dualmech.model.kinematics import Frame, Point, Vector

__all__ = ["declared", "material_velocity", "acceleration_row", "trig_reduced"]


def declared(name: str, value, level: str, coordinates: Sequence, unknowns: Sequence = (),
             model: str = "the model") -> Constraint:
    """``value`` checked as a ``level`` (``"position"`` or ``"velocity"``) constraint of a
    model in ``coordinates`` whose reactions are ``unknowns``; raises :class:`ModelError`
    saying what to fix."""
    what = f"constraint `{name}` of `{model}`"
    expr = _scalar(what, value)
    refuse_jumps([expr], what)
    coordinates = tuple(coordinates)
    stray = [f for f in expr.atoms(AppliedUndef) if f not in coordinates]
    if stray:
        raise ModelError(f"{what} uses {sorted(map(str, stray))}, which are not coordinates of "
                         f"`{model}` ({', '.join(q.func.__name__ for q in coordinates)}); write "
                         "it in the model's coordinates, their rates and the parameters.")
    hit = sorted(str(u) for u in expr.free_symbols & set(unknowns))
    if hit:
        raise ModelError(f"{what} holds the reaction(s) {hit}: a constraint is kinematic (where "
                         "the bodies may be and how fast), never a force.")
    for d in expr.atoms(sp.Derivative):
        if d.derivative_count > 1 or level == "position":
            raise ModelError(
                f"{what} holds {d}: " + ("a position-level constraint holds no rates; declare "
                                         "it with `velocity_constraint`." if d.derivative_count
                                         == 1 else "declare a constraint at position or "
                                         "velocity level; its acceleration level is derived."))
    if vanishes_identically(expr, coordinates):
        raise ModelError(f"{what} is identically zero: the coordinates already keep it (e.g. "
                         "the height of a rolling body is built into them); leave it out.")
    if level == "velocity":
        _linear_in_rates(what, expr, coordinates)
    return Constraint(name, level, expr, f"constraint {name} (acceleration level)")


def _scalar(what: str, value) -> sp.Expr:
    if isinstance(value, Vector):
        raise ModelError(f"{what} is a Vector; a constraint is one scalar: declare one per "
                         "direction, e.g. `v.dot(O.x)` and `v.dot(O.y)`.")
    if isinstance(value, (list, tuple, sp.MatrixBase)):
        raise ModelError(f"{what} is a sequence or matrix of {len(value)} entries; a constraint "
                         "is one scalar: declare one per entry.")
    expr = as_expr(value)
    if not isinstance(expr, sp.Expr):
        raise ModelError(f"{what} must be a scalar expression, got {type(expr).__name__}.")
    return expr


def _linear_in_rates(what: str, expr: sp.Expr, coordinates: tuple) -> None:
    """Refuse ``expr`` unless it is ``a(q, t) . q' + a0(q, t)`` with some ``a`` nonzero
    (decided in symengine: sympy's ``diff`` of a wheel's contact velocity takes minutes)."""
    plain = to_plain_se(expr, coordinates)
    rates = [se.Symbol(state_symbols(q).qd.name) for q in coordinates]
    held = plain.free_symbols
    if not any(r in held for r in rates):
        raise ModelError(f"{what} holds no rate: it is a position-level constraint; declare it "
                         "with `constraint` (its velocity level is derived).")
    for q, r in zip(coordinates, rates):
        if r in held and plain.diff(r).free_symbols & set(rates):
            raise ModelError(f"{what} is not linear in the rates (its coefficient of "
                             f"{q.func.__name__}' holds rates); a velocity constraint is "
                             "a(q, t) . q' + a0(q, t) = 0.")


def acceleration_row(constraint: Constraint) -> tuple:
    """``(row, names)``: the constraint differentiated to acceleration level, in symengine
    (twice in time for a position-level one, once for a velocity-level one)."""
    expr = constraint.expression
    row = to_se(expr)
    for _ in range(2 if constraint.level == "position" else 1):
        row = row.diff(time_se())
    return row, names_of(expr)


def material_velocity(body: RigidBody, contact: Point, ground: Frame) -> Vector:
    """Velocity in ``ground`` of the material point of ``body`` instantaneously at
    ``contact``: ``v_C + w x r_C->contact`` (``C`` the mass centre, ``w`` the body's angular
    velocity in ``ground``).

    This is not ``contact.vel(ground)``: a geometric contact point located by the
    coordinates (``x O.x + y O.y`` for a disk) slides along the ground as the body rolls, and
    its velocity is the rate of those coordinates, whatever the body does.
    """
    if not isinstance(body, RigidBody):
        raise ModelError(f"rolling needs a rigid body (it turns about the contact); "
                         f"`{getattr(body, 'name', body)}` is a {type(body).__name__}.")
    if not isinstance(contact, Point):
        raise ModelError(f"the contact must be a Point, got {type(contact).__name__}.")
    w = body.frame.ang_vel_in(ground)
    return body.masscenter.vel(ground) + w.cross(contact.pos_from(body.masscenter))


def trig_reduced(expr, coordinates: Sequence) -> sp.Expr | None:
    """``expr`` (in ``coordinates``, their rates and parameters) in the normal form of a
    polynomial in sines and cosines modulo ``sin(a)^2 + cos(a)^2 = 1``, or ``None`` when it
    is not such a polynomial (a square root, a sine in a denominator...).

    The normal form (the remainder of the division by those relations, the sines first in a
    lexical order) is unique: an expression that vanishes identically becomes 0, and a
    rolling row built from rotation matrices becomes the hand one.

    >>> from dualmech import coordinate
    >>> a, b = coordinate("a"), coordinate("b")
    >>> trig_reduced(sp.sin(a)**2 * sp.cos(b) + sp.cos(a)**2 * sp.cos(b) - sp.cos(b), [a, b])
    0
    >>> trig_reduced(sp.sqrt(1 + sp.sin(a)), [a]) is None
    True
    """
    plain = to_plain(expr, coordinates)
    args = sorted({f.args[0] for f in plain.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
    sines = [sp.Dummy(f"s{i}") for i in range(len(args))]
    cosines = [sp.Dummy(f"c{i}") for i in range(len(args))]
    poly = plain.xreplace({**{sp.sin(a): s for a, s in zip(args, sines)},
                           **{sp.cos(a): c for a, c in zip(args, cosines)}})
    if poly.has(sp.sin, sp.cos) or not poly.is_polynomial(*sines, *cosines):
        return None
    if not args:
        return expr
    relations = [s**2 + c**2 - 1 for s, c in zip(sines, cosines)]
    _, rem = sp.reduced(poly, relations, *sines, *cosines, order="lex")
    back = {**{s: sp.sin(a) for a, s in zip(args, sines)},
            **{c: sp.cos(a) for a, c in zip(args, cosines)}}
    return from_plain(rem.xreplace(back), coordinates)
