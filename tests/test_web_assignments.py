"""Assignments without grading: hostile input to every new endpoint, the teacher's token and
sessions, the gradebook CSV, statistics and a student's data.  Every hostile request is timed:
each is answered with a clear 4xx in well under a second (no 500, no work done for it).
Grading at a student's numbers is in test_web_assignment_grading.py, the student's page in
the browser in test_web_browser.py."""
from __future__ import annotations

import csv
import io
import json
import time

import pytest

pytest.importorskip("starlette")
from starlette.testclient import TestClient  # noqa: E402

from dualmech.web import create_app  # noqa: E402
from dualmech.web.rules import MAX_STUDENTS  # noqa: E402

TOKEN = "assignments-teacher-token"
AUTH = {"Authorization": f"Bearer {TOKEN}"}
GOOD = {"title": "HW 1", "questions": [{"problem": "simple_pendulum", "quantity": None},
                                       {"problem": "toy_car", "quantity": "F_r"}],
        "students": ["ada", "bob"], "per_student_numbers": True, "feedback": "locate",
        "attempts": 2, "penalty": 0.25, "deadline": "2031-06-30T23:59:00+02:00"}
#: the slowest a refused request may take (they are refused before any grading or loading)
FAST = 1.0


class NoGrading:
    """Stands where the grading pool goes: these tests must not grade."""

    workers = 2

    def submit(self, *args, **kwargs):
        raise AssertionError("this test must not grade")

    def close(self):
        pass


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    app = create_app(["simple_pendulum", "toy_car"], data=tmp_path_factory.mktemp("a"),
                     token=TOKEN, pool=NoGrading(), rates={})
    with TestClient(app) as c:
        for name in ("simple_pendulum", "toy_car"):   # loaded once, before any timing
            c.app.state.server.info(name)
        yield c


@pytest.fixture(scope="module")
def made(client):
    r = client.post("/api/assignments", json=GOOD, headers=AUTH)
    assert r.status_code == 201, r.text
    return r.json()


def _timed(call, *args, **kwargs):
    t0 = time.perf_counter()
    r = call(*args, **kwargs)
    seconds = time.perf_counter() - t0
    assert seconds < FAST, f"{seconds:.2f} s"
    return r


def _refused(client, body, status, words, raw=None):
    kw = {"content": raw, "headers": {**AUTH, "Content-Type": "application/json"}} \
        if raw is not None else {"json": body, "headers": AUTH}
    r = _timed(client.post, "/api/assignments", **kw)
    assert r.status_code == status, r.text
    assert words in r.json()["error"], r.json()["error"]


# -- POST /api/assignments, hostile ---------------------------------------------------------------
def test_making_an_assignment_needs_the_teacher(client):
    assert _timed(client.post, "/api/assignments", json=GOOD).status_code == 401
    r = _timed(client.post, "/api/assignments", json=GOOD,
               headers={"Authorization": "Bearer " + TOKEN[:-1]})
    assert r.status_code == 401


@pytest.mark.parametrize("raw, words", [
    (b"{not json", "must be a JSON object"),
    (b"[1, 2]", "must be a JSON object"),
    (b"[" * 100000 + b"]" * 100000, "nested too deeply"),
    (b'{"title": "\\ud800"}', "lone surrogate"),
    (b"\xff\xfe", "must be a JSON object"),
])
def test_malformed_bodies_are_refused(client, raw, words):
    _refused(client, None, 400, words, raw=raw)


