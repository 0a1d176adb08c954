"""The report's two pages: ``report.md`` and a self-contained ``report.html``.

The HTML page needs nothing but a browser: equations are MathML (:mod:`.mathml`), charts are
embedded as PNG data, styling is a few lines of CSS, and there is no script.  Both pages hold
the summary table (verdict, method, time, reactions, printed answers per problem), then per
problem: the verdict line, the equations of motion of the reference model, the reactions
recovered from the direct form, every printed answer with its judgement, and the chart with
its notes (identical curves, zero reactions, why the simulation stops where it does).
"""
from __future__ import annotations

import base64
import html
from pathlib import Path

import sympy as sp

from . import mathml

__all__ = ["markdown_page", "html_page", "summary_rows", "SUMMARY_HEADERS"]

SUMMARY_HEADERS = ("problem", "dof", "equivalent", "method", "seconds", "reactions",
                   "printed answers")


def _dof(problem) -> str:
    try:
        return str(problem.model(problem.reference).n)
    except Exception:  # noqa: BLE001 - a broken model is still listed
        return "?"


def _published(c) -> list:
    return list(getattr(c, "published", None) or [])


def _counts(c) -> str:
    verdicts = [p.verdict for p in _published(c)]
    if not verdicts:
        return "-"
    order = dict.fromkeys(["correct", "wrong", "unchecked", *verdicts])
    return ", ".join(f"{verdicts.count(v)} {v}" for v in order if v in verdicts)


def summary_rows(comparisons) -> list[tuple]:
    rows = []
    for c in comparisons:
        rows.append((c.problem.name, _dof(c.problem), "yes" if c.equivalent else "NO",
                     str(c.method), f"{float(getattr(c, 'seconds', 0.0)):.2f}",
                     _reaction_cell(c), _counts(c)))
    return rows


def _reaction_cell(c) -> str:
    """Declared reactions, and how many of them one derivation alone gives."""
    cell = getattr(c, "reaction_count_text", None)
    return cell() if callable(cell) else str(len(_reactions(c)))


def _reactions(c) -> dict:
    try:
        return dict(c.reactions or {})
    except Exception:  # noqa: BLE001 - display only
        return {}


