"""The pages in a real browser: Chromium (the operating system's package) driven by Playwright.

A student types a wrong and then a right answer and sees the preview and the feedback; a
teacher logs in, uploads a class's CSV and sees the table.  The server is uvicorn on a free
loopback port, in a thread, with the real grading pool.  Under CI (``CI`` set) a missing
Chromium fails the test: .ci/run installs it.

Screenshots go to the test's temporary folder, or to ``docs/`` (the README's pictures) when
``DUALMECH_SCREENSHOTS`` names a folder.
"""
from __future__ import annotations

import os
import shutil
import socket
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip("starlette")
uvicorn = pytest.importorskip("uvicorn")

CHROMIUM = "/usr/bin/chromium"
ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync"]
TOKEN = "browser-test-token"


def _need_browser():
    missing = []
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        missing.append("the playwright package (pip install -e '.[test]')")
    if not (os.path.exists(CHROMIUM) or shutil.which("chromium")):
        missing.append(f"Chromium at {CHROMIUM} (apt-get install chromium)")
    if missing:
        message = "the browser test needs " + " and ".join(missing)
        if os.environ.get("CI"):
            pytest.fail(message + "; .ci/run installs it")
        pytest.skip(message)


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    _need_browser()
    from dualmech.web import create_app
    data = tmp_path_factory.mktemp("web-data")
    app = create_app(["simple_pendulum", "toy_car"], data=data, token=TOKEN, workers=2)
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(app, log_level="warning"))
    thread = threading.Thread(target=srv.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    deadline = time.monotonic() + 60
    while not srv.started:
        assert thread.is_alive() and time.monotonic() < deadline, "the server did not start"
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    srv.should_exit = True
    thread.join(30)
    sock.close()


@pytest.fixture(scope="module")
def browser(server):
    from playwright.sync_api import sync_playwright
    exe = CHROMIUM if os.path.exists(CHROMIUM) else shutil.which("chromium")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=exe, args=ARGS)
        yield b
        b.close()


def _shots(tmp_path) -> Path:
    out = os.environ.get("DUALMECH_SCREENSHOTS")
    return Path(out) if out else tmp_path


@pytest.mark.slow
def test_student_sees_the_preview_while_typing_and_feedback_on_submit(server, browser,
                                                                       tmp_path):
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.goto(f"{server}/problems/simple_pendulum")
    assert page.inner_text("h1") == "Simple pendulum"
    box = page.locator("#answer")

    # a wrong sign: the preview typesets it (theta with two dots), the feedback names the term
    box.fill("a*theta'' - g*sin(theta) = 0")
    page.wait_for_selector("#preview[data-state=ok] math")
    assert "θ̈" in page.inner_text("#preview")
    page.click("#submit")
    page.wait_for_selector("#feedback .feedback.wrong")
    feedback = page.inner_text("#feedback")
    assert "Not right yet" in feedback and "has the wrong sign" in feedback
    assert page.locator("#feedback li math").count() == 2   # the term and its correction

    # an unknown name is listed while typing, before any submission
    box.fill("a*theta'' + g*sin(thetaa) = 0")
    page.wait_for_selector("#preview[data-state=error] .unknown-names")
    assert "thetaa" in page.inner_text("#preview .unknown-names")
    page.screenshot(path=str(_shots(tmp_path) / "web_problem_page.png"), full_page=True)

    # the right answer
    box.fill("a*theta'' + g*sin(theta) = 0")
    page.wait_for_selector("#preview[data-state=ok] math")   # the page's CSP forbids eval
    page.click("#submit")
    page.wait_for_selector("#feedback .feedback.right")
    assert "Right" in page.inner_text("#feedback .verdict")


@pytest.mark.slow
def test_preview_typesets_the_dimensions_of_terms_that_disagree(server, browser, tmp_path):
    # a*theta'' is L T^-2, a*g is L^2 T^-2: both shown with their exponents as superscripts
    page = browser.new_page(viewport={"width": 1280, "height": 700})
    page.goto(f"{server}/problems/simple_pendulum")
    page.locator("#answer").fill("a*theta'' + a*g = 0")
    page.wait_for_selector("#preview .warn math")
    warn = page.locator("#preview .warn")
    assert warn.locator("math").count() == 2 and warn.locator("msup").count() == 3
    assert "^" not in warn.inner_text() and "T^-2" not in page.content()
    page.locator("#preview").screenshot(path=str(_shots(tmp_path) / "web_dimensions.png"))


