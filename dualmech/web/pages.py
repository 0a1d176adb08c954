"""The HTML of the pages: every piece of text from a student, a CSV or a problem is escaped.

Pages are plain HTML5 with MathML (browsers render it with no script), one stylesheet and one
script served by the app (:mod:`.assets`).  Feedback terms are the grader's own MathML
(``term_html``/``correct_html`` of each edit), or typeset with :func:`.preview.term_mathml`
when a grade has none, in the student's own notation.

Example
-------
>>> html = feedback_html(None, {"status": "invalid", "summary": "<b>x</b>", "edits": []})
>>> "&lt;b&gt;x&lt;/b&gt;" in html and "<b>" not in html
True
"""
from __future__ import annotations

from collections import Counter, defaultdict
from html import escape

from dualmech.grade.report import summarise
from dualmech.report.mathml import text_html
from dualmech.sources import source_name

__all__ = ["layout", "index_page", "problem_page", "feedback_html", "login_page",
           "teacher_page", "batch_page", "api_page", "student_page"]

_VERDICT = {"right": "Right", "wrong": "Not right yet", "invalid": "Not graded"}


def layout(title: str, body: str) -> str:
    """A whole page around ``body`` (already HTML)."""
    return f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{escape(title)} - dualmech</title>
<link rel="stylesheet" href="/static/style.css"></head>
<body><header class="top"><a class="brand" href="/">dualmech</a><a href="/">problems</a>
<a href="/teacher">teacher</a><a href="/api/docs">API</a></header>
<main>{body}</main>
<script src="/static/app.js"></script></body></html>"""


def index_page(infos: list) -> str:
    """The list of served problems (``infos``: dicts with name, title, source, summary)."""
    items = "".join(
        f'<li><a href="/problems/{escape(i["name"])}">{escape(i["title"])}</a> '
        f'<span class="muted">{escape(i["name"])}</span><br>'
        f'<span class="muted">{escape(i["summary"])}</span></li>' for i in infos)
    return layout("Problems", f"""<h1>Problems</h1>
<p class="muted">Pick a problem, type an answer, see how it reads while you type, and get
feedback when you submit.</p><div class="card"><ul class="problems">{items}</ul></div>""")


def problem_page(info) -> str:
    """A problem: title, source, sketch, names with units, the quantities, the answer box."""
    coords = "".join(f"<tr><td><code>{escape(c['name'])}</code></td><td>{escape(c['unit'])}"
                     f"</td><td>{escape(c['description'])}</td></tr>"
                     for c in info.coordinates)
    params = "".join(f"<tr><td><code>{escape(p['name'])}</code></td><td>{escape(p['unit'])}"
                     f"</td><td>{escape(p['description'])}</td></tr>" for p in info.parameters)
    reactions = "".join(f"<tr><td><code>{escape(r['name'])}</code></td><td>"
                        f"{escape(r['unit'])}</td><td>{escape(r['direction'])}</td></tr>"
                        for r in info.reactions)
    options = "".join(f'<option value="{escape(k)}">{escape(k)} &#8212; {escape(v)}</option>'
                      for k, v in info.quantities.items())
    names = "".join(
        f"<dt>{escape(kind)}</dt><dd>" + ", ".join(
            f"<code>{escape(n['name'])}</code>" + (
                f" <span class='muted'>({escape(', '.join(n['aliases']))})</span>"
                if n["aliases"] else "") for n in entries) + "</dd>"
        for kind, entries in info.accepted.items())
    first = info.coordinates[0]["name"] if info.coordinates else "q"
    sketch = (f'<pre class="sketch" role="img" aria-label="sketch of the system">'
              f"{escape(info.sketch)}</pre>" if info.sketch else
              '<p class="muted">This problem has no sketch.</p>')
    table = ("<table><tr><th>name</th><th>unit</th><th>meaning</th></tr>{}</table>")
    body = f"""<h1>{escape(info.title)}</h1>
