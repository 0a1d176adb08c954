"""Names and constants of a parsed answer resolved into a formula tree, within the limits.

The tree is nested tuples: ``("c", Fraction)``, ``("pi",)``, ``("s", symbol)``, ``("add",
terms)``, ``("mul", factors)``, ``("pow", base, int)``, ``("rpow", base, Fraction)``, ``("f",
name, argument)``, ``("vec", components)``.  Exponents must be numbers; they are computed here
with bounds checked before each power, so ``9^9^9^9`` is refused, never evaluated.
"""
from __future__ import annotations

from fractions import Fraction

from dualmech.grade.parser import AnswerError, AnswerTooLarge, Limits, Node, to_text
from dualmech.grade.vocabulary import Vocabulary

__all__ = ["resolve"]

_MAX_BITS = 4000        # largest constant, in bits


def resolve(node: Node, voc: Vocabulary, limits: Limits):
    """The formula tree of a parsed ``node``, names looked up in ``voc``."""
    return _resolve(node, voc, limits)


def _resolve(node: Node, voc: Vocabulary, limits: Limits):
    op, a = node.op, node.args
    if op == "num":
        return ("c", a[0])
    if op == "resolved":
        return a[0]
    if op == "name":
        refs = voc.resolve(a[0], a[1])
        leaves = [("pi",) if r.kind == "constant" else ("s", r.symbol) for r in refs]
        return leaves[0] if len(leaves) == 1 else ("mul", tuple(leaves))
    if op == "group":
        return _resolve(a[0], voc, limits)
    if op == "neg":
        return ("mul", (("c", Fraction(-1)), _resolve(a[0], voc, limits)))
    if op == "inv":
        inner = _resolve(a[0], voc, limits)
        if inner[0] == "c":
            return ("c", 1 / inner[1]) if inner[1] != 0 else _zero_division()
        return ("pow", inner, -1)
    if op == "add":
        return ("add", tuple(_resolve(c, voc, limits) for c in a))
    if op == "mul":
        return ("mul", tuple(_resolve(c, voc, limits) for c in _drop_of_t(a, voc)))
    if op == "pow":
        if a[0].op == "name" and len(voc.resolve(*a[0].args)) > 1:
            # an implicit product typed as one word: the power binds to its last letter
            # (``ka^2`` is ``k*a^2``, as ``k a^2`` is), never to the whole product
            *first, last = _resolve(a[0], voc, limits)[1]
            power = Node("pow", (_leaf(last), a[1]), (a[1],))
            return ("mul", (*first, _resolve(power, voc, limits)))
        base = _resolve(a[0], voc, limits)
        e = _constant(a[1], limits)
        if e.denominator == 1:
            if abs(e) > limits.exponent:
                raise AnswerTooLarge(f"the exponent {e} is larger than {limits.exponent}.")
            if base[0] == "c":
                _check_bits(base[1], int(e))
                return ("c", base[1] ** int(e)) if base[1] != 0 or e >= 0 else \
                    _zero_division()
            return ("pow", base, int(e))
        if e.denominator > 12 or abs(e) > limits.exponent:
            raise AnswerTooLarge(f"the exponent {e} is not supported (use small fractions).")
        return ("rpow", base, e)
    if op == "func":
        arg = _resolve(a[1], voc, limits)
        if a[0] == "sqrt":
            return ("rpow", arg, Fraction(1, 2))
        return ("f", a[0], arg)
    if op == "vec":
        return ("vec", tuple(_resolve(c, voc, limits) for c in a))
    raise AssertionError(op)


def _leaf(leaf) -> Node:
    """A parsed node standing for ``leaf``, one resolved factor of an implicit product."""
    return Node("resolved", (leaf,))


def _zero_division():
    raise AnswerError("the answer divides by zero.")


def _check_bits(base: Fraction, k: int) -> None:
    bits = max(abs(base.numerator), base.denominator).bit_length() * abs(k)
    if bits > _MAX_BITS:
        raise AnswerTooLarge(f"a number in the answer is too large (about {bits} bits).")


def _drop_of_t(args, voc: Vocabulary):
    """``theta(t)`` is the coordinate itself, not ``theta*t``."""
    out = []
    for node in args:
        if (node.op == "group" and out and out[-1].op == "name" and node.args[0].op == "name"
                and node.args[0].args == ("t", 0)):
            ref = voc.lookup(out[-1].args[0], out[-1].args[1])
            if ref is not None and ref.kind == "coordinate":
                continue
        out.append(node)
    return out


def _constant(node: Node, limits: Limits) -> Fraction:
    """Value of a constant exponent, refusing anything large before computing it."""
    op, a = node.op, node.args
    if op == "num":
        return a[0]
    if op == "group":
        return _constant(a[0], limits)
    if op == "neg":
        return -_constant(a[0], limits)
    if op == "inv":
        v = _constant(a[0], limits)
        if v == 0:
            raise AnswerError("the answer divides by zero in an exponent.")
        return 1 / v
    if op in ("add", "mul"):
        vals = [_constant(c, limits) for c in a]
        out = Fraction(0) if op == "add" else Fraction(1)
        for v in vals:
            out = out + v if op == "add" else out * v
        _bound(out, limits)
        return out
    if op == "pow":
        b, e = _constant(a[0], limits), _constant(a[1], limits)
        if e.denominator != 1:
            raise AnswerError(f"a number to the power {e} inside an exponent is not graded; "
                              "write exponents as whole numbers or simple fractions.")
        if abs(e) > limits.exponent:
            raise AnswerTooLarge(f"the exponent {e} is larger than {limits.exponent}.")
        if b == 0 and e < 0:
            raise AnswerError("the answer divides by zero in an exponent.")
        _check_bits(b, int(e))
        out = b ** int(e)
        _bound(out, limits)
        return out
    raise AnswerError(f"exponents must be numbers; `{to_text(node)}` is not.")


def _bound(v: Fraction, limits: Limits) -> None:
    if abs(v) > 10 ** limits.digits or v.denominator > 10 ** limits.digits:
        raise AnswerTooLarge(f"the exponent {v} is too large.")