@pytest.mark.parametrize("change, status, words", [
    ({"title": 7}, 400, "`title` must be a non-empty string"),
    ({"title": "   "}, 400, "`title` must be a non-empty string"),
    ({"title": "x" * 201}, 413, "`title` is longer than 200"),
    ({"title": "a\u202eb"}, 400, "control or format character"),
    ({"questions": []}, 400, "`questions` must be a list of 1 to 50"),
    ({"questions": "simple_pendulum"}, 400, "`questions` must be a list"),
    ({"questions": [{"problem": "simple_pendulum"}] * 51}, 413, "1 to 50"),
    ({"questions": [{"problem": 3}]}, 400, "question 1 must be an object"),
    ({"questions": [{"problem": "simple_pendulum", "x": 1}]}, 400, "must be an object"),
    ({"questions": [{"problem": "../../etc/passwd"}]}, 404, "no problem '../../etc/passwd'"),
    ({"questions": [{"problem": "bead_on_hoop"}]}, 404, "served: simple_pendulum, toy_car"),
    ({"questions": [{"problem": "toy_car", "quantity": "nope"}]}, 400,
     "one of toy_car's: eom, equation"),
    ({"questions": [{"problem": "toy_car", "quantity": 5}]}, 400, "`quantity` must be null"),
    ({"questions": [{"problem": "toy_car", "quantity": "nope"}, {"problem": "nope"}]}, 404,
     "question 2: no problem 'nope'"),
    ({"students": []}, 400, "`students` must be a non-empty list"),
    ({"students": "ada"}, 400, "`students` must be a non-empty list"),
    ({"students": ["ada", 4]}, 400, "`students[]` must be a non-empty string"),
    ({"students": ["ada", "ada"]}, 400, "listed twice"),
    ({"students": ["x" * 101]}, 413, "longer than 100"),
    ({"students": ["a\x00b"]}, 400, "control or format character"),
    ({"students": [f"s{i}" for i in range(MAX_STUDENTS + 1)]}, 413, "at most 2000"),
    ({"per_student_numbers": "yes"}, 400, "`per_student_numbers` must be true or false"),
    ({"feedback": "everything"}, 400, "`feedback` must be one of verdict, locate, hint, full"),
    ({"attempts": 0}, 400, "`attempts` must be a whole number from 1 to 100"),
    ({"attempts": True}, 400, "`attempts` must be a whole number"),
    ({"attempts": "3"}, 400, "`attempts` must be a whole number"),
    ({"attempts": 10 ** 30}, 400, "`attempts` must be a whole number"),
    ({"penalty": 1.5}, 400, "`penalty` must be a number from 0 to 1"),
    ({"deadline": "2031-06-30T23:59:00"}, 400, "needs its time zone"),
    ({"deadline": "next friday"}, 400, "is not an ISO 8601 time"),
    ({"deadline": 1893456000}, 400, "`deadline` must be an ISO 8601 time"),
    ({"grades": "all A"}, 400, "unknown field `grades`"),
])
def test_wrong_fields_are_refused_naming_the_field(client, change, status, words):
    _refused(client, {**GOOD, **change}, status, words)


def test_a_nan_penalty_and_a_body_over_the_bound_are_refused(client):
    raw = json.dumps({**GOOD, "penalty": 0.5}).replace("0.5", "NaN").encode()
    _refused(client, None, 400, "`penalty` must be a number", raw=raw)
    huge = json.dumps({**GOOD, "students": ["s" * 90 + str(i) for i in range(6000)]}).encode()
    _refused(client, None, 413, "at most 524288 are accepted", raw=huge)


def test_an_assignment_gives_each_student_a_link_once(client, made):
    assert set(made["students"]) == {"ada", "bob"}
    ada, bob = made["students"]["ada"], made["students"]["bob"]
    assert ada["token"] != bob["token"] and len(ada["token"]) >= 32
    assert ada["url"] == f"http://testserver/assignments/{made['id']}#token={ada['token']}"
    listed = client.get("/api/assignments", headers=AUTH).json()
    assert [a["id"] for a in listed] == [made["id"]] and listed[0]["students"] == 2
    assert "token" not in json.dumps(listed)                    # never shown again
    stored = client.app.state.server.store._all("SELECT token FROM enrolled")
    assert ada["token"] not in {r["token"] for r in stored}       # only its hash is kept


