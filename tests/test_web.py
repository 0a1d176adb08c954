"""The web layer without grading: pages, validation while typing, limits, the teacher's token,
uploads, escaping, the OpenAPI description.  Grading is in test_web_grading.py, the real
browser in test_web_browser.py."""
from __future__ import annotations

import re

import pytest

pytest.importorskip("starlette")
from starlette.routing import Route  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

from dualmech.web import create_app, served_problems  # noqa: E402
from dualmech.web.app import WebLimits  # noqa: E402
from dualmech.web.batches import BatchRunner, read_upload  # noqa: E402
from dualmech.web.catalog import sketch_of, unit  # noqa: E402
from dualmech.web.openapi import SPEC  # noqa: E402
from dualmech.web.pages import batch_page, feedback_html  # noqa: E402

TOKEN = "t0ken-for-the-web-tests"
AUTH = {"Authorization": f"Bearer {TOKEN}"}
HOSTILE = '<script>alert("x")</script><img src=x onerror=alert(1)>'


class NoGrading:
    """Stands where the grading pool goes, for tests that must not grade."""

    workers = 2

    def submit(self, *args, **kwargs):
        raise AssertionError("this test must not grade")

    def close(self):
        pass


@pytest.fixture
def client(tmp_path):
    app = create_app(["simple_pendulum", "toy_car"], data=tmp_path, token=TOKEN,
                     pool=NoGrading())
    with TestClient(app) as c:
        yield c


def _validate(client, answer, problem="simple_pendulum", **extra):
    r = client.post("/api/validate", json={"problem": problem, "answer": answer, **extra})
    assert r.status_code == 200, r.text
    return r.json()


# -- problem page -----------------------------------------------------------------------------
def test_problem_page_shows_source_sketch_names_with_units_and_quantities(client):
    r = client.get("/problems/simple_pendulum")
    assert r.status_code == 200
    page = r.text
    assert "<h1>Simple pendulum</h1>" in page
    # the source, named by course (never the archive's hashed file name)
    assert "Source: Cambridge 3C5 Dynamics, Lagrangian mechanics: section 2.2" in page
    assert "002_df41972c66c4514e" not in page
    assert 'class="sketch"' in page and "pivot" in page             # the module's sketch
    # theta is an angle (rad); a is a length (m); g an acceleration (m s^-2): problem module
    assert re.search(r"<code>theta</code></td><td>rad</td>", page)
    assert re.search(r"<code>a</code></td><td>m</td>", page)
    assert re.search(r"<code>g</code></td><td>m s⁻²</td>", page)
    assert re.search(r"<code>T</code></td><td>kg m s⁻²</td>", page)  # the string's tension
    assert '<option value="eom">' in page and '<option value="T">' in page
    assert 'id="answer"' in page and 'id="preview"' in page


def test_index_lists_served_problems_only(client):
    page = client.get("/").text
    assert "/problems/simple_pendulum" in page and "/problems/toy_car" in page
    assert "/problems/bead_on_hoop" not in page
    assert [p["name"] for p in client.get("/api/problems").json()] == ["simple_pendulum",
                                                                       "toy_car"]


def test_units_of_dimensions():
    from dualmech.model.dimensions import ANGLE, ENERGY, TORSIONAL_DAMPING
    assert unit(ENERGY) == "kg m² s⁻²"
    assert unit(ANGLE) == "rad"
    # torque * time / angle: kg m^2 s^-1 (the angle is dimensionless)
    assert unit(TORSIONAL_DAMPING) == "kg m² s⁻¹"


def test_every_catalogue_problem_has_a_sketch():
    from dualmech.problems import all_problems
    missing = [p.name for p in all_problems() if not sketch_of(p).strip()]
    assert missing == []