def _md_table(headers, rows) -> str:
    esc = lambda s: str(s).replace("|", "\\|").replace("\n", " ")  # noqa: E731
    lines = ["| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    lines += ["| " + " | ".join(esc(c) for c in r) + " |" for r in rows]
    return "\n".join(lines)


def _verdict(c) -> str:
    line = getattr(c, "verdict_line", None)
    return line() if callable(line) else str(c).splitlines()[0]


def markdown_page(comparisons, charts: dict, duration: float) -> str:
    ok = sum(1 for c in comparisons if c.equivalent)
    lines = ["# dualmech report", "",
             f"{ok} of {len(comparisons)} problems: every model agrees with the reference "
             f"model. Charts: up to {duration:g} s of simulated motion, cut where the scene "
             "ends.", "", _md_table(SUMMARY_HEADERS, summary_rows(comparisons)), ""]
    for c in comparisons:
        name = c.problem.name
        lines += [f"## {name}", "", "```", str(c), "```", ""]
        pubs = _published(c)
        if pubs:
            lines += ["Printed answers:", "",
                      _md_table(("answer", "where", "verdict", "why"),
                                [(p.label, p.where, p.verdict.upper(),
                                  "" if p.verdict == "correct" else p.detail) for p in pubs]),
                      ""]
        chart = charts.get(name)
        if chart is None or chart.error:
            lines += [f"No chart: {chart.error if chart else 'not drawn'}", ""]
        else:
            lines += [f"![{name}: simulated motion and reactions]({name}_reactions.png)", ""]
            lines += [f"- {n}" for n in chart.notes] + [""]
    return "\n".join(lines)


_CSS = """
body { font-family: Georgia, serif; max-width: 60em; margin: 2em auto; padding: 0 1em;
       line-height: 1.45; color: #222; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; vertical-align: top; text-align: left; }
th { background: #eee; }
td.yes, td.correct { color: #176317; } td.NO, td.wrong { color: #a31515; font-weight: bold; }
h2 { border-bottom: 1px solid #ccc; margin-top: 2.2em; }
math { font-size: 1.05em; margin: 0.4em 0; overflow-x: auto; }
img { max-width: 100%; }
.note { color: #555; font-size: 0.92em; }
code, pre { font-size: 0.88em; }
"""


def _cell(value, cls: str = "") -> str:
    attr = f' class="{html.escape(cls)}"' if cls else ""
    return f"<td{attr}>{html.escape(str(value))}</td>"


def _table(headers, rows, classes=None) -> str:
    out = ["<table><tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in headers) + "</tr>"]
    for i, r in enumerate(rows):
        cls = classes[i] if classes else [""] * len(r)
        out.append("<tr>" + "".join(_cell(v, k) for v, k in zip(r, cls)) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def _equations_html(c) -> list[str]:
    p = c.problem
    out = []
    try:
        ref = p.model(p.reference)
    except Exception as exc:  # noqa: BLE001
        return [f"<p class='note'>no equations: {html.escape(str(exc))}</p>"]
    out.append(f"<h3>Equations of motion ({html.escape(ref.name)})</h3>")
    for label, e in zip(ref.labels, ref.equations):
        out.append(f"<p class='note'>{html.escape(label)}</p>{mathml.equation(e, 0)}")
    reactions = _reactions(c)
    if reactions:
        directions = {r.name: r.direction for r in p.reactions}
        out.append("<h3>Reactions, from the direct form</h3>")
        for name, expr in reactions.items():
            note = directions.get(str(name), "")
            out.append((f"<p class='note'>{html.escape(note)}</p>" if note else "")
                       + mathml.equation(sp.Symbol(str(name)), expr))
    for note in getattr(c, "display_notes", []) or []:
        out.append(f"<p class='note'>{html.escape(note)}</p>")
    return out


def _chart_html(name: str, chart, out_dir: Path) -> list[str]:
    if chart is None or chart.error:
        why = chart.error if chart else "not drawn"
        return [f"<p class='note'>No chart: {html.escape(why)}</p>"]
    png = Path(out_dir) / f"{name}_reactions.png"
    data = base64.b64encode(png.read_bytes()).decode("ascii")
    out = [f'<img alt="{html.escape(name)}: simulated motion and reactions" '
           f'src="data:image/png;base64,{data}">']
    out += [f"<p class='note'>{html.escape(n)}</p>" for n in chart.notes]
    return out


def html_page(comparisons, charts: dict, out_dir: Path, duration: float) -> str:
    ok = sum(1 for c in comparisons if c.equivalent)
    rows = summary_rows(comparisons)
    classes = [["", "", r[2], "", "", "", ""] for r in rows]
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             "<title>dualmech report</title>", f"<style>{_CSS}</style></head><body>",
             "<h1>dualmech report</h1>",
             f"<p>{ok} of {len(comparisons)} problems: every model agrees with the reference "
             f"model. Each problem was written twice (Newton&ndash;Euler and Lagrange); the "
             f"charts show up to {duration:g} s of simulated motion, cut where the scene "
             "ends.</p>", _table(SUMMARY_HEADERS, rows, classes)]
    for c in comparisons:
        name = c.problem.name
        parts.append(f'<h2 id="{html.escape(name)}">{html.escape(name)}: '
                     f"{html.escape(c.problem.title)}</h2>")
        parts.append(f"<p class='note'>source: {html.escape(c.problem.source)}</p>")
        parts.append(f"<p><b>Verdict:</b> {html.escape(_verdict(c))}</p>")
        parts += _equations_html(c)
        pubs = _published(c)
        if pubs:
            parts.append("<h3>Printed answers</h3>")
            parts.append(_table(("answer", "where", "verdict", "why"),
                                [(p.label, p.where, p.verdict.upper(),
                                  "" if p.verdict == "correct" else p.detail) for p in pubs],
                                [["", "", p.verdict, ""] for p in pubs]))
        parts.append("<h3>Simulated motion</h3>")
        parts += _chart_html(name, charts.get(name), out_dir)
        parts.append(f"<details><summary>full report</summary><pre>{html.escape(str(c))}"
                     "</pre></details>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