<p class="source">Source: {escape(source_name(info.source))}</p><p>{escape(info.summary)}</p>
<div class="card"><h2>The system</h2>{sketch}</div>
<div class="grid"><section>
<div class="card"><h2>Coordinates</h2>{table.format(coords)}
<h2 class="next">Parameters</h2>{table.format(params)}
{('<h2 class="next">Reactions</h2>' + table.format(reactions)) if reactions else ''}
</div>
<div class="card names"><h2>Names you may use</h2><dl>{names}</dl>
<p class="muted">Derivatives: <code>{escape(first)}'</code>, <code>{escape(first)}''</code>
(or <code>{escape(first)}dot</code>, <code>{escape(first)}ddot</code>). Functions: sin cos tan
sqrt exp log. Powers with <code>^</code>.</p></div></section><section>
<div class="card"><h2>Your answer</h2>
<form id="answer-form" data-problem="{escape(info.name)}" autocomplete="off">
<label for="quantity">What you are answering</label>
<select id="quantity" name="quantity"><option value="">automatic &#8212; the equations
of motion, or one equation</option>{options}</select>
<label for="answer">Answer</label>
<textarea id="answer" name="answer" maxlength="4000" spellcheck="false"
 placeholder="e.g. {escape(first)}'' + ... = 0 (one equation per line)"></textarea>
<div id="preview" class="preview" aria-live="polite"></div>
<button id="submit" type="submit">Check my answer</button></form>
<div id="feedback" aria-live="polite"></div></div>