# -- validation while typing --------------------------------------------------------------------
def test_validate_typesets_in_the_students_order_with_dotted_names(client):
    p = _validate(client, "a*theta'' + g*sin(theta) = 0")
    assert p["ok"] and p["error"] is None and p["unknown"] == [] and p["dimensions"] == []
    m = p["mathml"]
    # theta'' is a theta with two dots (U+0308), and `a` comes before it, as typed
    assert "<mi>a</mi><mo>&#x2062;</mo><mi>&#952;&#776;</mi>" in m
    assert m.index("&#952;&#776;") < m.index("<mi>sin</mi>")
    assert "<mo>=</mo><mn>0</mn>" in m


def test_validate_lists_unknown_names_with_the_closest_accepted_ones(client):
    p = _validate(client, "a*thetaa'' + g*sinn = 0")
    assert not p["ok"]
    names = {u["name"]: u["suggestions"] for u in p["unknown"]}
    assert set(names) == {"thetaa''", "sinn"}
    assert names["thetaa''"][0] == "theta"
    assert 'class="unknown"' in p["mathml"]


def test_validate_warns_of_terms_whose_dimensions_disagree(client):
    # a*theta'' is L T^-2 and a*g is L^2 T^-2 (a is a length, g an acceleration)
    p = _validate(client, "a*theta'' + a*g = 0")
    assert p["ok"]
    assert p["dimensions"] == ["the terms do not share one dimension: `a*theta''` has "
                               "L T^-2; `a*g` has L^2 T^-2"]


def test_validate_reports_syntax_and_size_errors_without_evaluating(client):
    p = _validate(client, "__import__('os').system('true')")
    assert not p["ok"] and p["error"].startswith("could not read the answer at column 1")
    p = _validate(client, "x" * 4001)
    assert p["error"] == "the answer has 4001 characters; at most 4000 are graded."
    p = _validate(client, "9^9^9^9")
    assert "larger than 24" in p["error"]


def test_validate_knows_basis_vectors_of_vector_quantities(client):
    p = _validate(client, "m*R^2*(phi'*cos(theta)*i_B + theta'*j_B)", problem="toy_car",
                  quantity="h_O")
    assert p["ok"] and p["unknown"] == []


@pytest.mark.parametrize("body, status", [
    (b"not json", 400), (b"[1, 2]", 400), (b'{"problem": "simple_pendulum"}', 400),
    (b'{"problem": "simple_pendulum", "answer": 3}', 400),
    (b'{"problem": "../../etc/passwd", "answer": "x"}', 404),
    (b'{"problem": "simple_pendulum", "answer": "x", "quantity": "' + b"q" * 300 + b'"}', 413),
], ids=["not-json", "not-object", "no-answer", "answer-not-text", "path-as-problem",
        "long-quantity"])
def test_bad_requests_get_clear_errors(client, body, status):
    r = client.post("/api/validate", content=body, headers={"Content-Type": "application/json"})
    assert r.status_code == status
    assert r.json()["error"]


def test_request_bodies_are_bounded(client):
    r = client.post("/api/validate", json={"problem": "simple_pendulum",
                                           "answer": "x" * 70000})
    assert r.status_code == 413
    assert "at most 65536" in r.json()["error"]


def test_rate_limit_per_client(tmp_path):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading(),
                     rates={"validate": (0.001, 3)})
    with TestClient(app) as c:
        codes = [c.post("/api/validate", json={"problem": "simple_pendulum",
                                               "answer": "a"}).status_code for _ in range(4)]
        assert codes == [200, 200, 200, 429]
        r = c.post("/api/validate", json={"problem": "simple_pendulum", "answer": "a"})
        assert int(r.headers["Retry-After"]) >= 1 and "too many requests" in r.json()["error"]


# -- the teacher ----------------------------------------------------------------------------------
def test_teacher_api_needs_the_token(client):
    assert client.get("/api/batches").status_code == 401
    assert client.get("/api/batches", headers={"Authorization": "Bearer nope"}).status_code \
        == 401
    assert client.get("/api/batches", headers=AUTH).json() == []


