"""Grading through the web layer, in the real bounded pool: one answer, a hostile answer beside
right ones, a class's batch with its downloads, and a batch resumed after a restart.

Expected verdicts are the grader's own on the simple pendulum (``M a^2 theta'' + M g a
sin(theta) = 0``, problems/simple_pendulum.py): a multiple of it is right, a flipped sign on the
gravity term is wrong with that term named."""
from __future__ import annotations

import csv
import io
import json
import time

import pytest

pytest.importorskip("starlette")
from starlette.testclient import TestClient  # noqa: E402

from dualmech.web import create_app  # noqa: E402
from dualmech.web.store import Store  # noqa: E402

TOKEN = "grading-token-for-tests"
AUTH = {"Authorization": f"Bearer {TOKEN}"}
RIGHT = "a*theta'' + g*sin(theta) = 0"
WRONG = "a*theta'' - g*sin(theta) = 0"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    app = create_app(["simple_pendulum"], data=tmp_path_factory.mktemp("web"), token=TOKEN,
                     workers=2)
    with TestClient(app) as c:
        yield c


def _wait(client, bid, seconds=120):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        p = client.get(f"/api/batches/{bid}", headers=AUTH).json()
        if p["status"] == "done":
            return p
        time.sleep(0.1)
    raise AssertionError(f"batch {bid} not done after {seconds} s: {p}")


def test_grade_right_and_wrong_with_typeset_feedback(client):
    r = client.post("/api/grade", json={"problem": "simple_pendulum", "answer": RIGHT})
    assert r.status_code == 200
    g = r.json()
    assert g["status"] == "right" and g["problem"] == "simple_pendulum"
    assert '<div class="feedback right">' in g["feedback_html"]

    g = client.post("/api/grade", json={"problem": "simple_pendulum", "answer": WRONG}).json()
    assert g["status"] == "wrong"
    assert [(e["kind"], e["term"], e["correct"]) for e in g["edits"]] == \
        [("sign", "-g*sin(theta)", "g*sin(theta)")]
    # the term and its correction typeset inline, as the student wrote them: minus g
    # sin(theta), theta as a Greek letter
    html = g["feedback_html"]
    assert html.count('<math xmlns="http://www.w3.org/1998/Math/MathML" display="inline">') == 2
    assert "<mo>-</mo><mi>g</mi>" in html and html.count("<mi>&#952;</mi>") == 2
    assert 'display="block"' not in html


def test_grade_a_named_quantity(client):
    # the string's tension, T = M (g cos(theta) + a theta'^2): problems/simple_pendulum.py
    g = client.post("/api/grade", json={"problem": "simple_pendulum", "quantity": "T",
                                        "answer": "M*(g*cos(theta) + a*theta'^2)"}).json()
    assert g["status"] == "right" and g["quantity"] == "T"


def test_hostile_answers_get_a_clear_verdict_and_never_an_internal_error(client):
    for answer in ("__import__('os')", "9^9^9^9", "(" * 50 + "theta" + ")" * 50):
        g = client.post("/api/grade", json={"problem": "simple_pendulum",
                                            "answer": answer}).json()
        assert g["status"] == "invalid"
        assert "internal error" not in g["summary"]


def test_answers_typed_on_the_page_are_kept_for_the_teacher(client):
    client.post("/api/grade", json={"problem": "simple_pendulum", "answer": WRONG})
    answers = client.app.state.server.store.answers()
    assert any(a["answer"] == WRONG and a["status"] == "wrong" for a in answers)


def test_a_batch_is_graded_in_the_background_with_its_downloads(client):
    body = ("id,question,answer\n"
            f"ada,simple_pendulum,{RIGHT}\n"
            f"bob,simple_pendulum,{WRONG}\n"
            "cy,simple_pendulum:T,M*(g*cos(theta) + a*theta'^2)\n"
            "dee,toy_car,x\n").encode()
    r = client.post("/api/batches", content=body, headers={**AUTH, "X-Filename": "class.csv"})
    assert r.status_code == 201 and r.json()["total"] == 4
    bid = r.json()["id"]
    assert client.get(f"/api/batches/{bid}/report.md", headers=AUTH).status_code in (200, 409)
    p = _wait(client, bid)
    assert (p["done"], p["total"]) == (4, 4)
    data = client.get(f"/api/batches/{bid}/results.json", headers=AUTH).json()
    assert [(r["id"], r["status"]) for r in data["results"]] == \
        [("ada", "right"), ("bob", "wrong"), ("cy", "right"), ("dee", "invalid")]
    assert data["results"][3]["summary"].startswith("no problem `toy_car` is served here")
    assert data["summary"]["simple_pendulum"]["right"] == 1
    md = client.get(f"/api/batches/{bid}/report.md", headers=AUTH).text
    assert md.startswith("# Grades: class.csv") and "has the wrong sign" in md
    rows = list(csv.DictReader(io.StringIO(
        client.get(f"/api/batches/{bid}/results.csv", headers=AUTH).text)))
    assert [r["status"] for r in rows] == ["right", "wrong", "right", "invalid"]
    assert rows[1]["feedback"].startswith("the term `-g*sin(theta)` has the wrong sign")