# -- GET /me, hostile -----------------------------------------------------------------------------
def _me(client, aid, token):
    return _timed(client.get, f"/api/assignments/{aid}/me",
                  headers={"Authorization": f"Bearer {token}"} if token else {})


def test_me_needs_the_students_own_token_for_this_assignment(client, made):
    aid, ada = made["id"], made["students"]["ada"]["token"]
    assert _me(client, aid, None).status_code == 401
    assert _me(client, aid, "forged").status_code == 401
    assert _me(client, aid, TOKEN).status_code == 401               # the teacher's is not one
    assert _me(client, aid, "x" * 100000).status_code in (401, 431)
    other = client.post("/api/assignments", json={**GOOD, "students": ["cy"]},
                        headers=AUTH).json()
    r = _me(client, other["id"], ada)
    assert r.status_code == 403 and "another assignment" in r.json()["error"]
    me = _me(client, aid, ada).json()
    assert me["student"] == "ada" and "bob" not in json.dumps(me)


def test_me_shows_the_numbers_drawn_from_the_declared_ranges(client, made):
    from dualmech.problems import get
    aid = made["id"]
    mine = {s: _me(client, aid, made["students"][s]["token"]).json() for s in ("ada", "bob")}
    ranges = {str(p.symbol): p.range for name in ("simple_pendulum", "toy_car")
              for p in get(name).parameters}
    for me in mine.values():
        assert set(me["numbers"]) == {"M", "a", "g", "m", "R"}
        for name, text in me["numbers"].items():
            lo, hi = ranges[name]
            assert lo <= float(text) <= hi and len(text.replace(".", "").lstrip("0")) <= 3
        assert me["units"]["g"] == "m s⁻²" and me["attempts_left"] == [2, 2]
        assert me["score"] == 0.0 and me["deadline"] == "2031-06-30T21:59:00Z"
        assert [q["asked"] for q in me["questions"]] == [
            "the equations of motion", "the reaction F_r (along k_B, track on car)"]
    assert mine["ada"]["numbers"] != mine["bob"]["numbers"]


# -- POST /answers, hostile -----------------------------------------------------------------------
def _answer(client, made, body, student="ada", raw=None):
    headers = {"Authorization": f"Bearer {made['students'][student]['token']}"}
    if raw is not None:
        return _timed(client.post, f"/api/assignments/{made['id']}/answers", content=raw,
                      headers={**headers, "Content-Type": "application/json"})
    return _timed(client.post, f"/api/assignments/{made['id']}/answers", json=body,
                  headers=headers)


@pytest.mark.parametrize("body, status, words", [
    ({"question": "0", "answer": "x"}, 400, "`question` must be the index"),
    ({"question": True, "answer": "x"}, 400, "`question` must be the index"),
    ({"question": 2, "answer": "x"}, 400, "0 to 1"),
    ({"question": -1, "answer": "x"}, 400, "0 to 1"),
    ({"question": 0, "answer": ["x"]}, 400, "`answer` must be a string"),
    ({"question": 0}, 400, "`answer` must be a string"),
    ({"question": 0, "answer": "x" * 4001}, 413, "longer than 4000"),
    ({"question": 0, "answer": "x", "student": "bob"}, 400, "only `question` and `answer`"),
])
def test_wrong_answers_bodies_are_refused(client, made, body, status, words):
    r = _answer(client, made, body)
    assert r.status_code == status and words in r.json()["error"], r.text


@pytest.mark.parametrize("raw, words", [(b"nope", "must be a JSON object"),
                                        (b"[" * 20000 + b"]" * 20000, "nested too deeply"),
                                        (b'{"question": 0, "answer": "\\udfff"}',
                                         "lone surrogate")])
def test_malformed_answer_bodies_are_refused(client, made, raw, words):
    r = _answer(client, made, None, raw=raw)
    assert r.status_code == 400 and words in r.json()["error"]