</section></div>"""
    return layout(info.title, body)


def _term(info, text: str, typeset: str | None) -> str:
    if typeset:   # the grader's MathML, set inline in the sentence
        return typeset.replace('display="block"', 'display="inline"', 1)
    if info is None:
        return f"<code>{escape(text)}</code>"
    from dualmech.web.preview import term_mathml
    return term_mathml(info, text)


def _edit(info, e: dict) -> str:
    part = "component" if "component" in e else "equation"
    where = f"{part} {e[part] + 1}: " if isinstance(e.get(part), int) else ""
    if e.get("where"):
        where = f"{e['where']}: "
    cat = f" ({escape(e['category'])})" if e.get("category") else ""
    # the grader's own MathML of the term when it gives one, else typeset here
    term = lambda key: _term(info, e.get(key, ""), e.get(f"{key}_html"))  # noqa: E731
    kind = e.get("kind")
    if kind == "missing":
        text = f"the term {term('correct')} is missing{cat}"
    elif kind == "extra":
        text = f"the term {term('term')} does not belong{cat}"
    elif kind == "sign":
        text = f"the term {term('term')} has the wrong sign: it is {term('correct')}{cat}"
    elif kind in ("coefficient", "replace"):
        text = f"{term('term')} where {term('correct')} belongs{cat}"
    elif kind == "swap":
        text = (f"{escape(e.get('detail', ''))} are swapped in {term('term')}: it is "
                f"{term('correct')}{cat}")
    else:
        return f"<li>{escape(e.get('sentence', ''))}</li>"
    return f"<li>{escape(where)}{text}</li>"


def feedback_html(info, g: dict) -> str:
    """The verdict on one answer (the grade's JSON) as HTML; terms typeset when ``info``
    (the problem's :class:`~.catalog.ProblemInfo`) is given."""
    status = g.get("status", "invalid")
    out = [f'<div class="feedback {escape(status)}"><div class="verdict">'
           f"{escape(_VERDICT.get(status, status))}</div><p>{escape(g.get('summary', ''))}</p>"]
    if g.get("dimension_issues"):
        out.append("<ul>" + "".join(f'<li class="warn">dimensions: {text_html(str(d))}</li>'
                                    for d in g["dimension_issues"]) + "</ul>")
    if g.get("edits"):
        out.append("<p>The smallest edit that makes it right:</p><ul>"
                   + "".join(_edit(info, e) for e in g["edits"]) + "</ul>")
    if g.get("details"):
        out.append("<ul>" + "".join(f"<li>{escape(str(d))}</li>" for d in g["details"])
                   + "</ul>")
    if g.get("state"):
        shown = ", ".join(f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}"
                          for k, v in g["state"].items())
        out.append(f'<p class="muted">at {escape(shown)}</p>')
    if status != "invalid" and g.get("method"):
        out.append(f'<p class="muted">decided by the {escape(str(g["method"]))}</p>')
    out.append("</div>")
    return "".join(out)


def login_page(error: str = "") -> str:
    """The teacher's token form."""
    msg = f'<p class="error">{escape(error)}</p>' if error else ""
    return layout("Teacher", f"""<h1>Teacher</h1><div class="card narrow">
<p>Enter the token the server printed when it started.</p>{msg}
<form method="post" action="/teacher/login"><label for="token">Token</label>
<input id="token" name="token" type="password" autocomplete="off">
<button type="submit">Open</button></form></div>""")


def teacher_page(batches: list[dict], answers: list[dict],
                 assignments: list[dict] = ()) -> str:
    """Upload form, the batches so far, the assignments, and the answers typed on the page by
    question; a logout button."""
    rows = "".join(
        f'<tr><td><a href="/teacher/batches/{escape(b["id"])}">{escape(b["name"])}</a></td>'
        f'<td class="num">{b["done"]} / {b["total"]}</td><td>{escape(b["status"])}</td></tr>'
        for b in batches)
    listing = (f"<table><tr><th>file</th><th>graded</th><th>status</th></tr>{rows}</table>"
               if batches else '<p class="muted">No batch yet.</p>')
    typed = _by_question(answers, with_students=False) if answers else \
        '<p class="muted">No answer typed on the page yet.</p>'
    made = "".join(
        f'<tr><td>{escape(str(a.get("title", "")))}</td><td class="num">{a["students"]}</td>'
        f'<td><a href="/api/assignments/{escape(a["id"])}/grades.csv">grades.csv</a> '
        f'<a href="/api/assignments/{escape(a["id"])}/stats">statistics</a></td></tr>'
        for a in assignments)
    made = (f"<table><tr><th>assignment</th><th>students</th><th></th></tr>{made}</table>"
            if assignments else '<p class="muted">No assignment yet (POST /api/assignments, '
                                'see <a href="/api/docs">the API</a>).</p>')
    return layout("Teacher", f"""<h1>Teacher</h1>
<form method="post" action="/teacher/logout" class="logout"><button type="submit"
 id="logout">Log out</button></form>
<div class="card"><h2>Assignments</h2>{made}</div>
<div class="card"><h2>Grade a class</h2>
<p class="muted">A CSV with the columns <code>id</code>, <code>question</code>,
<code>answer</code> (optional: <code>quantity</code>, <code>about</code>); a question is a
problem name or <code>name:quantity</code>.</p>
<form id="upload-form"><input id="csv" type="file" accept=".csv,text/csv">
<button type="submit">Upload and grade</button></form><p id="upload-message"></p></div>
<div class="card"><h2>Batches</h2>{listing}</div>
<div class="card"><h2>Answers typed on the page</h2>{typed}</div>""")


def _by_question(results: list[dict], with_students: bool = True) -> str:
    out = []
    for q, s in summarise(results).items():
        out.append(f"<h3>{escape(str(q))}</h3><p>{s['right']} of {s['answers']} right, "
                   f"{s['wrong']} wrong, {s['invalid']} not graded.</p>")
        if s["mistakes"]:
            head = "<th>students</th>" if with_students else ""
            out.append(f"<table><tr><th>most common mistakes</th><th>answers</th>{head}</tr>")
            for m, n, who in s["mistakes"][:10]:
                shown = ", ".join(who[:8]) + (" ..." if len(who) > 8 else "")
                cell = f"<td>{escape(shown)}</td>" if with_students else ""
                out.append(f'<tr><td>{escape(m)}</td><td class="num">{n}</td>{cell}</tr>')
            out.append("</table>")
    return "".join(out)


def batch_page(progress: dict, results: list[dict]) -> str:
    """One batch: a progress bar while it grades, then results by question and by student."""
    bid = escape(progress["id"])
    head = f"<h1>{escape(progress['name'])}</h1>"
    if progress["status"] != "done":
        return layout("Batch", head + f"""<div class="card"><h2>Grading</h2>
<progress id="batch-progress" data-batch="{bid}" max="{progress['total']}"
 value="{progress['done']}"></progress>
<p id="batch-count">{progress['done']} of {progress['total']} graded</p></div>""")
    counts = Counter(r.get("status") for r in results)
    by_student = defaultdict(list)
    for r in results:
        by_student[str(r.get("id", ""))].append(r)
    rows = []
    for sid in sorted(by_student):
        for r in by_student[sid]:
            status = r.get("status", "invalid")
            rows.append(f"<tr><td>{escape(sid)}</td><td>{escape(str(r.get('question', '')))}"
                        f"</td><td><code>{escape(str(r.get('answer', '')))}</code></td>"
                        f'<td><span class="pill {escape(status)}">{escape(status)}</span></td>'
                        f"<td>{escape(str(r.get('summary', '')))}"
                        + "".join(f"<br>&#8226; {escape(e.get('sentence', ''))}"
                                  for e in r.get("edits", [])) + "</td></tr>")
    return layout("Batch", head + f"""<p>{len(results)} answers: {counts.get('right', 0)}
right, {counts.get('wrong', 0)} wrong, {counts.get('invalid', 0)} not graded.</p>
<p class="downloads">Download: <a href="/api/batches/{bid}/results.json">results.json</a>
<a href="/api/batches/{bid}/report.md">report.md</a>
<a href="/api/batches/{bid}/results.csv">results.csv</a></p>
<div class="card"><h2>By question</h2>{_by_question(results)}</div>
<div class="card"><h2>By student</h2><table id="by-student"><tr><th>student</th>
<th>question</th><th>answer</th><th>verdict</th><th>feedback</th></tr>{''.join(rows)}
</table></div>""")


def api_page(spec: dict) -> str:
    """The OpenAPI description as a readable page (no third-party script)."""
    out = [f"<h1>{escape(spec['info']['title'])}</h1><p>{escape(spec['info']['description'])}"
           '</p><p>Machine-readable: <a href="/api/openapi.json">/api/openapi.json</a> '
           "(OpenAPI 3.1).</p>"]
    for path, ops in spec["paths"].items():
        for method, op in ops.items():
            out.append(f'<div class="card"><h2><code>{escape(method.upper())} '
                       f"{escape(path)}</code></h2><p>{escape(op.get('summary', ''))}</p>")
            if op.get("description"):
                out.append(f"<p class='muted'>{escape(op['description'])}</p>")
            body = op.get("requestBody", {}).get("content", {})
            for ctype, c in body.items():
                props = c.get("schema", {}).get("properties", {})
                fields = ", ".join(f"<code>{escape(k)}</code>" for k in props)
                out.append(f"<p>Body ({escape(ctype)}){': ' + fields if fields else ''}</p>")
            codes = ", ".join(f"{escape(k)} {escape(v.get('description', ''))}"
                              for k, v in op.get("responses", {}).items())
            out.append(f"<p class='muted'>Responses: {codes}</p></div>")
    return layout("API", "".join(out))


def student_page(aid: str) -> str:
    """A student's assignment page; its script (``/assignments/student.js``) reads the
    student's token from the link's fragment (never sent to the server in a URL) and fills
    the page from ``/api/assignments/{id}/me``."""
    return f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>Assignment - dualmech</title>
<link rel="stylesheet" href="/static/style.css"></head>
<body><header class="top"><a class="brand" href="/">dualmech</a></header>
<main id="assignment" data-assignment="{escape(aid)}"><h1 id="title">Assignment</h1>
<p id="status" class="muted">Loading...</p>
<div class="card"><h2>Your numbers</h2><table id="numbers"></table></div>
<div id="questions"></div>
<div class="card"><h2>Your score</h2><p id="score"></p></div></main>
<script src="/assignments/student.js"></script></body></html>"""
