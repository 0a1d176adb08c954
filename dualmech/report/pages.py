"""The report's two pages: ``report.md`` and a self-contained ``report.html``.

The HTML page needs nothing but a browser: equations are MathML (:mod:`.mathml`), charts are
embedded as PNG data, styling is a few lines of CSS, and there is no script.  Both pages hold
the summary table (verdict, method, time, reactions, printed answers per problem), then per
problem: the verdict line, the equations of motion of the reference model, the reactions
recovered from the direct form, every printed answer with its judgement, and the chart with
its notes (identical curves, zero reactions, why the simulation stops where it does) as its
one caption.  The summary links to each problem's section; sources are named by course
(:mod:`dualmech.sources`).

Two audiences: ``"teachers"`` see why each wrong printed answer is wrong (typeset) and the full
text report; ``"students"`` see which printed answers are right and which are wrong, with the
corrections left for them to find.

Every expression a person reads is in the textbook's notation (:mod:`dualmech.model.notation`), rates
as dots or primes (``notation``): typeset with MathML on the HTML page, one line of textbook
text (``m l θ̇^2``, no ``**``) in the Markdown.
"""
from __future__ import annotations

import base64
import html
from pathlib import Path

import sympy as sp

from dualmech.report import mathml
from dualmech.model.notation import check_notation
from dualmech.sources import source_name

__all__ = ["markdown_page", "html_page", "summary_rows", "SUMMARY_HEADERS", "AUDIENCES",
           "check_audience"]

#: who a page is for: teachers see the corrections, students only the verdicts
AUDIENCES = ("teachers", "students")


def check_audience(audience: str) -> str:
    """``audience`` if it is one of :data:`AUDIENCES`, else a ``ValueError`` naming them."""
    if audience not in AUDIENCES:
        raise ValueError(f"`audience` must be one of {', '.join(AUDIENCES)}; got "
                         f"{audience!r}.")
    return audience

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


def _why_text(p, notation: str) -> str:
    if p.verdict == "correct":
        return ""
    return p.text(notation) if callable(getattr(p, "text", None)) else p.detail


def _full_text(c, notation: str) -> str:
    """The comparison's text report in ``notation`` (a stand-in's ``str()`` otherwise)."""
    text = getattr(c, "text", None)
    return text(notation) if callable(text) else str(c)


def markdown_page(comparisons, charts: dict, duration: float,
                  audience: str = "teachers", notation: str = "dots") -> str:
    check_audience(audience)
    check_notation(notation)
    teachers = audience == "teachers"
    ok = sum(1 for c in comparisons if c.equivalent)
    rows = [(f"[{r[0]}](#{r[0]})",) + r[1:] for r in summary_rows(comparisons)]
    lines = ["# dualmech report" + ("" if teachers else " (for students)"), "",
             f"{ok} of {len(comparisons)} problems: every model agrees with the reference "
             f"model. Charts: up to {duration:g} s of simulated motion, cut where the scene "
             "ends." + ("" if teachers else _STUDENTS_NOTE), "",
             _md_table(SUMMARY_HEADERS, rows), ""]
    for c in comparisons:
        name = c.problem.name
        lines += [f"## {name}", "", f"*{c.problem.title}* -- {source_name(c.problem.source)}",
                  "", f"**Verdict:** {_verdict(c)}", ""]
        if teachers:
            lines += ["```", _full_text(c, notation), "```", ""]
        pubs = _published(c)
        if pubs:
            headers = ("answer", "where", "verdict") + (("why",) if teachers else ())
            lines += ["Printed answers:", "",
                      _md_table(headers, [(p.label, _where(p, teachers), p.verdict.upper())
                                          + ((_why_text(p, notation),) if teachers else ())
                                          for p in pubs]), ""]
        chart = charts.get(name)
        if chart is None or chart.error:
            lines += [f"No chart: {chart.error if chart else 'not drawn'}", ""]
        else:
            lines += [f"![{name}: simulated motion and reactions]({name}_reactions.png)", ""]
            lines += ["*" + _caption(chart) + "*", ""]
            lines += _animation_md(name, chart)
    return "\n".join(lines)


_STUDENTS_NOTE = (" Each printed answer of the source is marked right or wrong; finding what "
                  "is wrong in a wrong one is left to you.")


def _caption(chart) -> str:
    """The chart's notes as one caption (sentences)."""
    notes = [n + "." for n in chart.notes]
    if notes:
        notes[0] = notes[0][0].upper() + notes[0][1:]
    return " ".join(notes)


def _caption_html(chart) -> str:
    """The caption as HTML: the chart's typeset notes where it has them, else its text
    escaped."""
    typeset = list(getattr(chart, "notes_html", None) or [])
    if len(typeset) != len(chart.notes):
        return html.escape(_caption(chart))
    notes = [n + "." for n in typeset]
    if notes and notes[0][:1].islower():
        notes[0] = notes[0][0].upper() + notes[0][1:]
    return " ".join(notes)