def test_an_interrupted_batch_resumes_on_restart(tmp_path):
    # a server stopped after grading row 0 of 3: the store holds that result, nothing else
    store = Store(tmp_path)
    bid = store.add_batch("class.csv", [
        {"id": "s1", "question": "simple_pendulum", "answer": RIGHT, "line": 2},
        {"id": "s2", "question": "simple_pendulum", "answer": WRONG, "line": 3},
        {"id": "s3", "question": "simple_pendulum", "answer": RIGHT, "line": 4}])
    kept = {"id": "s1", "question": "simple_pendulum", "status": "right",
            "summary": "graded before the restart", "line": 2}
    store.put_result(bid, 0, kept)
    store.close()
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, workers=1)
    with TestClient(app) as c:                       # the restart
        p = _wait(c, bid)
        results = c.get(f"/api/batches/{bid}/results.json", headers=AUTH).json()["results"]
    assert p["status"] == "done"
    assert results[0] == kept                        # not graded twice
    assert [(r["id"], r["status"]) for r in results[1:]] == [("s2", "wrong"), ("s3", "right")]
    reopened = Store(tmp_path)
    assert reopened.unfinished() == [] and len(reopened.results(bid)) == 3
    assert json.loads(json.dumps(reopened.results(bid)[0])) == kept


@pytest.mark.slow
def test_one_hostile_answer_does_not_stall_the_others(tmp_path):
    # parser limits loosened so that `theta^3000000` reaches the grader: its exact value at a
    # sampled point has ~180 million bits (tests/test_grade_sandbox.py), far past the 1 s
    # ceiling; the pool must refuse it alone and grade the others
    from concurrent.futures import ThreadPoolExecutor

    from dualmech.grade.parser import Limits
    from dualmech.grade.sandbox import GradingPool
    pool = GradingPool(2, seconds=1.0, limits=Limits(exponent=10 ** 9, degree=10 ** 12))
    try:
        app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=pool)
        with TestClient(app) as c:
            def post(answer):
                return c.post("/api/grade", json={"problem": "simple_pendulum",
                                                  "answer": answer}).json()
            with ThreadPoolExecutor(4) as ex:
                got = list(ex.map(post, ["theta''*theta^3000000 = 0", RIGHT, WRONG, RIGHT]))
    finally:
        pool.close()
    assert got[0]["status"] == "invalid"
    assert got[0]["summary"].startswith("too costly to grade: `theta^3000000`")
    assert [g["status"] for g in got[1:]] == ["right", "wrong", "right"]


@pytest.mark.parametrize("body, said", [
    ("[" * 30000 + "]" * 30000, "nested too deeply"),
    ('{"problem": "simple_pendulum", "answer": "' + "[" * 3000 + "]" * 3000 + '"}', None),
    ('{"problem": "simple_pendulum", "answer": "\\ud800"}', "`answer` holds a lone surrogate"),
    ('{"problem": "simple_pendulum", "answer": "x", "\\udfff": 1}', "lone surrogate"),
    ('{"problem": "simple_pendulum", "answer": "x", "q": [{"a": "\\udbff"}]}', "`q` holds"),
])
def test_malformed_json_gets_400_never_500(client, body, said):
    """A body nested 30,000 deep and a lone surrogate escape were internal errors (500)."""
    import time
    start = time.perf_counter()
    r = client.post("/api/grade", content=body, headers={"content-type": "application/json"})
    assert time.perf_counter() - start < 10
    if said is None:      # deep brackets inside the answer text: a grade, not a failure
        assert r.status_code == 200 and r.json()["status"] == "invalid"
    else:
        assert r.status_code == 400 and said in r.json()["error"]


@pytest.mark.parametrize("origin, status", [
    (None, 200),                               # not a browser: judged as before
    ("http://testserver", 200),                # the page itself
    ("http://testserver:80", 200),             # the default port written out
    ("http://evil.example", 403),              # another site
    ("http://testserver:8081", 403),           # another port of the same host (SameSite does
                                               # not tell these apart)
    ("https://testserver", 403),               # another scheme
    ("null", 403),                             # a sandboxed or file:// page
])
def test_a_state_changing_request_from_another_origin_is_refused(client, origin, status):
    headers = {"origin": origin} if origin is not None else {}
    r = client.post("/api/grade", json={"problem": "simple_pendulum",
                                        "answer": "a*theta'' + g*sin(theta) = 0"},
                    headers=headers)
    assert r.status_code == status
    if status == 403:
        assert "Origin" in r.json()["error"]
    else:   # no referrer leaves for other sites, and the page's own posts keep their Origin
        assert r.headers["referrer-policy"] == "same-origin"


def test_results_csv_keeps_answers_starting_with_a_sign_as_text():
    """An answer `-g*sin(theta) = ...` or `+...` would be read as a formula by a spreadsheet;
    like `=` and `@` it is written behind a quote (the teacher's results.csv and the
    gradebook share one rule, web.common.safe_cell)."""
    from dualmech.web.app import _csv
    rows = list(csv.reader(io.StringIO(_csv([
        {"id": "-s1", "question": "simple_pendulum", "line": 2, "status": "wrong",
         "summary": "+1", "answer": "-g*sin(theta) - a*theta'' = 0"},
        {"id": "@s2", "question": "=cmd", "line": 3, "status": "right", "summary": "ok",
         "answer": "a*theta'' + g*sin(theta) = 0"}]))))
    assert rows[1][0] == "'-s1" and rows[1][4] == "'+1"
    assert rows[1][6] == "'-g*sin(theta) - a*theta'' = 0"
    assert rows[2][0] == "'@s2" and rows[2][1] == "'=cmd"
    assert rows[2][6] == "a*theta'' + g*sin(theta) = 0"
