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
from .answers import Quantity, UnknownQuantity, catalogue
from .api import Grader, grade
from .context import GradingUnavailable
from .parser import LIMITS, AnswerError, AnswerSyntaxError, AnswerTooLarge, Limits, parse
from .result import STATUSES, Edit, Grade
from .vocabulary import UnknownName

__all__ = ["grade", "Grader", "Grade", "Edit", "STATUSES", "Quantity", "catalogue",
           "Limits", "LIMITS", "parse", "AnswerError", "AnswerSyntaxError", "AnswerTooLarge",
           "UnknownName", "UnknownQuantity", "GradingUnavailable"]