def _where(p, teachers: bool) -> str:
    """Where the answer is printed; for students only the place (the source's own remark
    after the colon may give the correction away)."""
    return p.where if teachers else p.where.split(":")[0]


_CSS = """
body { font-family: Georgia, serif; max-width: 60em; margin: 2em auto; padding: 0 1em;
       line-height: 1.45; color: #222; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; vertical-align: top; text-align: left; }
th { background: #eee; }
td.yes, td.correct { color: #176317; } td.NO, td.wrong { color: #a31515; font-weight: bold; }
h2 { border-bottom: 1px solid #ccc; margin-top: 2.2em; }
math { font-size: 1.05em; }
math[display="block"] { margin: 0.4em 0; padding: 0.2em 0; overflow-x: auto;
                        overflow-y: hidden; }
img { max-width: 100%; }
.note { color: #555; font-size: 0.92em; }
figure { margin: 1em 0; } figcaption { color: #555; font-size: 0.92em; }
nav.toc a { text-decoration: none; }
code, pre { font-size: 0.88em; }
"""


def _cell(value, cls: str = "") -> str:
    attr = f' class="{html.escape(cls)}"' if cls else ""
    return f"<td{attr}>{html.escape(str(value))}</td>"


def _equations_html(c, notation: str) -> list[str]:
    p = c.problem
    out = []
    try:
        ref = p.model(p.reference)
    except Exception as exc:  # noqa: BLE001
        return [f"<p class='note'>no equations: {html.escape(str(exc))}</p>"]
    out.append(f"<h3>Equations of motion ({html.escape(ref.name)})</h3>")
    limits = getattr(c, "limits", None)
    for label, e in zip(ref.labels, ref.equations):
        out.append(f"<p class='note'>{html.escape(label)}</p>"
                   f"{mathml.equation(_shortest(e, limits), 0, notation)}")
    reactions = _reactions(c)
    if reactions:
        directions = {r.name: r.direction for r in p.reactions}
        out.append("<h3>Reactions, from the direct form</h3>")
        for name, expr in reactions.items():
            note = directions.get(str(name), "")
            out.append((f"<p class='note'>{html.escape(note)}</p>" if note else "")
                       + mathml.equation(sp.Symbol(str(name)), expr, notation))
    out += _values_html(c, notation)
    for note in getattr(c, "display_notes", []) or []:
        out.append(f"<p class='note'>{html.escape(note)}</p>")
    return out


def _values_html(c, notation: str) -> list[str]:
    """The reactions without a formula (past the display budget), as values at the problem's
    default state: the direct form's and, beside it, another derivation's; the state
    typeset in the page's notation."""
    p = c.problem
    formulas = getattr(c, "reactions", None)
    if not getattr(c, "equivalent", False) or formulas is None or \
            all(r.name in formulas for r in p.reactions):
        return []
    from dualmech.numeric.reactions_state import reactions_at_state
    try:
        v = reactions_at_state(p, None, comparison=c)
    except Exception as exc:  # noqa: BLE001 -- a singular state must not lose the page
        return [f"<p class='note'>reaction values at a state: {html.escape(str(exc))}</p>"]
    rows = []
    for name, value in v.direct.items():
        if name in v.referee:
            other = f"{v.referee[name][0]:.10g} ({html.escape(v.referee[name][1])}, Kane)"
        elif v.others.get(name):
            other = "; ".join(f"{x:.10g} ({html.escape(who)})" for x, who in v.others[name])
        else:
            other = "no other derivation gives it"
        rows.append(f"<tr><td>{html.escape(name)}</td><td>{value:.10g}</td>"
                    f"<td>{other}</td></tr>")
    return ["<h3>Reaction values at a state</h3>",
            f"<p class='note'>Too long to show as formulas; at t = {v.time:g} s, "
            f"{_state_html(p, v.state, notation)} (the default state of the problem; "
            "<code>dualmech show NAME --at</code> for another).</p>",
            "<table><tr><th>reaction</th><th>direct form</th><th>another derivation</th>"
            "</tr>" + "".join(rows) + "</table>"]


def _state_html(p, state: dict, notation: str) -> str:
    """``theta = 0.2, theta' = 0`` typeset: each name as the coordinate or its rate."""
    coords = {q.func.__name__: q for q in p.model(p.reference).coordinates}
    parts = []
    for key, value in state.items():
        base = key[:-4] if key.endswith("_dot") else key
        q = coords.get(base)
        if q is None:
            parts.append(html.escape(f"{key} = {value:.6g}"))
            continue
        lhs = q.diff(q.args[0]) if key.endswith("_dot") else q
        parts.append(mathml.equation(lhs, sp.Float(value, 6), notation, block=False))
    return ", ".join(parts)


def _shortest(expr, limits=None):
    """``expr`` or its tidied form (:func:`~dualmech.verify.display.tidy`, within the display
    budget), whichever is shorter: ``m q1''(2 sin^2 a + 2 cos^2 a)/2`` becomes ``m q1''``."""
    from dualmech.verify.display import OverBudget, tidy
    try:
        short = tidy(expr, limits)
    except OverBudget:
        return expr
    return short if sp.count_ops(short) < sp.count_ops(expr) else expr


