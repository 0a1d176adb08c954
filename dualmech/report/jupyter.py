"""Rich display in Jupyter: HTML with MathML for problems, comparisons, grades and charts.

The classes call these from their ``_repr_html_`` (an :class:`~dualmech.model.equations.EquationSet`
shows itself as LaTeX through ``_repr_latex_``).  Everything a reader might have typed --
labels, answers, sources -- is escaped; expressions are typeset with textbook dots
(:mod:`dualmech.model.notation`).  Nothing here decides anything: it only shows verdicts already
reached.

Example
-------
>>> from dualmech.problems import get
>>> "<math" in problem_html(get("simple_pendulum"))
True
"""
from __future__ import annotations

import base64
import html
from pathlib import Path

import sympy as sp

from dualmech.model import notation
from dualmech.sources import source_name

__all__ = ["problem_html", "comparison_html", "grade_html", "chart_html", "math_block",
           "math_inline"]

_STYLE = ("<style>.dm td,.dm th{padding:2px 8px;text-align:left;vertical-align:top}"
          ".dm .yes,.dm .right,.dm .correct{color:#176317}"
          ".dm .no,.dm .wrong{color:#a31515;font-weight:bold}.dm .note{color:#555}</style>")


def math_block(lhs, rhs=None) -> str:
    """``<math display="block">`` of ``lhs`` (``= rhs`` when given)."""
    body = notation.mathml(lhs) + ("" if rhs is None else "<mo>=</mo>" + notation.mathml(rhs))
    return ('<math xmlns="http://www.w3.org/1998/Math/MathML" display="block"><mrow>'
            f"{body}</mrow></math>")


def math_inline(expr) -> str:
    """``<math>`` of ``expr`` inside a sentence."""
    return ('<math xmlns="http://www.w3.org/1998/Math/MathML"><mrow>'
            f"{notation.mathml(expr)}</mrow></math>")


def _e(x) -> str:
    return html.escape(str(x))


def _unit(dimension) -> str:
    try:
        from dualmech.model.dimensions import format_dimension
        return format_dimension(dimension)
    except Exception:  # noqa: BLE001 - display only
        return str(dimension)


def problem_html(problem) -> str:
    """A problem's card: title, source by course, coordinates, parameters, reactions, models,
    and the reference model's equations."""
    p = problem
    rows = []
    for c in p.all_coordinates():
        rows.append(f"<tr><td>{math_inline(c.function)}</td><td>coordinate</td>"
                    f"<td>{_e(_unit(c.dimension))}</td><td>{_e(c.description)}</td></tr>")
    for par in p.parameters:
        rows.append(f"<tr><td>{math_inline(par.symbol)}</td><td>parameter = {par.default:g}"
                    f"</td><td>{_e(_unit(par.dimension))}</td><td>{_e(par.description)}"
                    "</td></tr>")
    for r in p.reactions:
        rows.append(f"<tr><td>{math_inline(sp.Symbol(r.name))}</td><td>reaction</td>"
                    f"<td>{_e(_unit(r.dimension))}</td><td>{_e(r.direction)}</td></tr>")
    out = [_STYLE, '<div class="dm">', f"<h4>{_e(p.name)}: {_e(p.title)}</h4>",
           f'<p class="note">{_e(source_name(p.source))}</p>',
           "<table><tr><th>symbol</th><th>role</th><th>dimension</th><th>meaning</th></tr>",
           *rows, "</table>",
           f"<p>models: {_e(', '.join(p.model_names))} (reference: {_e(p.reference)})</p>"]
    try:
        ref = p.model(p.reference)
        out.append(f"<p>equations of motion ({_e(ref.name)}):</p>")
        out += [math_block(e, 0) for e in ref.equations]
    except Exception as exc:  # noqa: BLE001 - a broken model is shown, not raised
        out.append(f'<p class="note">the reference model cannot be built: {_e(exc)}</p>')
    out.append("</div>")
    return "\n".join(out)