def test_answers_need_a_students_token_for_this_assignment(client, made):
    url = f"/api/assignments/{made['id']}/answers"
    body = {"question": 0, "answer": "x"}
    assert _timed(client.post, url, json=body).status_code == 401
    assert _timed(client.post, url, json=body, headers=AUTH).status_code == 401
    other = client.post("/api/assignments", json={**GOOD, "students": ["dee"]},
                        headers=AUTH).json()
    r = _timed(client.post, f"/api/assignments/{other['id']}/answers", json=body,
               headers={"Authorization": f"Bearer {made['students']['ada']['token']}"})
    assert r.status_code == 403 and "another assignment" in r.json()["error"]


def test_the_teacher_page_lists_assignments_as_text(client):
    hostile = '<script>alert(1)</script>'
    client.post("/api/assignments", json={**GOOD, "title": hostile}, headers=AUTH)
    client.post("/teacher/login", data={"token": TOKEN})
    page = client.get("/teacher").text
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in page and hostile not in page
    assert "/grades.csv" in page and "/stats" in page


def test_no_answer_after_the_deadline(client, made):
    srv = client.app.state.server
    try:
        srv.clock = lambda: 1941000000.0                        # 2031-07-04: after it
        r = _answer(client, made, {"question": 0, "answer": "x"})
        assert r.status_code == 403
        assert r.json()["error"] == ("the deadline passed at 2031-06-30T21:59:00Z; answers "
                                     "are no longer graded.")
        assert _me(client, made["id"], made["students"]["ada"]["token"]).json()["closed"]
    finally:
        srv.clock = time.time


def test_no_answer_once_the_attempts_are_used(client, made):
    room = client.app.state.server.classroom
    for _ in range(2):   # bob's two attempts at question 1, taken as the endpoint takes them
        k = room.reserve(made["id"], "bob", 1, "F_r = 0", limit=2)
        room.finish(k, {"full": {"status": "wrong", "edits": []}, "shown": {}, "score": 0.0})
    r = _answer(client, made, {"question": 1, "answer": "F_r = 1"}, student="bob")
    assert r.status_code == 409
    assert r.json()["error"] == "no attempt left at question 2 (all 2 used)."
    assert room.reserve(made["id"], "bob", 1, "x", limit=2) is None


def test_answers_are_rate_limited_per_student_not_per_address(tmp_path):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading(),
                     rates={"grade": (0.001, 1)})
    with TestClient(app) as c:
        made = c.post("/api/assignments", json={
            "title": "t", "questions": [{"problem": "simple_pendulum"}],
            "students": ["ada", "bob"], "deadline": "2030-01-01T00:00:00Z"},
            headers=AUTH).json()
        app.state.server.clock = lambda: 4e9     # past the deadline: refused after the limit
        codes = {s: [_answer(c, made, {"question": 0, "answer": "x"}, student=s).status_code
                     for _ in range(2)] for s in ("ada", "bob")}
    assert codes == {"ada": [403, 429], "bob": [403, 429]}


# -- the teacher's token and sessions -------------------------------------------------------------
def test_a_weak_teacher_token_is_refused(tmp_path):
    for weak in ("", "s3cret", "aaaaaaaaaaaaaaaaaaaa", " padded-token-of-length "):
        with pytest.raises(ValueError, match="token"):
            create_app(["simple_pendulum"], data=tmp_path, token=weak, pool=NoGrading())