def test_teacher_login_sets_a_session_cookie_that_is_not_the_token(client):
    assert 'name="token"' in client.get("/teacher").text            # the login form
    r = client.post("/teacher/login", data={"token": "wrong"}, follow_redirects=False)
    assert r.status_code == 401 and "not the token" in r.text
    r = client.post("/teacher/login", data={"token": TOKEN}, follow_redirects=False)
    assert r.status_code == 303
    cookie = r.cookies.get("dualmech_teacher")
    assert cookie and TOKEN not in cookie
    assert "HttpOnly" in r.headers["set-cookie"] and "SameSite=strict" in r.headers["set-cookie"]
    page = client.get("/teacher").text                                # the cookie is kept
    assert 'id="upload-form"' in page


def test_upload_errors_say_what_to_fix(client, tmp_path):
    r = client.post("/api/batches", content=b"student,answer\ns1,x\n", headers={
        **AUTH, "X-Filename": "class%201.csv"})
    assert r.status_code == 400
    err = r.json()["error"]
    assert err.startswith("class 1.csv: the header must have the columns id, question, answer")
    assert "missing id, question" in err and str(tmp_path) not in err
    r = client.post("/api/batches", content=b"id,question,answer\n\xff\xfe,x,y\n", headers=AUTH)
    assert r.status_code == 400 and "not UTF-8" in r.json()["error"]
    r = client.post("/api/batches", content=b"id,question,answer\n", headers=AUTH)
    assert r.status_code == 400 and "no answers" in r.json()["error"]


def test_upload_size_and_rows_are_bounded(tmp_path, monkeypatch):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading(),
                     limits=WebLimits(csv_bytes=1000))
    with TestClient(app) as c:
        r = c.post("/api/batches", content=b"id,question,answer\n" + b"s,q,a\n" * 200,
                   headers=AUTH)
        assert r.status_code == 413
    monkeypatch.setattr("dualmech.web.batches.MAX_ROWS", 3)
    with pytest.raises(ValueError, match="4 answers; at most 3"):
        read_upload(b"id,question,answer\n" + b"s,q,a\n" * 4, "c.csv", tmp_path / "up")
    assert list((tmp_path / "up").iterdir()) == []      # the upload's file is removed


def test_batch_rows_naming_an_unserved_problem_are_refused_without_loading_it(tmp_path):
    from dualmech.web.store import Store
    store = Store(tmp_path)
    bid = store.add_batch("c.csv", [{"id": "s1", "question": "../../etc/passwd:eom",
                                     "answer": "x", "line": 2},
                                    {"id": "s2", "question": "os:system", "answer": "x",
                                     "line": 3}])
    runner = BatchRunner(store, NoGrading(), {"simple_pendulum": "simple_pendulum"}).start()
    try:
        import time
        for _ in range(100):
            if store.progress(bid)["status"] == "done":
                break
            time.sleep(0.05)
    finally:
        runner.close()
    results = store.results(bid)
    assert [r["status"] for r in results] == ["invalid", "invalid"]
    assert results[0]["summary"] == ("no problem `../../etc/passwd` is served here; served: "
                                     "simple_pendulum.")
    assert results[1]["summary"].startswith("no problem `os` is served here")


# -- escaping ---------------------------------------------------------------------------------------
def test_student_text_is_escaped_on_the_teacher_pages(client):
    store = client.app.state.server.store
    bid = store.add_batch(HOSTILE, [{"id": HOSTILE, "question": "simple_pendulum",
                                     "answer": HOSTILE, "line": 2}])
    store.put_result(bid, 0, {"id": HOSTILE, "question": HOSTILE, "answer": HOSTILE,
                              "status": "wrong", "summary": HOSTILE, "line": 2,
                              "edits": [{"kind": "missing", "sentence": HOSTILE,
                                         "correct": HOSTILE, "term": ""}],
                              "dimension_issues": [HOSTILE]})
    store.add_answer({"problem": "simple_pendulum", "answer": HOSTILE, "status": "invalid",
                      "summary": HOSTILE, "question": HOSTILE})
    client.post("/teacher/login", data={"token": TOKEN})
    for page in (client.get(f"/teacher/batches/{bid}").text, client.get("/teacher").text):
        assert "<script>alert" not in page and "<img src=x" not in page
        assert "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;" in page


