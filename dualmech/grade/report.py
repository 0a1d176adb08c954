r"""The report of a graded batch: JSON for machines, Markdown for people.

``results.json`` holds every result (the :class:`~.result.Grade` JSON with ``id``,
``question``, ``line``) and a summary per question; ``report.md`` has, per question, how many
answers were right and the most common mistakes -- grouped by the wrong term, so twenty
students who dropped the same Coriolis term are one line -- and, per student, the verdict and
feedback on each answer.

Example
-------
>>> results = [{"id": "s1", "question": "q", "status": "wrong", "summary": "wrong",
...             "edits": [{"kind": "missing", "sentence": "equation 2: the term `c*x'` is missing"}]},
...            {"id": "s2", "question": "q", "status": "wrong", "summary": "wrong",
...             "edits": [{"kind": "missing", "sentence": "the term `c*x'` is missing"}]}]
>>> summarise(results)["q"]["mistakes"][0][:2]
("the term `c*x'` is missing", 2)
"""
from __future__ import annotations

import json
import re
from collections import Counter, defaultdict
from pathlib import Path

__all__ = ["summarise", "write_report", "markdown"]

_PART = re.compile(r"^(equation|component) \d+: ")


def mistake_keys(result: dict) -> list[str]:
    """What went wrong in one answer, as keys that group like mistakes across answers."""
    if result.get("status") == "invalid":
        return ["not graded: " + _first_sentence(result.get("summary", ""))]
    if result.get("status") != "wrong":
        return []
    keys = [_PART.sub("", e["sentence"]) for e in result.get("edits", [])]
    keys += [f"dimensions: {_PART.sub('', d)}" for d in result.get("dimension_issues", [])]
    return keys or [result.get("summary", "wrong")]


def _first_sentence(text: str) -> str:
    return text.split(". ")[0].split("; ")[0][:160]


def summarise(results: list[dict]) -> dict:
    """Per question: counts of right, wrong and not graded, and the mistakes by frequency
    (``(mistake, answers, students)``)."""
    out: dict = {}
    by_question = defaultdict(list)
    for r in results:
        by_question[r.get("question", "")].append(r)
    for q, rs in by_question.items():
        counts = Counter(r.get("status") for r in rs)
        mistakes = Counter()
        students = defaultdict(list)
        for r in rs:
            for key in dict.fromkeys(mistake_keys(r)):
                mistakes[key] += 1
                students[key].append(str(r.get("id", "")))
        out[q] = {"answers": len(rs), "right": counts.get("right", 0),
                  "wrong": counts.get("wrong", 0), "invalid": counts.get("invalid", 0),
                  "mistakes": [(m, n, students[m]) for m, n in mistakes.most_common()]}
    return out


def markdown(results: list[dict], title: str = "Grades") -> str:
    """The readable report (see the module docstring)."""
    summary = summarise(results)
    total = Counter(r.get("status") for r in results)
    lines = [f"# {title}", "",
             f"{len(results)} answers: {total.get('right', 0)} right, "
             f"{total.get('wrong', 0)} wrong, {total.get('invalid', 0)} not graded.", "",
             "## By question", ""]
    for q, s in summary.items():
        lines += [f"### {q}", "", f"{s['right']} of {s['answers']} right"
                  + (f", {s['invalid']} not graded" if s["invalid"] else "") + ".", ""]
        if s["mistakes"]:
            lines += ["| mistake | answers | students |", "|---|---|---|"]
            for m, n, who in s["mistakes"][:10]:
                shown = ", ".join(who[:8]) + (" ..." if len(who) > 8 else "")
                lines.append(f"| {_cell(m)} | {n} | {_cell(shown)} |")
            lines.append("")
    lines += ["## By student", ""]
    by_student = defaultdict(list)
    for r in results:
        by_student[str(r.get("id", ""))].append(r)
    for sid in sorted(by_student):
        lines += [f"### {sid}", ""]
        for r in by_student[sid]:
            head = {"right": "right", "wrong": "WRONG", "invalid": "not graded"}.get(
                r.get("status"), r.get("status"))
            lines.append(f"- **{r.get('question', '')}** ({head}): {r.get('summary', '')}")
            for e in r.get("edits", []):
                lines.append(f"  - {e['sentence']}")
            for d in r.get("dimension_issues", []):
                lines.append(f"  - dimensions: {d}")
        lines.append("")
    return "\n".join(lines)


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def write_report(results: list[dict], out: str | Path, title: str = "Grades") -> dict:
    """Write ``results.json`` and ``report.md`` into ``out``; return their paths."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    paths = {"json": out / "results.json", "markdown": out / "report.md"}
    data = {"summary": {q: dict(s, mistakes=[{"mistake": m, "answers": n, "students": w}
                                             for m, n, w in s["mistakes"]])
                        for q, s in summarise(results).items()},
            "results": results}
    paths["json"].write_text(json.dumps(data, indent=2, default=str), encoding="utf-8")
    paths["markdown"].write_text(markdown(results, title), encoding="utf-8")
    return paths
