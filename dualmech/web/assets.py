"""The page's stylesheet and script, served as files so the pages carry no inline code (the
Content-Security-Policy allows scripts and styles from the server itself only).

The script builds every piece of client-side text with ``textContent``; the only markup it
inserts is what the server rendered (typeset MathML and escaped feedback).

Example
-------
>>> "textContent" in SCRIPT and "innerHTML = data.mathml" in SCRIPT
True
"""
from __future__ import annotations

__all__ = ["STYLE", "SCRIPT"]

STYLE = """
:root { --ink: #1d2430; --muted: #5b6573; --line: #d9dee5; --bg: #f6f7f9; --card: #fff;
        --accent: #2456a6; --ok: #1d7a46; --bad: #b3261e; --warn: #8a5a00; }
* { box-sizing: border-box; }
body { margin: 0; font: 16px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif;
       color: var(--ink); background: var(--bg); }
header.top { background: var(--ink); color: #fff; padding: .6rem 1.5rem; display: flex;
             gap: 1.5rem; align-items: baseline; }
header.top a { color: #fff; text-decoration: none; }
header.top .brand { font-weight: 700; letter-spacing: .02em; }
main { max-width: 70rem; margin: 1.5rem auto; padding: 0 1.5rem; }
h1 { font-size: 1.6rem; margin: .2rem 0; }
h2 { font-size: 1.15rem; margin: 0 0 .6rem; }
h2.next { margin-top: 1.1rem; }
.card.narrow { max-width: 30rem; }
.source, .muted { color: var(--muted); font-size: .9rem; }
.grid { display: grid; grid-template-columns: minmax(0, 1fr) minmax(0, 1.15fr); gap: 1.2rem;
        align-items: start; }
@media (max-width: 900px) { .grid { grid-template-columns: 1fr; } }
.card { background: var(--card); border: 1px solid var(--line); border-radius: 8px;
        padding: 1rem 1.2rem; margin-bottom: 1.2rem; }
pre.sketch { font: 12px/1.25 ui-monospace, "DejaVu Sans Mono", monospace; overflow-x: auto;
             background: #fbfcfd; border: 1px solid var(--line); border-radius: 6px;
             padding: .7rem; margin: 0; }
table { border-collapse: collapse; width: 100%; font-size: .92rem; }
th, td { text-align: left; padding: .3rem .5rem; border-bottom: 1px solid var(--line);
         vertical-align: top; }
th { color: var(--muted); font-weight: 600; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
code { font: .9em ui-monospace, "DejaVu Sans Mono", monospace; background: #eef1f5;
       padding: 0 .25em; border-radius: 3px; }
label { font-weight: 600; display: block; margin: .4rem 0 .2rem; }
select, textarea, input[type=text], input[type=password] {
  width: 100%; font: 15px/1.4 ui-monospace, "DejaVu Sans Mono", monospace; padding: .5rem;
  border: 1px solid #b8c0cc; border-radius: 6px; background: #fff; }
textarea { min-height: 6.5rem; resize: vertical; }
button { font: inherit; font-weight: 600; background: var(--accent); color: #fff; border: 0;
         border-radius: 6px; padding: .5rem 1.1rem; cursor: pointer; margin-top: .6rem; }
button:disabled { opacity: .6; cursor: wait; }
.preview { min-height: 3rem; border: 1px dashed var(--line); border-radius: 6px;
           padding: .4rem .8rem; margin-top: .6rem; background: #fbfcfd; }
.preview .label { color: var(--muted); font-size: .85rem; }
.preview math { font-size: 1.2rem; }
.error { color: var(--bad); }
.warn { color: var(--warn); }
.unknown-names span.name { color: var(--bad); font-weight: 600; }
.feedback { margin-top: 1rem; border-radius: 8px; padding: .8rem 1rem; border: 1px solid; }
.feedback.right { border-color: #9fd3b4; background: #eef8f2; }
.feedback.wrong { border-color: #e6a8a3; background: #fcf1f0; }
.feedback.invalid { border-color: #e3c98f; background: #fdf7ea; }
.verdict { font-weight: 700; font-size: 1.05rem; }
.right .verdict { color: var(--ok); } .wrong .verdict { color: var(--bad); }
.invalid .verdict { color: var(--warn); }
.feedback ul { margin: .4rem 0; padding-left: 1.2rem; }
.feedback math { font-size: 1.1rem; }
.names { font-size: .9rem; }
.names dt { font-weight: 600; margin-top: .3rem; }
.names dd { margin: 0 0 0 1rem; }
.problems { list-style: none; padding: 0; }
.problems li { padding: .5rem 0; border-bottom: 1px solid var(--line); }
.problems a { font-weight: 600; color: var(--accent); text-decoration: none; }
progress { width: 100%; height: 1.1rem; }
.pill { display: inline-block; padding: 0 .5rem; border-radius: 999px; font-size: .85rem;
        font-weight: 600; }
.pill.right { background: #e3f4ea; color: var(--ok); }
.pill.wrong { background: #fbe6e4; color: var(--bad); }
.pill.invalid { background: #fbf0d9; color: var(--warn); }
.downloads a { margin-right: 1rem; }
"""