def test_sessions_expire_end_at_logout_and_pages_are_not_cached(tmp_path, monkeypatch):
    import dualmech.web.sessions as sessions
    now = [1000.0]
    monkeypatch.setattr(sessions, "time", type("Clock", (), {"time": lambda: now[0]}))
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading())
    with TestClient(app, base_url="https://testserver") as c:
        r = c.post("/teacher/login", data={"token": TOKEN}, follow_redirects=False)
        cookie = r.headers["set-cookie"]
        assert "Secure" in cookie and "HttpOnly" in cookie and "Max-Age=28800" in cookie
        page = c.get("/teacher")
        assert 'id="upload-form"' in page.text and page.headers["cache-control"] == "no-store"
        now[0] += 8 * 3600 + 1                                      # the session expired
        assert 'name="token"' in c.get("/teacher").text
        assert c.get("/api/batches").status_code == 401
        now[0] = 1000.0
        c.post("/teacher/login", data={"token": TOKEN})
        sid = c.cookies.get("dualmech_teacher")
        assert 'id="logout"' in c.get("/teacher").text
        r = c.post("/teacher/logout", follow_redirects=False)
        assert r.status_code == 303 and 'dualmech_teacher=""' in r.headers["set-cookie"]
        c.cookies.set("dualmech_teacher", sid)                      # replaying the old cookie
        assert 'name="token"' in c.get("/teacher").text
    with TestClient(app) as c:                                      # plain http: no Secure
        r = c.post("/teacher/login", data={"token": TOKEN}, follow_redirects=False)
        assert "Secure" not in r.headers["set-cookie"]
        assert c.get("/api/assignments", headers=AUTH).headers["cache-control"] == "no-store"
        assert "cache-control" not in c.get("/problems/simple_pendulum").headers


# -- gradebook, statistics, a student's data ------------------------------------------------------
def _graded(room, aid, student, question, answer, problem="simple_pendulum", quantity=None):
    """An attempt recorded with the real grade of ``answer`` (graded here, in-process)."""
    from dualmech.grade import grade
    from dualmech.web.gradebook import record
    k = room.reserve(aid, student, question, answer, limit=100)
    room.finish(k, record(grade(problem, answer, quantity), "locate"))


def test_gradebook_csv_for_moodle_and_canvas(tmp_path):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading())
    with TestClient(app) as c:
        made = c.post("/api/assignments", json={
            "title": "=HW", "questions": [{"problem": "simple_pendulum"},
                                          {"problem": "simple_pendulum", "quantity": "T"}],
            "students": ["ada", "=cmd|' /C calc'!A0", "+bob"], "penalty": 0.5},
            headers=AUTH).json()
        room, aid = app.state.server.classroom, made["id"]
        _graded(room, aid, "ada", 0, "a*theta'' - g*sin(theta) = 0")     # wrong: 0.5 credit
        _graded(room, aid, "ada", 0, "a*theta'' + g*sin(theta) = 0")     # right, 2nd: 0.5
        _graded(room, aid, "+bob", 0, "a*theta'' + g*sin(theta) = 0")    # right, 1st: 1
        r = c.get(f"/api/assignments/{aid}/grades.csv", headers=AUTH)
        assert c.get(f"/api/assignments/{aid}/grades.csv").status_code == 401
    assert r.status_code == 200 and r.headers["content-type"].startswith("text/csv")
    rows = list(csv.reader(io.StringIO(r.text)))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section",
                       "'=HW Q1 simple_pendulum", "'=HW Q2 simple_pendulum T", "'=HW total"]
    # ada: max(0.5 * 1, 1 * (1 - 0.5)) = 0.5 on question 1, nothing on 2: total 25 %
    assert rows[1] == ["ada", "", "ada", "ada", "", "50.00", "0.00", "25.00"]
    assert rows[2][:5] == ["'=cmd|' /C calc'!A0", "", "'=cmd|' /C calc'!A0",
                           "'=cmd|' /C calc'!A0", ""]
    assert rows[3] == ["'+bob", "", "'+bob", "'+bob", "", "100.00", "0.00", "50.00"]
    assert len(rows) == 4


