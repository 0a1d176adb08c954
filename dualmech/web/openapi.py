"""The JSON API described in OpenAPI 3.1 (served at ``/api/openapi.json`` and as a page at
``/api/docs``); a test checks that it lists exactly the API's routes.

Example
-------
>>> sorted(SPEC["paths"])[:3]
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


SPEC = {
    "openapi": "3.1.0",
    "info": {"title": "dualmech grading API", "version": "1",
             "description": "Problems, validation while typing, grading of one answer, and "
                            "batches of a class (teacher token). Answers are read by a "
                            "whitelisting parser and never evaluated; grading runs in a "
                            "bounded process pool. Requests are rate-limited per client (429 "
                            "with Retry-After) and bounded in size (413)."},
    "components": {"securitySchemes": {"token": {
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
        "/api/openapi.json": {"get": {"summary": "This description.",
                                      "responses": {"200": _json("OpenAPI 3.1")}}},
    },
}
