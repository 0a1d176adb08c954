"""The JSON API described in OpenAPI 3.1 (served at ``/api/openapi.json`` and as a page at
``/api/docs``); a test checks that it lists exactly the API's routes.

Example
-------
>>> [p for p in sorted(SPEC["paths"]) if p.startswith("/api/batches")][:3]
['/api/batches', '/api/batches/{id}', '/api/batches/{id}/report.md']
"""
from __future__ import annotations

__all__ = ["SPEC"]

_ERROR = {"description": "a clear error", "content": {"application/json": {"schema": {
    "type": "object", "properties": {"error": {"type": "string"}}}}}}
_ANSWER = {"type": "object", "required": ["problem", "answer"], "properties": {
    "problem": {"type": "string", "description": "a served problem's name"},
    "answer": {"type": "string", "maxLength": 4000},
    "quantity": {"type": ["string", "null"], "maxLength": 200,
                 "description": "what is asked (default: the equations of motion, or one "
                                "equation)"},
    "about": {"type": ["string", "null"], "maxLength": 200,
              "description": "the equilibrium of a `linearised` answer"}}}
_TOKEN = [{"token": []}]


def _json(description: str, schema: dict | None = None) -> dict:
    return {"description": description,
            "content": {"application/json": {"schema": schema or {"type": "object"}}}}


def _teacher(summary: str, ok: dict, description: str = "") -> dict:
    return {"get": {"summary": summary, "description": description, "security": _TOKEN,
                    "parameters": [{"name": "id", "in": "path", "required": True,
                                    "schema": {"type": "string"}}],
                    "responses": {"200": ok, "401": _ERROR, "404": _ERROR}}}


_STUDENT = [{"student": []}]
_ID = [{"name": "id", "in": "path", "required": True, "schema": {"type": "string"}}]
_RULES = {"type": "object", "required": ["title", "questions", "students"], "properties": {
    "title": {"type": "string", "maxLength": 200},
    "questions": {"type": "array", "minItems": 1, "maxItems": 50, "items": {
        "type": "object", "required": ["problem"], "properties": {
            "problem": {"type": "string", "description": "a served problem's name"},
            "quantity": {"type": ["string", "null"],
                         "description": "one of the problem's quantities (null: the "
                                        "equations of motion)"}}}},
    "students": {"type": "array", "minItems": 1, "maxItems": 2000,
                 "items": {"type": "string", "maxLength": 100}, "description": "unique ids"},
    "per_student_numbers": {"type": "boolean", "default": False,
                            "description": "each student gets parameter values of their own, "
                                           "drawn from the problems' declared ranges as short "
                                           "decimals; answers are graded exactly with them"},
    "feedback": {"enum": ["verdict", "locate", "hint", "full"], "default": "full"},
    "attempts": {"type": "integer", "minimum": 1, "maximum": 100, "default": 3},
    "penalty": {"type": "number", "minimum": 0, "maximum": 1, "default": 0,
                "description": "share of a question's score lost per attempt after the first"},
    "deadline": {"type": ["string", "null"], "format": "date-time",
                 "description": "ISO 8601 with its zone; answers after it are refused"}}}
_STATS = ("per question: students, answered, right, right_share, attempts, mistakes (the "
          "mistakes most often named, grouped: 'gravity sign', 'missing Coriolis term', ...); "
          "per student: attempts, scores, total")
_ASSIGNMENTS = {
    "/api/assignments": {
        "get": {"summary": "The assignments.", "security": _TOKEN,
                "responses": {"200": _json("assignments", {"type": "array"}),
                              "401": _ERROR}},
        "post": {"summary": "Make an assignment: questions, roster, per-student numbers, "
                            "feedback level, attempts, penalty, deadline.",
                 "description": "Answers {id, title, students: {id: {token, url}}}; each "
                                "student's token and link are shown this once.",
                 "security": _TOKEN,
                 "requestBody": {"required": True, "content": {"application/json": {
                     "schema": _RULES}}},
                 "responses": {"201": _json("id and each student's token and url"),
                               "400": _ERROR, "401": _ERROR, "404": _ERROR, "413": _ERROR,
                               "429": _ERROR}}},
    "/api/assignments/{id}/me": {"get": {
        "summary": "A student's view: numbers, questions, attempts left, score.",
        "security": _STUDENT, "parameters": _ID,
        "responses": {"200": _json("numbers {parameter: value}, units, questions, "
                                   "attempts_left (per question), score (0 to 1), deadline"),
                      "401": _ERROR, "403": _ERROR}}},
    "/api/assignments/{id}/answers": {"post": {
        "summary": "A student's answer to one question, graded at their numbers under the "
                   "assignment's rules.",
        "description": "Body {question: index from 0, answer: text}. Answers the grade at the "
                       "assignment's feedback level with attempt, attempts_left and "
                       "question_score; 403 after the deadline, 409 with no attempt left.",
        "security": _STUDENT, "parameters": _ID,
        "requestBody": {"required": True, "content": {"application/json": {"schema": {
            "type": "object", "required": ["question", "answer"], "properties": {
                "question": {"type": "integer", "minimum": 0},
                "answer": {"type": "string", "maxLength": 4000}}}}}},
        "responses": {"200": _json("the grade"), "400": _ERROR, "401": _ERROR, "403": _ERROR,
                      "409": _ERROR, "413": _ERROR, "429": _ERROR, "503": _ERROR}}},
    "/api/assignments/{id}/grades.csv": _teacher(
        "The gradebook: one row per student, one column per question (percent) and the "
        "total; Student, ID, SIS User ID, SIS Login ID, Section first, as Moodle's and "
        "Canvas's gradebook imports read.", {"description": "CSV",
                                             "content": {"text/csv": {}}}),
    "/api/assignments/{id}/stats": _teacher("Statistics of an assignment.", _json(_STATS)),
    "/api/assignments/{id}/regrade": {"post": {
        "summary": "Grade every attempt again (after a problem's fix and a restart).",
        "security": _TOKEN, "parameters": _ID,
        "responses": {"200": _json("regraded (how many) and changed (which, before, after)"),
                      "401": _ERROR, "404": _ERROR}}},
    "/api/students/{student}": {
        "get": {"summary": "Everything kept about one student (export).", "security": _TOKEN,
                "parameters": [{"name": "student", "in": "path", "required": True,
                                "schema": {"type": "string"}}],
                "responses": {"200": _json("assignments (numbers, attempts) and batch_rows"),
                              "401": _ERROR, "404": _ERROR}},
        "delete": {"summary": "Remove everything kept about one student.", "security": _TOKEN,
                   "parameters": [{"name": "student", "in": "path", "required": True,
                                   "schema": {"type": "string"}}],
                   "responses": {"200": _json("how many assignments and batch rows"),
                                 "401": _ERROR, "404": _ERROR}}},
}

