"""The result of grading one answer: ``str()`` is the feedback, ``to_dict()`` the JSON object.

Example
-------
>>> e = Edit("missing", 1, "", "-2*R*phi'*theta'*sin(theta)", "a Coriolis term")
>>> e.sentence()
"equation 2: the term `-2*R*phi'*theta'*sin(theta)` is missing (a Coriolis term)"
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

__all__ = ["Edit", "Grade", "STATUSES", "FEEDBACK_LEVELS", "check_feedback", "score_of",
           "ONE_TERM", "FEW_TERMS", "DIMENSIONS_ONLY"]

#: ``right``: the answer is correct; ``wrong``: it is not (the feedback says why);
#: ``invalid``: it could not be graded as typed (syntax, unknown name, too large, ...).
STATUSES = ("right", "wrong", "invalid")

#: How much feedback a wrong answer gets, least first: ``verdict`` (right or wrong only),
#: ``locate`` (which equation and which kind of term; no term shown), ``hint`` (the wrong term,
#: not its correction), ``full`` (the smallest edit with the correct terms).  A teacher sets
#: it per question or assignment: ``full`` for homework, ``verdict`` or ``locate`` for exams.
FEEDBACK_LEVELS = ("verdict", "locate", "hint", "full")

#: What a located edit says, by kind, when no term may be shown.
_LOCATED = {"missing": "a term is missing", "extra": "a term does not belong",
            "sign": "a term has the wrong sign", "coefficient": "a term has a wrong coefficient",
            "replace": "a term is the wrong function", "swap": "two symbols are swapped",
            "factor": "the whole answer is off by a constant factor"}
_RIGHT_VALUE = re.compile(r"the answer is (\S+), the right value \S+$")


#: Partial credit (:func:`score_of`): a wrong equation (or component, or expression) that one
#: term's edit makes right, one that two or three terms' edits make right, and a right value
#: written with inconsistent dimensions.
ONE_TERM, FEW_TERMS, DIMENSIONS_ONLY = 0.5, 0.25, 0.5


def score_of(status: str, parts: int = 1, wrong_parts=None, edits=(), credit=None) -> float:
    """The score of one answer in [0, 1], by a rule a teacher can explain to a class.

    * a right answer scores 1, one that could not be graded (``invalid``) 0;
    * a wrong answer of ``parts`` equations (or vector components) scores the mean over its
      parts: 1 for each right part; for each wrong part, :data:`ONE_TERM` when the smallest
      edit that makes it right changes one term, :data:`FEW_TERMS` when it changes two or
      three, 0 when no small edit explains it (``wrong_parts`` None: every part is wrong);
    * a judge may set the credit itself (``credit``): a system of right equations that does
      not determine every unknown scores the share of unknowns it determines; a right value
      with inconsistent dimensions scores :data:`DIMENSIONS_ONLY`.

    Examples
    --------
    >>> score_of("right"), score_of("invalid")
    (1.0, 0.0)
    >>> e = Edit("sign", 1, "-k*x", "k*x")
    >>> score_of("wrong", parts=2, wrong_parts=(1,), edits=[e])    # (1 + 1/2) / 2
    0.75
    >>> score_of("wrong", parts=2, wrong_parts=(0, 1), edits=[e])  # (0 + 1/2) / 2
    0.25
    """
    if status == "right":
        return 1.0
    if status not in ("wrong", "right") or (credit is None and parts < 1):
        return 0.0
    if credit is not None:
        return float(credit)
    wrong = tuple(range(parts)) if wrong_parts is None else tuple(wrong_parts)
    total = float(parts - len(wrong))
    for i in wrong:
        n = sum(1 for e in edits if e.equation == i or (parts == 1 and e.equation is None))
        total += ONE_TERM if n == 1 else FEW_TERMS if 2 <= n <= 3 else 0.0
    return total / parts


def check_feedback(level: str) -> str:
    """``level`` when it is one of :data:`FEEDBACK_LEVELS`; a clear ``ValueError`` otherwise."""
    if level not in FEEDBACK_LEVELS:
        raise ValueError(f"`feedback` must be one of {', '.join(FEEDBACK_LEVELS)}, "
                         f"got {level!r:.40}.")
    return level


@dataclass(frozen=True)
class Edit:
    """One step of the smallest edit that makes a wrong answer right.

    ``kind``: ``missing`` (``correct`` is the term to add), ``extra`` (``term`` must go),
    ``sign``, ``coefficient`` (``term`` becomes ``correct``), ``replace`` (the right
    coefficient on the wrong function: ``g*sin(theta)`` where ``g*theta`` belongs in a
    linearised equation), ``swap`` (``detail`` names the
    two symbols), ``factor`` (the whole answer is off by ``detail``).  ``equation`` is the
    0-based index of the equation (or, with ``part="component"``, of the vector component)
    in the answer; ``None`` for a single expression.  ``where`` names that equation for a
    student (``the theta equation``); ``term_html`` and ``correct_html`` are the terms as
    MathML for web pages.
    """

    kind: str
    equation: int | None
    term: str
    correct: str
    category: str = ""
    detail: str = ""
    part: str = "equation"
    where: str = ""
    term_html: str = ""
    correct_html: str = ""
    shown: str = "full"

    def at_level(self, level: str) -> "Edit":
        """This edit as ``level`` shows it (:data:`FEEDBACK_LEVELS`): ``hint`` drops the correct
        term, ``locate`` every term."""
        if check_feedback(level) == "full":
            return self
        keep = level == "hint" and self.kind != "factor"
        return replace(self, correct="", correct_html="", detail="", shown=level,
                       term=self.term if keep else "", term_html=self.term_html if keep else "")

    def sentence(self) -> str:
        where = f"{self.part} {self.equation + 1}: " if self.equation is not None else ""
        if self.where:
            where = f"{self.where}: "
        cat = f" ({self.category})" if self.category else ""
        if self.shown != "full":
            return where + self._partial() + cat
        if self.kind == "missing":
            return f"{where}the term `{self.correct}` is missing{cat}"
        if self.kind == "extra":
            return f"{where}the term `{self.term}` does not belong{cat}"
        if self.kind == "sign":
            return f"{where}the term `{self.term}` has the wrong sign: it is `{self.correct}`{cat}"
        if self.kind == "coefficient":
            return (f"{where}wrong coefficient: `{self.term}` where `{self.correct}` "
                    f"belongs{cat}")
        if self.kind == "replace":
            return f"{where}wrong term: `{self.term}` where `{self.correct}` belongs{cat}"
        if self.kind == "swap":
            return (f"{where}{self.detail} are swapped in `{self.term}`: it is "
                    f"`{self.correct}`{cat}")
        if self.kind == "factor":
            return (f"{where}the whole answer is off by a factor: it is `{self.detail}` times "
                    "the right one")
        return f"{where}{self.kind}: `{self.term}` -> `{self.correct}`"

    def _partial(self) -> str:
        """The sentence of a ``hint`` or ``locate`` edit: never the correct term."""
        if not self.term:
            return _LOCATED.get(self.kind, "a term is wrong")
        if self.kind == "extra":
            return f"the term `{self.term}` does not belong"
        if self.kind == "sign":
            return f"the term `{self.term}` has the wrong sign"
        if self.kind == "coefficient":
            return f"the coefficient of `{self.term}` is wrong"
        if self.kind == "swap":
            return f"two symbols are swapped in `{self.term}`"
        return f"the term `{self.term}` is wrong"

    def to_dict(self) -> dict:
        return {"kind": self.kind, self.part: self.equation, "term": self.term,
                "correct": self.correct, "category": self.category, "detail": self.detail,
                "where": self.where, "term_html": self.term_html,
                "correct_html": self.correct_html, "shown": self.shown,
                "sentence": self.sentence()}


@dataclass
class Grade:
    """Verdict and feedback on one answer.

    ``status`` is one of :data:`STATUSES`; ``summary`` one sentence; ``details`` further
    sentences (which equation, what it matches); ``edits`` the smallest edit as terms;
    ``dimension_issues`` inconsistent terms (reported first); ``state`` a concrete state where
    answer and truth differ when no small edit explains it; ``method`` names how the verdict was
    decided; ``seconds`` is the CPU time spent on this answer (a problem's one-time loading -- its
    models, sampled points and feedback targets -- is not counted).
    """

    problem: str
    quantity: str
    kind: str
    answer: str
    status: str
    summary: str
    details: list = field(default_factory=list)
    edits: list = field(default_factory=list)
    dimension_issues: list = field(default_factory=list)
    matches: str = ""
    state: dict = field(default_factory=dict)
    method: str = "none"
    bound: float = math.nan
    seconds: float = 0.0
    feedback: str = "full"
    score: float | None = None

    def __post_init__(self):
        if self.score is None:
            self.score = score_of(self.status, edits=self.edits)

    @property
    def right(self) -> bool:
        return self.status == "right"

    def at_level(self, level: str) -> "Grade":
        """This grade as a teacher's feedback ``level`` shows it (:data:`FEEDBACK_LEVELS`).

        ``verdict``: right or wrong and nothing else; ``locate``: which equation and which kind
        of term, no term and no right value shown; ``hint``: also the wrong term, never its
        correction; ``full``: everything.  A grade that could not be made (``invalid``) keeps
        its reason at every level: it is about what was typed, not about the answer.

        Examples
        --------
        >>> from dualmech import grade
        >>> g = grade("simple_pendulum", "a*theta'' - g*sin(theta) = 0")
        >>> print(g.at_level("hint"))  # doctest: +ELLIPSIS
        WRONG: the equation does not follow from the equations of motion
          smallest edit that makes it right:
            - the term `-g*sin(theta)` has the wrong sign (a gravity term)
        ...
        >>> print(g.at_level("locate").edits[0].sentence())
        a term has the wrong sign (a gravity term)
        >>> print(g.at_level("verdict"))
        WRONG: the answer is wrong
        """
        if check_feedback(level) == "full" or self.status == "invalid":
            return replace(self, feedback=level)
        if level == "verdict":
            summary = "the answer is right" if self.right else "the answer is wrong"
            return replace(self, summary=summary, details=[], edits=[], dimension_issues=[],
                           matches="", state={}, feedback=level)
        details = [_RIGHT_VALUE.sub(r"the answer is \1, not the right value", d)
                   for d in self.details]
        return replace(self, details=details, edits=[e.at_level(level) for e in self.edits],
                       feedback=level)

    def __str__(self) -> str:
        head = {"right": "RIGHT", "wrong": "WRONG", "invalid": "NOT GRADED"}[self.status]
        lines = [f"{head}: {self.summary}"]
        for issue in self.dimension_issues:
            lines.append(f"  dimensions: {issue}")
        if self.edits:
            lines.append("  smallest edit that makes it right:")
            lines.extend(f"    - {e.sentence()}" for e in self.edits)
        lines.extend(f"  {d}" for d in self.details)
        if self.state:
            shown = ", ".join(f"{k}={_fmt(v)}" for k, v in self.state.items())
            lines.append(f"  at {shown}")
        if self.status == "wrong" and self.feedback != "verdict":
            lines.append(f"  score: {self.score:.2g} (see dualmech.grade.result.score_of)")
        if self.status != "invalid" and self.feedback != "verdict":
            lines.append(f"  (decided by the {self.method}; {self.problem}, {self.quantity})")
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """Jupyter: the verdict in colour, the summary and the smallest edit."""
        from dualmech.report.jupyter import grade_html
        return grade_html(self)

    def to_dict(self) -> dict:
        return {"problem": self.problem, "quantity": self.quantity, "kind": self.kind,
                "answer": self.answer, "status": self.status, "right": self.right,
                "summary": self.summary, "details": list(self.details),
                "edits": [e.to_dict() for e in self.edits],
                "dimension_issues": list(self.dimension_issues), "matches": self.matches,
                "state": {k: _json(v) for k, v in self.state.items()}, "method": self.method,
                "false_right_bound": _json(self.bound), "seconds": self.seconds,
                "feedback": self.feedback, "score": self.score}


def _fmt(v) -> str:
    return f"{v:.6g}" if isinstance(v, float) else str(v)


def _json(v):
    if isinstance(v, float):
        return None if math.isnan(v) or math.isinf(v) else v
    return v
