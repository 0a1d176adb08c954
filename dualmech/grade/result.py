"""The result of grading one answer: ``str()`` is the feedback, ``to_dict()`` the JSON object.

Example
-------
>>> e = Edit("missing", 1, "", "-2*R*phi'*theta'*sin(theta)", "a Coriolis term")
>>> e.sentence()
"equation 2: the term `-2*R*phi'*theta'*sin(theta)` is missing (a Coriolis term)"
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

__all__ = ["Edit", "Grade", "STATUSES"]

#: ``right``: the answer is correct; ``wrong``: it is not (the feedback says why);
#: ``invalid``: it could not be graded as typed (syntax, unknown name, too large, ...).
STATUSES = ("right", "wrong", "invalid")


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

    def sentence(self) -> str:
        where = f"{self.part} {self.equation + 1}: " if self.equation is not None else ""
        if self.where:
            where = f"{self.where}: "
        cat = f" ({self.category})" if self.category else ""
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
            return f"{where}{self.detail} are swapped in `{self.term}`: it is `{self.correct}`"
        if self.kind == "factor":
            return (f"{where}the whole answer is off by a factor: it is `{self.detail}` times "
                    "the right one")
        return f"{where}{self.kind}: `{self.term}` -> `{self.correct}`"

    def to_dict(self) -> dict:
        return {"kind": self.kind, self.part: self.equation, "term": self.term,
                "correct": self.correct, "category": self.category, "detail": self.detail,
                "where": self.where, "term_html": self.term_html,
                "correct_html": self.correct_html, "sentence": self.sentence()}


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

    @property
    def right(self) -> bool:
        return self.status == "right"

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
        if self.status != "invalid":
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
                "false_right_bound": _json(self.bound), "seconds": self.seconds}


def _fmt(v) -> str:
    return f"{v:.6g}" if isinstance(v, float) else str(v)


def _json(v):
    if isinstance(v, float):
        return None if math.isnan(v) or math.isinf(v) else v
    return v
