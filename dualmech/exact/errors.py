"""Why an expression is not decided exactly (:class:`NotExact`) or at all (:class:`Undecidable`)."""
from __future__ import annotations

__all__ = ["Undecidable", "NotExact"]


class Undecidable(ValueError):
    """No method here can decide this soundly; ``expr`` is the sub-expression, ``why`` the reason.

    Raised instead of ever giving a verdict that could be wrong.
    """

    def __init__(self, expr, why: str):
        self.expr, self.why = expr, why
        super().__init__(f"cannot decide identities involving `{expr}`: {why}")


class NotExact(Exception):
    """``expr`` leaves the exact world (``why``); interval arithmetic may still evaluate it."""

    def __init__(self, expr, why: str):
        self.expr, self.why = expr, why
        super().__init__(f"{expr}: {why}")
