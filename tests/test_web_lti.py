"""LTI 1.3 against a learning platform simulated here: its RSA key and JWKS, the OIDC login,
a signed launch, the token endpoint (which checks the tool's signed client assertion against
the tool's public key) and the AGS score endpoint, all behind a ``requests`` transport adapter
(no network).  Hostile launches first: a forged signature, a replayed or missing state, a
wrong nonce, an unknown assignment, a server without LTI."""
from __future__ import annotations

import json
import time
import uuid
from urllib.parse import parse_qs, urlparse

import pytest

pytest.importorskip("starlette")
pytest.importorskip("pylti1p3")
jwt = pytest.importorskip("jwt")
requests = pytest.importorskip("requests")
from cryptography.hazmat.primitives import serialization  # noqa: E402
from cryptography.hazmat.primitives.asymmetric import rsa  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

from dualmech.web import create_app  # noqa: E402

TOKEN = "lti-teacher-token-for-tests"
AUTH = {"Authorization": f"Bearer {TOKEN}"}
ISS = "https://lms.example"
CLIENT = "dualmech-tool"
LINEITEM = "https://lms.example/api/lti/courses/1/line_items/7"
LTI = "https://purl.imsglobal.org/spec/lti/claim/"
AGS_SCOPES = ["https://purl.imsglobal.org/spec/lti-ags/scope/score",
              "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem"]
LEARNER = "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"


def _key():
    return rsa.generate_private_key(public_exponent=65537, key_size=2048)


def _pem(key, private: bool) -> bytes:
    if private:
        return key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                                 serialization.NoEncryption())
    return key.public_key().public_bytes(serialization.Encoding.PEM,
                                         serialization.PublicFormat.SubjectPublicKeyInfo)


class Platform(requests.adapters.BaseAdapter):
    """The learning platform's HTTP side, as a transport adapter of a requests session."""

    def __init__(self, tool_public_pem: bytes):
        super().__init__()
        self.key, self.kid = _key(), "platform-key-1"
        self.tool_public = tool_public_pem
        self.issued: set = set()
        self.scores: list = []
        self.calls: list = []

    def jwks(self) -> dict:
        jwk = json.loads(jwt.algorithms.RSAAlgorithm.to_jwk(self.key.public_key()))
        return {"keys": [dict(jwk, kid=self.kid, alg="RS256", use="sig")]}

    def id_token(self, nonce: str, assignment: str, key=None, **changes) -> str:
        now = int(time.time())
        claims = {"iss": ISS, "aud": CLIENT, "sub": "lms-user-42", "iat": now,
                  "exp": now + 300, "nonce": nonce,
                  LTI + "deployment_id": "deployment-1",
                  LTI + "message_type": "LtiResourceLinkRequest",
                  LTI + "version": "1.3.0", LTI + "roles": [LEARNER],
                  LTI + "resource_link": {"id": "link-1"},
                  LTI + "target_link_uri": "http://testserver/lti/launch",
                  LTI + "custom": {"assignment": assignment},
                  "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint": {
                      "scope": AGS_SCOPES, "lineitem": LINEITEM}}
        claims.update(changes)
        return jwt.encode(claims, key or self.key, algorithm="RS256",
                          headers={"kid": self.kid})

    def send(self, request, **kwargs):
        self.calls.append((request.method, request.url))
        r = requests.Response()
        r.status_code, r.url, r.request = 200, request.url, request
        r.headers["Content-Type"] = "application/json"
        if request.method == "GET" and request.url == f"{ISS}/jwks":
            body = self.jwks()
        elif request.method == "POST" and request.url == f"{ISS}/token":
            form = parse_qs(request.body if isinstance(request.body, str)
                            else request.body.decode())
            claims = jwt.decode(form["client_assertion"][0], self.tool_public,
                                algorithms=["RS256"], audience=f"{ISS}/token")
            assert claims["iss"] == claims["sub"] == CLIENT
            assert set(form["scope"][0].split()) == set(AGS_SCOPES)
            token = uuid.uuid4().hex
            self.issued.add(token)
            body = {"access_token": token, "token_type": "bearer", "expires_in": 3600}
        elif request.method == "POST" and request.url == LINEITEM + "/scores":
            assert request.headers["Authorization"].split()[1] in self.issued
            assert request.headers["Content-Type"] == "application/vnd.ims.lis.v1.score+json"
            self.scores.append(json.loads(request.body))
            body = {}
        else:
            r.status_code, body = 404, {"error": "not here"}
        r._content = json.dumps(body).encode()
        return r

    def close(self):
        pass


@pytest.fixture
def lms(tmp_path):
    tool = _key()
    (tmp_path / "tool-private.pem").write_bytes(_pem(tool, True))
    (tmp_path / "tool-public.pem").write_bytes(_pem(tool, False))
    (tmp_path / "lti.json").write_text(json.dumps({ISS: [{
        "default": True, "client_id": CLIENT, "auth_login_url": f"{ISS}/auth",
        "auth_token_url": f"{ISS}/token", "key_set_url": f"{ISS}/jwks",
        "deployment_ids": ["deployment-1"], "private_key_file": "tool-private.pem",
        "public_key_file": "tool-public.pem"}]}))
    platform = Platform(_pem(tool, False))
    session = requests.Session()
    session.mount(ISS, platform)
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, workers=1, rates={},
                     grade_seconds=5.0)
    with TestClient(app) as c:
        app.state.server.lti.requests_session = session
        made = c.post("/api/assignments", json={
            "title": "Pendulum", "questions": [{"problem": "simple_pendulum"}],
            "students": ["ada"], "per_student_numbers": True}, headers=AUTH).json()
        yield c, platform, made["id"]


