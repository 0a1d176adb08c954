"""The exam-solution checker: grade typed answers against a problem's verified equations.

This first layer reads answers safely: a whitelisting parser (:mod:`.parser`), the problem's
names and aliases (:mod:`.vocabulary`), and formulas evaluated exactly (:mod:`.formula`).
"""
from .formula import Env, Formula
from .parser import LIMITS, AnswerError, AnswerSyntaxError, AnswerTooLarge, Limits, parse
from .vocabulary import UnknownName, Vocabulary

__all__ = ["parse", "Limits", "LIMITS", "AnswerError", "AnswerSyntaxError", "AnswerTooLarge",
           "Vocabulary", "UnknownName", "Formula", "Env"]