def _why_html(p, notation: str) -> str:
    """Why a printed answer is wrong: its sentences, expressions typeset."""
    if p.verdict == "correct":
        return ""
    parts = getattr(p, "parts", None)
    if parts is None:
        return html.escape(p.detail)
    return "; ".join(mathml.sentence(s, notation) for s in parts)


def _chart_html(name: str, chart, out_dir: Path) -> list[str]:
    if chart is None or chart.error:
        why = chart.error if chart else "not drawn"
        return [f"<p class='note'>No chart: {html.escape(why)}</p>"]
    png = Path(out_dir) / f"{name}_reactions.png"
    data = base64.b64encode(png.read_bytes()).decode("ascii")
    return [f'<figure><img alt="{html.escape(name)}: simulated motion and reactions" '
            f'src="data:image/png;base64,{data}">'
            f"<figcaption>{_caption_html(chart)}</figcaption></figure>"]


_ANIMATION_NOTE = ("The motion, each reaction force an arrow at its point (one scale for all; "
                   "the legend gives each one's largest value).")


def _animation_md(name: str, chart) -> list[str]:
    if getattr(chart, "animation", None) is not None:
        return [f"![{name}: the motion, reaction forces as arrows]({name}_motion.gif)", "",
                f"*{_ANIMATION_NOTE}*", ""]
    why = getattr(chart, "animation_error", "")
    return [f"No animation: {why}", ""] if why else []


def _animation_html(name: str, chart) -> list[str]:
    path = getattr(chart, "animation", None)
    if path is None:
        why = getattr(chart, "animation_error", "")
        return [f"<p class='note'>No animation: {html.escape(why)}</p>"] if why else []
    data = base64.b64encode(Path(path).read_bytes()).decode("ascii")
    return [f'<figure><img alt="{html.escape(name)}: the motion, reaction forces as arrows" '
            f'src="data:image/gif;base64,{data}">'
            f"<figcaption>{html.escape(_ANIMATION_NOTE)}</figcaption></figure>"]


def _published_html(c, teachers: bool, notation: str) -> list[str]:
    pubs = _published(c)
    if not pubs:
        return []
    headers = ("answer", "where", "verdict") + (("why",) if teachers else ())
    out = ["<h3>Printed answers</h3>", "<table><tr>"
           + "".join(f"<th>{h}</th>" for h in headers) + "</tr>"]
    for p in pubs:
        cells = [_cell(p.label), _cell(_where(p, teachers)),
                 _cell(p.verdict.upper(), p.verdict)]
        if teachers:
            cells.append(f"<td>{_why_html(p, notation)}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</table>")
    return out


def html_page(comparisons, charts: dict, out_dir: Path, duration: float,
              audience: str = "teachers", notation: str = "dots") -> str:
    check_audience(audience)
    check_notation(notation)
    teachers = audience == "teachers"
    ok = sum(1 for c in comparisons if c.equivalent)
    rows = summary_rows(comparisons)
    head = "<table><tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in SUMMARY_HEADERS) \
        + "</tr>"
    table = [head]
    for r in rows:
        link = f'<td><a href="#{html.escape(r[0])}">{html.escape(r[0])}</a></td>'
        table.append("<tr>" + link + "".join(_cell(v, r[2] if i == 2 else "")
                                             for i, v in enumerate(r[1:], 1)) + "</tr>")
    table.append("</table>")
    title = "dualmech report" + ("" if teachers else " (for students)")
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             f"<title>{title}</title>", f"<style>{_CSS}</style></head><body>",
             f"<h1>{title}</h1>",
             f"<p>{ok} of {len(comparisons)} problems: every model agrees with the reference "
             f"model. Each problem was written twice (Newton&ndash;Euler and Lagrange); the "
             f"charts show up to {duration:g} s of simulated motion, cut where the scene "
             "ends." + ("" if teachers else html.escape(_STUDENTS_NOTE)) + "</p>",
             '<nav class="toc">', "\n".join(table), "</nav>"]
    for c in comparisons:
        name = c.problem.name
        parts.append(f'<h2 id="{html.escape(name)}">{html.escape(name)}: '
                     f"{html.escape(c.problem.title)}</h2>")
        parts.append(f"<p class='note'>source: {html.escape(source_name(c.problem.source))}"
                     "</p>")
        parts.append(f"<p><b>Verdict:</b> {html.escape(_verdict(c))}</p>")
        parts += _equations_html(c, notation)
        parts += _published_html(c, teachers, notation)
        parts.append("<h3>Simulated motion</h3>")
        parts += _chart_html(name, charts.get(name), out_dir)
        parts += _animation_html(name, charts.get(name))
        if teachers:
            parts.append(f"<details><summary>full text report</summary><pre>"
                         f"{html.escape(_full_text(c, notation))}</pre></details>")
        parts.append('<p class="note"><a href="#">back to the summary</a></p>')
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