def _login(c) -> tuple[str, str]:
    """The OIDC login as the platform starts it; ``(state, nonce)`` of the redirect."""
    r = c.get("/lti/login", params={"iss": ISS, "login_hint": "lms-user-42",
                                     "target_link_uri": "http://testserver/lti/launch",
                                     "lti_message_hint": "m", "client_id": CLIENT},
              follow_redirects=False)
    assert r.status_code == 302, r.text
    where = urlparse(r.headers["location"])
    assert f"{where.scheme}://{where.netloc}{where.path}" == f"{ISS}/auth"
    q = parse_qs(where.query)
    assert q["redirect_uri"] == ["http://testserver/lti/launch"] and q["client_id"] == [CLIENT]
    return q["state"][0], q["nonce"][0]


def _launch(c, state, id_token, origin=ISS):
    return c.post("/lti/launch", data={"state": state, "id_token": id_token},
                  headers={"Origin": origin}, follow_redirects=False)


def test_forged_stale_and_misdirected_launches_are_refused(lms):
    c, platform, aid = lms
    state, nonce = _login(c)
    r = _launch(c, state, platform.id_token(nonce, aid, key=_key()))          # another key
    assert r.status_code == 403 and r.json()["error"] == (
        "LTI launch refused: Can't decode id_token: Signature verification failed")
    state, nonce = _login(c)
    r = _launch(c, state, platform.id_token(nonce, aid, exp=int(time.time()) - 60))
    assert r.status_code == 403 and "Signature has expired" in r.json()["error"]
    state, nonce = _login(c)
    r = _launch(c, "not-the-state", platform.id_token(nonce, aid))
    assert r.status_code == 403 and "State not found" in r.json()["error"]
    state, _ = _login(c)
    r = _launch(c, state, platform.id_token("another-nonce", aid))
    assert r.status_code == 403 and "nonce" in r.json()["error"].lower()
    state, nonce = _login(c)
    r = _launch(c, state, platform.id_token(nonce, aid, **{LTI + "deployment_id": "other"}))
    assert r.status_code == 403 and "Unable to find deployment" in r.json()["error"]
    state, nonce = _login(c)
    r = _launch(c, state, platform.id_token(nonce, "no-such-assignment"))
    assert r.status_code == 404 and "custom parameter assignment" in r.json()["error"]
    state, nonce = _login(c)
    r = _launch(c, state, "not.a.jwt")
    assert r.status_code == 403
    r = c.get("/lti/login", params={"iss": "https://other.example", "login_hint": "x",
                                     "target_link_uri": "http://testserver/lti/launch"},
              follow_redirects=False)
    assert r.status_code == 400 and "LTI login refused" in r.json()["error"]
    r = c.get("/lti/login", params={"iss": ISS, "login_hint": "x",
                                     "target_link_uri": "https://evil.example/"},
              follow_redirects=False)
    assert r.status_code == 400
    assert platform.scores == []


def test_without_a_registration_lti_is_not_served(tmp_path):
    app = create_app(["simple_pendulum"], data=tmp_path, token=TOKEN, workers=1)
    with TestClient(app) as c:
        r = c.post("/lti/launch", data={"state": "s", "id_token": "t"})
        assert r.status_code == 404 and "no lti.json" in r.json()["error"]
        assert c.get("/lti/jwks").status_code == 404


@pytest.mark.slow
def test_a_learner_launched_from_the_platform_answers_and_the_score_goes_back(lms):
    c, platform, aid = lms
    jwks = c.get("/lti/jwks").json()
    assert jwks["keys"][0]["kty"] == "RSA"                       # the tool's key, public
    state, nonce = _login(c)
    r = _launch(c, state, platform.id_token(nonce, aid))
    assert r.status_code == 303, r.text
    where = r.headers["location"]
    assert where.startswith(f"/assignments/{aid}#token=")
    token = where.split("#token=")[1]
    me = c.get(f"/api/assignments/{aid}/me", headers={"Authorization": f"Bearer {token}"})
    me = me.json()
    assert me["student"] == "lms-user-42" and set(me["numbers"]) == {"M", "a", "g"}
    n = me["numbers"]
    r = c.post(f"/api/assignments/{aid}/answers", json={
        "question": 0, "answer": f"{n['a']}*theta'' + {n['g']}*sin(theta) = 0"},
        headers={"Authorization": f"Bearer {token}"})
    assert r.json()["status"] == "right" and r.json()["platform"] == "sent"
    assert len(platform.scores) == 1
    score = platform.scores[0]
    assert (score["scoreGiven"], score["scoreMaximum"], score["userId"]) == \
        (100.0, 100, "lms-user-42")
    assert score["gradingProgress"] == "FullyGraded"
    # a second launch keeps the numbers and rotates the token
    state, nonce = _login(c)
    again = _launch(c, state, platform.id_token(nonce, aid)).headers["location"]
    new = again.split("#token=")[1]
    assert new != token
    assert c.get(f"/api/assignments/{aid}/me",
                 headers={"Authorization": f"Bearer {token}"}).status_code == 401
    assert c.get(f"/api/assignments/{aid}/me",
                 headers={"Authorization": f"Bearer {new}"}).json()["numbers"] == n
    # an instructor's launch goes to the teacher page
    state, nonce = _login(c)
    r = _launch(c, state, platform.id_token(nonce, aid, **{LTI + "roles": [
        "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"]}))
    assert r.status_code == 303 and r.headers["location"] == "/teacher"