SCRIPT = r"""
"use strict";
(function () {
  function el(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
  }
  async function post(url, body) {
    const r = await fetch(url, {method: "POST", headers: {"Content-Type": "application/json"},
                                body: JSON.stringify(body), credentials: "same-origin"});
    let data = null;
    try { data = await r.json(); } catch (e) { data = {error: "the server sent no answer"}; }
    return {status: r.status, data: data};
  }

  // -- the problem page ---------------------------------------------------------------------
  const form = document.getElementById("answer-form");
  if (form) {
    const problem = form.dataset.problem;
    const box = document.getElementById("answer");
    const quantity = document.getElementById("quantity");
    const preview = document.getElementById("preview");
    const feedback = document.getElementById("feedback");
    const submit = document.getElementById("submit");
    let timer = null, seq = 0;

    async function validate() {
      const text = box.value;
      const mine = ++seq;
      if (!text.trim()) {
        preview.dataset.state = "empty";
        preview.replaceChildren(el("span", "label", "your answer reads as: (nothing yet)"));
        return;
      }
      const {status, data} = await post("/api/validate", {problem: problem, answer: text,
                                                          quantity: quantity.value});
      if (mine !== seq) return;                     // a newer keystroke won
      const out = [el("div", "label", "your answer reads as:")];
      if (status !== 200 || data.error) {
        out.push(el("div", "error", data.error || ("error " + status)));
      }
      if (data.mathml) {
        const m = el("div", "math");
        m.innerHTML = data.mathml;                 // MathML typeset by the server, escaped
        out.push(m);
      }
      if (data.unknown && data.unknown.length) {
        const p = el("div", "unknown-names error");
        p.append("unknown names: ");
        data.unknown.forEach(function (u, i) {
          if (i) p.append(", ");
          p.append(el("span", "name", u.name));
          if (u.suggestions.length) p.append(" (did you mean " + u.suggestions.join(", ") + "?)");
        });
        p.append(" -- the accepted names are listed beside the answer box.");
        out.push(p);
      }
      (data.dimensions_html || []).forEach(function (d) {   // escaped by the server, MathML
        const w = el("div", "warn", "dimensions: ");
        w.insertAdjacentHTML("beforeend", d);
        out.push(w);
      });
      preview.replaceChildren.apply(preview, out);
      preview.dataset.state = (status === 200 && data.ok) ? "ok" : "error";
    }
    box.addEventListener("input", function () {
      clearTimeout(timer); timer = setTimeout(validate, 200);
    });
    quantity.addEventListener("change", validate);
    form.addEventListener("submit", async function (ev) {
      ev.preventDefault();
      submit.disabled = true;
      feedback.replaceChildren(el("p", "muted", "grading..."));
      try {
        const {status, data} = await post("/api/grade", {problem: problem, answer: box.value,
                                                         quantity: quantity.value});
        if (status === 200 && data.feedback_html) {
          const d = el("div");
          d.innerHTML = data.feedback_html;        // rendered and escaped by the server
          feedback.replaceChildren(d);
        } else {
          feedback.replaceChildren(el("div", "feedback invalid", data.error || ("error " + status)));
        }
      } finally { submit.disabled = false; }
    });
    validate();
  }

  // -- the teacher page ---------------------------------------------------------------------
  const upload = document.getElementById("upload-form");
  if (upload) {
    upload.addEventListener("submit", async function (ev) {
      ev.preventDefault();
      const file = document.getElementById("csv").files[0];
      const msg = document.getElementById("upload-message");
      if (!file) { msg.textContent = "choose a CSV file first"; return; }
      msg.textContent = "uploading...";
      const r = await fetch("/api/batches", {method: "POST", body: file, credentials: "same-origin",
                                             headers: {"Content-Type": "text/csv",
                                                       "X-Filename": encodeURIComponent(file.name)}});
      let data = {};
      try { data = await r.json(); } catch (e) { data = {error: "the server sent no answer"}; }
      if (r.status === 201) { window.location = "/teacher/batches/" + data.id; }
      else { msg.textContent = data.error || ("error " + r.status); msg.className = "error"; }
    });
  }
  const bar = document.getElementById("batch-progress");
  if (bar) {
    const id = bar.dataset.batch;
    const label = document.getElementById("batch-count");
    async function poll() {
      const r = await fetch("/api/batches/" + id, {credentials: "same-origin"});
      if (r.status !== 200) { setTimeout(poll, 2000); return; }
      const p = await r.json();
      bar.max = p.total; bar.value = p.done;
      label.textContent = p.done + " of " + p.total + " graded";
      if (p.status === "done") { window.location.reload(); } else { setTimeout(poll, 500); }
    }
    poll();
  }
})();
"""