def test_feedback_escapes_summary_and_terms():
    html = feedback_html(None, {"status": "wrong", "summary": HOSTILE, "details": [HOSTILE],
                                "edits": [{"kind": "sign", "equation": 0, "term": HOSTILE,
                                           "correct": HOSTILE, "sentence": HOSTILE}]})
    assert "<script>" not in html and "<img" not in html
    assert html.count("&lt;script&gt;") == 4


def test_batch_page_shows_a_progress_bar_while_grading():
    page = batch_page({"id": "ab12", "name": "c.csv", "total": 10, "done": 3,
                       "status": "grading"}, [])
    assert '<progress id="batch-progress" data-batch="ab12" max="10"' in page
    assert "3 of 10 graded" in page


# -- headers, API description, CLI -------------------------------------------------------------------
def test_pages_forbid_inline_scripts_and_framing(client):
    r = client.get("/problems/toy_car")
    csp = r.headers["content-security-policy"]
    assert "script-src 'self'" in csp and "frame-ancestors 'none'" in csp
    assert r.headers["x-content-type-options"] == "nosniff"
    assert "<script>" not in r.text.replace('<script src="/static/app.js"></script>', "")


def test_openapi_lists_exactly_the_api_routes(client):
    app_paths = {re.sub(r"\{(\w+):path\}", r"{\1}", r.path) for r in client.app.routes
                 if isinstance(r, Route) and r.path.startswith("/api/")
                 and r.path != "/api/docs"}
    spec_paths = {re.sub(r"/(results\.json|report\.md|results\.csv)$", "/{file:str}", p)
                  for p in SPEC["paths"]}
    assert spec_paths == app_paths
    assert client.get("/api/openapi.json").json()["openapi"] == "3.1.0"
    docs = client.get("/api/docs").text
    assert "POST /api/grade" in docs


def test_unknown_endpoints_and_problems_get_404(client):
    assert client.get("/api/nothing").json() == {"error": "no such endpoint; see /api/docs."}
    assert client.get("/problems/..%2F..%2Fetc%2Fpasswd").status_code == 404
    assert client.get("/api/problems/nope").status_code == 404


def test_serve_refuses_an_unknown_problem_with_the_reason():
    with pytest.raises(ValueError, match="cannot serve problem .no_such_thing.: no problem named"):
        served_problems(["no_such_thing"])


def test_serve_command_is_registered_and_checks_its_port(capsys):
    from dualmech.cli.main import main
    assert main(["serve", "--port", "70000"]) == 2
    assert "`--port` must be 1 to 65535" in capsys.readouterr().err


class Recorded:
    """Stands where the pool goes and answers every submission with one fixed grade."""

    workers = 1

    def __init__(self):
        self.calls = []

    def submit(self, problem, answer, quantity=None, about=None):
        from concurrent.futures import Future

        from dualmech.grade.result import Grade
        self.calls.append((problem, answer, quantity, about))
        f = Future()
        f.set_result(Grade(problem, quantity or "auto", "equations", answer, "wrong",
                           "recorded"))
        return f

    def close(self):
        pass


def test_the_same_answer_is_graded_once(tmp_path):
    pool = Recorded()
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=pool)
    with TestClient(app) as c:
        body = {"problem": "simple_pendulum", "answer": "a*theta''", "quantity": "eom"}
        first = c.post("/api/grade", json=body).json()
        second = c.post("/api/grade", json=body).json()
        other = c.post("/api/grade", json=dict(body, answer="a*theta'' ")).json()
        kept = app.state.server.store.answers()
        assert len(kept) == 3                                   # every submission is kept
        assert {a["question"] for a in kept} == {"simple_pendulum:eom"}
        c.post("/teacher/login", data={"token": TOKEN})
        assert "<h3>simple_pendulum:eom</h3><p>0 of 3 right, 3 wrong" in c.get("/teacher").text
    assert pool.calls == [("simple_pendulum", "a*theta''", "eom", None),
                          ("simple_pendulum", "a*theta'' ", "eom", None)]
    assert first == second and first["summary"] == "recorded"
    assert other["answer"] == "a*theta'' "
