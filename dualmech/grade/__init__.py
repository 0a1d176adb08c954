"""The exam-solution checker: grade typed answers against a problem's verified equations.

A teacher or student types an answer -- equations of motion, one equation, a reaction, an
energy, a Lagrangian, a generalised force, an acceleration -- and :func:`grade` says whether it
is right and, if not, what is wrong, as the smallest edit named in terms.  The text is read by
a whitelisting parser (never evaluated), checked against the problem's symbols, then decided
by exact evaluation at random points of the verified motion.

Example
-------
>>> from dualmech.grade import grade
>>> r = grade("toy_car", "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0")
>>> r.right, r.matches
(True, 'the equation of theta (Lagrange)')
"""
from importlib import import_module

_HOME = {
    "answers": ("Quantity", "UnknownQuantity", "catalogue"),
    "api": ("Grader", "grade"),
    "context": ("GradingUnavailable",),
    "parser": ("LIMITS", "AnswerError", "AnswerSyntaxError", "AnswerTooLarge", "Limits",
               "parse"),
    "result": ("STATUSES", "Edit", "Grade"),
    "vocabulary": ("UnknownName",),
}
_WHERE = {name: module for module, names in _HOME.items() for name in names}

__all__ = ["grade", "Grader", "Grade", "Edit", "STATUSES", "Quantity", "catalogue",
           "Limits", "LIMITS", "parse", "AnswerError", "AnswerSyntaxError", "AnswerTooLarge",
           "UnknownName", "UnknownQuantity", "GradingUnavailable"]


def __getattr__(name):   # imported when first used: `dualmech list` never loads sympy
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module 'dualmech.grade' has no attribute {name!r}")
    value = getattr(import_module(f".{module}", __name__), name)
    globals()[name] = value
    return value