SPEC = {
    "openapi": "3.1.0",
    "info": {"title": "dualmech grading API", "version": "1",
             "description": "Problems, validation while typing, grading of one answer, and "
                            "batches of a class (teacher token). Answers are read by a "
                            "whitelisting parser and never evaluated; grading runs in a "
                            "bounded process pool. Requests are rate-limited per client (429 "
                            "with Retry-After) and bounded in size (413)."},
    "components": {"securitySchemes": {"student": {
        "type": "http", "scheme": "bearer",
        "description": "a student's token (from their personal link)"}, "token": {
        "type": "http", "scheme": "bearer",
        "description": "the teacher token the server printed at start (or the cookie set by "
                       "the teacher page's login)"}}},
    "paths": {
        "/api/problems": {"get": {"summary": "The served problems.",
                                  "responses": {"200": _json(
                                      "name, title, source (named by course), source_file "
                                      "(the archive's file, or null), summary of each",
                                      {"type": "array"})}}},
        "/api/problems/{name}": {"get": {
            "summary": "One problem: coordinates and parameters with units, quantities, the "
                       "names an answer may use, its sketch.",
            "parameters": [{"name": "name", "in": "path", "required": True,
                            "schema": {"type": "string"}}],
            "responses": {"200": _json("the problem"), "404": _ERROR}}},
        "/api/validate": {"post": {
            "summary": "How an answer reads, before grading: MathML, unknown names with "
                       "suggestions, dimension warnings.",
            "requestBody": {"required": True, "content": {"application/json": {
                "schema": _ANSWER}}},
            "responses": {"200": _json("ok, error, mathml, unknown, dimensions, dimensions_html"),
                          "400": _ERROR, "404": _ERROR, "413": _ERROR, "429": _ERROR}}},
        "/api/grade": {"post": {
            "summary": "Grade one answer: verdict, the smallest edit, feedback_html.",
            "description": "The grade's JSON (status right/wrong/invalid, summary, edits, "
                           "dimension_issues, method, ...) plus feedback_html, the feedback "
                           "with its terms typeset.",
            "requestBody": {"required": True, "content": {"application/json": {
                "schema": _ANSWER}}},
            "responses": {"200": _json("the grade"), "400": _ERROR, "404": _ERROR,
                          "413": _ERROR, "429": _ERROR, "503": _ERROR}}},
        "/api/batches": {
            "get": {"summary": "The batches with their progress.", "security": _TOKEN,
                    "responses": {"200": _json("batches", {"type": "array"}),
                                  "401": _ERROR}},
            "post": {"summary": "Upload a class's CSV (id, question, answer[, quantity, "
                                "about]) and start grading it.",
                     "security": _TOKEN,
                     "requestBody": {"required": True, "content": {"text/csv": {
                         "schema": {"type": "string"}}}},
                     "responses": {"201": _json("id and total"), "400": _ERROR,
                                   "401": _ERROR, "413": _ERROR, "429": _ERROR}}},
        "/api/batches/{id}": _teacher("Progress of a batch.", _json("done, total, status")),
        "/api/batches/{id}/results.json": _teacher(
            "Every result and a summary per question.", _json("summary and results")),
        "/api/batches/{id}/report.md": _teacher(
            "The readable report (Markdown).", {"description": "Markdown",
                                                "content": {"text/markdown": {}}}),
        "/api/batches/{id}/results.csv": _teacher(
            "One row per answer: id, question, line, status, summary, feedback, answer.",
            {"description": "CSV", "content": {"text/csv": {}}}),
        **_ASSIGNMENTS,
        "/api/openapi.json": {"get": {"summary": "This description.",
                                      "responses": {"200": _json("OpenAPI 3.1")}}},
    },
}