@pytest.mark.slow
def test_teacher_uploads_a_class_and_sees_the_table(server, browser, tmp_path):
    csv = tmp_path / "class.csv"
    csv.write_text("id,question,answer\n"
                   "ada,simple_pendulum,a*theta'' + g*sin(theta) = 0\n"
                   "bob,simple_pendulum,a*theta'' - g*sin(theta) = 0\n"
                   "cy,simple_pendulum,<b>a*theta''</b>\n"
                   "dee,simple_pendulum,a*theta'' - g*sin(theta) = 0\n", encoding="utf-8")
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.goto(f"{server}/teacher")
    page.fill("#token", TOKEN)
    page.click("button[type=submit]")
    page.wait_for_selector("#upload-form")
    page.set_input_files("#csv", str(csv))
    page.click("#upload-form button")
    page.wait_for_selector("#by-student", timeout=60000)
    rows = page.locator("#by-student tr")
    assert rows.count() == 5                                  # a header and four answers
    table = page.inner_text("#by-student")
    assert "<b>a*theta''</b>" in table                        # shown as text, not markup
    assert page.locator("#by-student b").count() == 0
    verdicts = [page.inner_text(f"#by-student tr:nth-child({i}) .pill") for i in range(2, 6)]
    assert verdicts == ["right", "wrong", "invalid", "wrong"]
    # the most common mistake first: bob and dee dropped the same sign
    first = page.inner_text("table:not(#by-student) tr:nth-child(2)")
    assert "wrong sign" in first and "2" in first
    page.screenshot(path=str(_shots(tmp_path) / "web_teacher_page.png"), full_page=True)


@pytest.mark.slow
def test_student_answers_an_assignment_with_their_own_numbers(server, browser, tmp_path):
    import json
    import urllib.request
    body = {"title": "Pendulum homework", "questions": [{"problem": "simple_pendulum"}],
            "students": ["ada"], "per_student_numbers": True, "feedback": "hint",
            "attempts": 3, "deadline": "2040-01-31T23:59:00Z"}
    req = urllib.request.Request(f"{server}/api/assignments", data=json.dumps(body).encode(),
                                 headers={"Authorization": f"Bearer {TOKEN}",
                                          "Content-Type": "application/json"})
    made = json.loads(urllib.request.urlopen(req, timeout=30).read())
    url = made["students"]["ada"]["url"]
    assert "#token=" in url

    page = browser.new_page(viewport={"width": 1100, "height": 900})
    page.goto(url)
    page.wait_for_selector("#numbers tr:nth-child(3)")
    assert page.inner_text("#title") == "Pendulum homework"
    rows = [r.split("\t") for r in page.inner_text("#numbers").splitlines()]
    numbers = {r[0]: r[1] for r in rows}
    assert set(numbers) == {"M", "a", "g"} and ["g", numbers["g"], "m s⁻²"] in rows
    assert "3 of 3 attempts left" in page.inner_text("#question-0 .attempts")

    # a wrong sign at the `hint` level: the term is named, its correction is not
    page.fill("#answer-0", f"{numbers['a']}*theta'' - {numbers['g']}*sin(theta) = 0")
    page.click("#submit-0")
    page.wait_for_selector("#feedback-0 .pill.wrong")
    assert "has the wrong sign" in page.inner_text("#feedback-0")
    assert "it is `" not in page.inner_text("#feedback-0")
    page.wait_for_selector("#question-0 .attempts:has-text('2 of 3')")

    page.fill("#answer-0", f"{numbers['a']}*theta'' + {numbers['g']}*sin(theta) = 0")
    page.click("#submit-0")
    page.wait_for_selector("#feedback-0 .pill.right")
    page.wait_for_selector("#score:has-text('100%')")
    assert "1 of 3 attempts left" in page.inner_text("#question-0 .attempts")
    page.screenshot(path=str(_shots(tmp_path) / "web_student_assignment.png"), full_page=True)

    # without the token the page says what to do, and shows nothing of ada's
    page.goto(url.split("#")[0])
    page.wait_for_selector("#status:has-text('no token')")
    assert page.locator("#numbers tr").count() == 0
