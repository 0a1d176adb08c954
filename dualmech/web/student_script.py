"""The script of a student's assignment page (served at ``/assignments/student.js``).

It reads the student's token from the link's fragment (``#token=...``: a fragment is never
sent to a server, so the token stays out of access logs and ``Referer`` headers), asks
``/api/assignments/{id}/me`` for the numbers, questions, attempts and score, and sends each
answer to ``/api/assignments/{id}/answers`` with ``Authorization: Bearer``.  Every piece of
text is set with ``textContent``: nothing from the server or the student is parsed as HTML.

Example
-------
>>> "textContent" in SCRIPT and "innerHTML" not in SCRIPT
True
"""
from __future__ import annotations

__all__ = ["SCRIPT"]

SCRIPT = r"""
(function () {
  "use strict";
  var main = document.getElementById("assignment");
  if (!main) { return; }
  var aid = main.getAttribute("data-assignment");
  var found = /(?:^|&)token=([^&]+)/.exec(location.hash.slice(1));
  var token = found ? decodeURIComponent(found[1]) : "";
  var statusLine = document.getElementById("status");
  var shown = {};
  var typed = {};

  function el(tag, text, cls) {
    var e = document.createElement(tag);
    if (text !== undefined && text !== null) { e.textContent = String(text); }
    if (cls) { e.className = cls; }
    return e;
  }

  function api(method, path, body) {
    var init = {method: method, cache: "no-store",
                headers: {"Authorization": "Bearer " + token}};
    if (body) {
      init.headers["Content-Type"] = "application/json";
      init.body = JSON.stringify(body);
    }
    return fetch("/api/assignments/" + encodeURIComponent(aid) + path, init)
      .then(function (r) {
        return r.json().then(function (j) { return {ok: r.ok, json: j}; }, function () {
          return {ok: false, json: {error: "HTTP " + r.status}};
        });
      });
  }

  function feedback(box, g) {
    box.textContent = "";
    var verdict = {right: "Right", wrong: "Not right yet", invalid: "Not graded"};
    var head = el("p");
    head.appendChild(el("span", verdict[g.status] || g.status, "pill " + g.status));
    head.appendChild(document.createTextNode(" " + (g.summary || "")));
    box.appendChild(head);
    var list = el("ul");
    (g.dimension_issues || []).forEach(function (d) { list.appendChild(el("li", d)); });
    (g.edits || []).forEach(function (e) { list.appendChild(el("li", e.sentence)); });
    if (list.childNodes.length) { box.appendChild(list); }
  }

  function question(q, me) {
    var card = el("div", null, "card question");
    card.id = "question-" + q.index;
    card.appendChild(el("h2", "Question " + (q.index + 1) + ": " + q.title));
    card.appendChild(el("p", "Give " + q.asked + ".", "muted"));
    card.appendChild(el("p", q.attempts_left + " of " + me.attempts + " attempts left; score " +
                        Math.round(q.score * 100) + "%", "attempts"));
    var area = el("textarea");
    area.id = "answer-" + q.index;
    area.setAttribute("aria-label", "answer to question " + (q.index + 1));
    area.value = typed[q.index] || "";
    var button = el("button", "Submit");
    button.id = "submit-" + q.index;
    button.type = "button";
    button.disabled = q.attempts_left <= 0 || me.closed;
    var box = el("div", null, "feedback");
    box.id = "feedback-" + q.index;
    if (shown[q.index]) { feedback(box, shown[q.index]); }
    else if (q.last) { feedback(box, q.last); }
    button.addEventListener("click", function () {
      button.disabled = true;
      typed[q.index] = area.value;
      box.textContent = "Grading...";
      api("POST", "/answers", {question: q.index, answer: area.value}).then(function (r) {
        if (!r.ok) { box.textContent = r.json.error; button.disabled = false; return; }
        shown[q.index] = r.json;
        load();
      });
    });
    card.appendChild(area);
    card.appendChild(button);
    card.appendChild(box);
    return card;
  }

  function render(me) {
    document.getElementById("title").textContent = me.title;
    statusLine.textContent = "Student " + me.student + (me.deadline ? "; deadline " +
      new Date(me.deadline).toLocaleString() : "") + (me.closed ? " (closed)" : "");
    var table = document.getElementById("numbers");
    table.textContent = "";
    var names = Object.keys(me.numbers);
    if (!names.length) {
      table.appendChild(el("tr")).appendChild(el("td", "Answer with the problem's symbols."));
    }
    names.forEach(function (n) {
      var row = el("tr");
      row.appendChild(el("td")).appendChild(el("code", n));
      row.appendChild(el("td", me.numbers[n], "num"));
      row.appendChild(el("td", me.units[n] || ""));
      table.appendChild(row);
    });
    var qs = document.getElementById("questions");
    qs.textContent = "";
    me.questions.forEach(function (q) { qs.appendChild(question(q, me)); });
    document.getElementById("score").textContent = Math.round(me.score * 100) + "%";
  }

  function load() {
    if (!token) {
      statusLine.textContent = "This link has no token: use the link your teacher sent.";
      return;
    }
    api("GET", "/me").then(function (r) {
      if (!r.ok) { statusLine.textContent = r.json.error; return; }
      render(r.json);
    });
  }
  load();
})();
"""