def comparison_html(c) -> str:
    """A comparison: verdict, each pair, the solved accelerations, reactions, printed answers
    with why the wrong ones are wrong."""
    pr = c.problem
    ok = c.equivalent
    out = [_STYLE, '<div class="dm">', f"<h4>{_e(pr.name)}: {_e(pr.title)}</h4>",
           f'<p class="note">{_e(source_name(pr.source))}</p>',
           f'<p><b class="{"yes" if ok else "no"}">{_e(c.verdict_line())}</b></p>',
           "<ul>" + "".join(f"<li>{_e(str(p).splitlines()[0])}</li>" for p in c.pairs)
           + "</ul>"]
    for m in c.mismatches:
        out.append(f'<p class="no">{_e(m)}</p>')
    if ok and c.accelerations:
        ref = pr.model(pr.reference)
        out.append("<p>accelerations:</p>")
        for q in ref.coordinates:
            if q.func.__name__ in c.accelerations:
                out.append(math_block(q.diff(ref.coordinates[0].args[0], 2),
                                      c.accelerations[q.func.__name__]))
    if ok and c.reactions:
        out.append("<p>reactions (from the direct form):</p>")
        dirs = c.reaction_directions
        for k, v in c.reactions.items():
            out.append(math_block(sp.Symbol(k), v)
                       + (f'<p class="note">{_e(dirs[k])}</p>' if dirs.get(k) else ""))
    for note in c.display_notes:
        out.append(f'<p class="note">{_e(note)}</p>')
    if c.published:
        out.append("<table><tr><th>printed answer</th><th>verdict</th><th>why</th></tr>")
        for v in c.published:
            why = "" if v.verdict == "correct" else "; ".join(
                "".join(_e(x) if isinstance(x, str) else math_inline(x) for x in s)
                for s in getattr(v, "parts", [(v.detail,)]))
            out.append(f"<tr><td>{_e(v.label)}</td><td class=\"{_e(v.verdict)}\">"
                       f"{_e(v.verdict.upper())}</td><td>{why}</td></tr>")
        out.append("</table>")
    out.append("</div>")
    return "\n".join(out)


def grade_html(g) -> str:
    """A graded answer: the verdict in colour, the summary, the smallest edit, the details."""
    head = {"right": "RIGHT", "wrong": "WRONG", "invalid": "NOT GRADED"}.get(g.status,
                                                                           g.status)
    cls = {"right": "right", "wrong": "wrong"}.get(g.status, "note")
    out = [_STYLE, '<div class="dm">',
           f'<p><b class="{cls}">{head}</b>: {_e(g.summary)}</p>',
           f'<p class="note">answer: <code>{_e(g.answer)}</code> ({_e(g.problem)}, '
           f"{_e(g.quantity)})</p>"]
    items = [f"dimensions: {i}" for i in g.dimension_issues]
    items += [e.sentence() for e in g.edits] + list(g.details)
    if items:
        out.append("<ul>" + "".join(f"<li>{_e(i)}</li>" for i in items) + "</ul>")
    if g.status != "invalid":
        out.append(f'<p class="note">decided by the {_e(g.method)}</p>')
    out.append("</div>")
    return "\n".join(out)


def chart_html(chart) -> str:
    """A chart: the picture (embedded PNG) and its one caption, or why it was not drawn."""
    if chart.error:
        return f'<p class="note">No chart: {_e(chart.error)}</p>'
    png = next((Path(p) for p in chart.paths if str(p).endswith(".png")), None)
    if png is None or not png.exists():
        return '<p class="note">No chart: the picture was not written</p>'
    data = base64.b64encode(png.read_bytes()).decode("ascii")
    notes = [n + "." for n in chart.notes]
    if notes:
        notes[0] = notes[0][0].upper() + notes[0][1:]
    return (f'<figure><img style="max-width:100%" src="data:image/png;base64,{data}">'
            f"<figcaption>{_e(' '.join(notes))}</figcaption></figure>")