def test_statistics_name_the_mistakes_grouped(tmp_path):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading())
    with TestClient(app) as c:
        made = c.post("/api/assignments", json={
            "title": "t", "questions": [{"problem": "simple_pendulum"}],
            "students": ["ada", "bob", "cy"]}, headers=AUTH).json()
        room, aid = app.state.server.classroom, made["id"]
        _graded(room, aid, "ada", 0, "a*theta'' - g*sin(theta) = 0")
        _graded(room, aid, "ada", 0, "a*theta'' + g*sin(theta) = 0")
        _graded(room, aid, "bob", 0, "a*theta'' - g*sin(theta) = 0")
        _graded(room, aid, "bob", 0, "a*theta'' + (")
        s = c.get(f"/api/assignments/{aid}/stats", headers=AUTH).json()
    q = s["questions"][0]
    assert (q["students"], q["answered"], q["right"], q["right_share"], q["attempts"]) == \
        (3, 2, 1, 0.3333, 4)
    assert q["mistakes"][0] == {"mistake": "gravity sign", "attempts": 2, "students": 2}
    assert {"mistake": "not graded (could not be read)", "attempts": 1, "students": 1} in \
        q["mistakes"]
    assert s["students"]["ada"] == {"attempts": [2], "scores": [1.0], "total": 1.0}
    assert s["students"]["cy"] == {"attempts": [0], "scores": [0.0], "total": 0.0}


def test_a_students_data_is_exported_and_deleted(tmp_path):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading())
    with TestClient(app) as c:
        made = c.post("/api/assignments", json={
            "title": "t", "questions": [{"problem": "simple_pendulum"}],
            "students": ["ada/1", "bob"], "per_student_numbers": True}, headers=AUTH).json()
        srv = app.state.server
        _graded(srv.classroom, made["id"], "ada/1", 0, "a*theta'' + g*sin(theta) = 0")
        srv.store.add_batch("c.csv", [{"id": "ada/1", "question": "simple_pendulum",
                                       "answer": "x", "line": 2},
                                      {"id": "bob", "question": "simple_pendulum",
                                       "answer": "y", "line": 3}])
        assert c.get("/api/students/ada%2F1").status_code == 401
        out = c.get("/api/students/ada%2F1", headers=AUTH).json()
        assert out["assignments"][0]["numbers"] == srv.classroom.roster(made["id"])["ada/1"]
        assert out["assignments"][0]["attempts"][0]["answer"] == "a*theta'' + g*sin(theta) = 0"
        assert [r["answer"] for r in out["batch_rows"]] == ["x"]
        r = c.delete("/api/students/ada%2F1", headers=AUTH)
        assert r.json() == {"student": "ada/1", "assignments": 1, "batch_rows": 1}
        assert c.get("/api/students/ada%2F1", headers=AUTH).status_code == 404
        me = c.get(f"/api/assignments/{made['id']}/me", headers={
            "Authorization": f"Bearer {made['students']['ada/1']['token']}"})
        assert me.status_code == 401                                # the link stopped working
        assert srv.store.batches()[0]["total"] == 1 and \
            [r["student"] for r in srv.store.pending(srv.store.batches()[0]["id"])] == ["bob"]
        assert c.delete("/api/students/nobody", headers=AUTH).status_code == 404


def test_the_markdown_report_shows_student_ids_as_text(tmp_path):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, pool=NoGrading())
    with TestClient(app) as c:
        store = app.state.server.store
        bid = store.add_batch("c.csv", [{"id": "<img src=x onerror=alert(1)>",
                                         "question": "simple_pendulum", "answer": "x",
                                         "line": 2}])
        store.put_result(bid, 0, {"id": "<img src=x onerror=alert(1)>",
                                  "question": "simple_pendulum", "status": "wrong",
                                  "summary": "s", "edits": []})
        md = c.get(f"/api/batches/{bid}/report.md", headers=AUTH).text
        raw = c.get(f"/api/batches/{bid}/results.json", headers=AUTH).text
    assert "<img" not in md and "&lt;img src=x onerror=alert(1)&gt;" in md
    assert "<img src=x onerror=alert(1)>" in raw                     # the data itself is kept
