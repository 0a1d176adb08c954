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
(True, 'the equation of theta')
"""
import sys
import types

from dualmech._lazy import exports

_HOME = {
    "answers": ("Quantity", "UnknownQuantity", "catalogue"),
    "api": ("Grader", "grade"),
    "context": ("GradingUnavailable",),
    "parser": ("LIMITS", "AnswerError", "AnswerSyntaxError", "AnswerTooLarge", "Limits",
               "parse"),
    "result": ("STATUSES", "Edit", "Grade"),
    "vocabulary": ("UnknownName",),
}

__all__ = ["grade", "Grader", "Grade", "Edit", "STATUSES", "Quantity", "catalogue",
           "Limits", "LIMITS", "parse", "AnswerError", "AnswerSyntaxError", "AnswerTooLarge",
           "UnknownName", "UnknownQuantity", "GradingUnavailable"]

__getattr__, __dir__ = exports(__name__, _HOME, globals())   # imported when first used


class _Package(types.ModuleType):
    """``dualmech.grade`` is this package and, called, :func:`~dualmech.grade.api.grade`.

    ``from dualmech import grade`` must give something callable whether or not the package
    was imported before (an import of ``dualmech.grade.x`` binds the package to that name).
    """

    def __call__(self, *args, **kwargs):
        return self.grade(*args, **kwargs)


sys.modules[__name__].__class__ = _Package
