"""``dualmech serve``: the teacher's token never on the command line, never weak."""
from __future__ import annotations

import os

import pytest

from dualmech.cli.main import main

pytest.importorskip("starlette")


@pytest.fixture
def served(monkeypatch):
    """What ``serve`` was called with (it is not started)."""
    import dualmech.web.server as server
    seen = {}
    monkeypatch.setattr(server, "serve",
                        lambda host, port, specs, **kw: seen.update(kw, specs=specs))
    monkeypatch.delenv("DUALMECH_TOKEN", raising=False)
    return seen


def test_the_token_comes_from_a_private_file_or_the_environment(served, tmp_path,
                                                                monkeypatch):
    f = tmp_path / "token"
    f.write_text("a-long-teacher-token-42\n")
    os.chmod(f, 0o600)
    assert main(["serve", "--problems", "toy_car", "--token-file", str(f)]) == 0
    assert served["token"] == "a-long-teacher-token-42"
    monkeypatch.setenv("DUALMECH_TOKEN", "token-from-the-environment")
    assert main(["serve", "--problems", "toy_car"]) == 0
    assert served["token"] == "token-from-the-environment"
    monkeypatch.delenv("DUALMECH_TOKEN")
    assert main(["serve", "--problems", "toy_car"]) == 0
    assert served["token"] is None                     # the server makes and prints one


def test_a_token_on_the_command_line_or_in_a_readable_file_is_refused(served, tmp_path,
                                                                      capsys):
    assert main(["serve", "--token", "a-long-teacher-token-42"]) == 2
    assert "every user of this machine (`ps`)" in capsys.readouterr().err
    f = tmp_path / "token"
    f.write_text("a-long-teacher-token-42")
    os.chmod(f, 0o644)
    assert main(["serve", "--token-file", str(f)]) == 2
    assert f"chmod 600 {f}" in " ".join(capsys.readouterr().err.split())   # wrapped
    assert main(["serve", "--token-file", str(tmp_path / "missing")]) == 2
    assert "cannot read the token file" in capsys.readouterr().err
    empty = tmp_path / "empty"
    empty.write_text("\n")
    os.chmod(empty, 0o600)
    assert main(["serve", "--token-file", str(empty)]) == 2
    assert "is empty" in capsys.readouterr().err
    assert served == {}


def test_a_weak_token_stops_the_server_before_it_starts(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("DUALMECH_TOKEN", "s3cret")
    assert main(["serve", "--problems", "toy_car", "--port", "8999",
                 "--data", str(tmp_path)]) == 2
    assert "the teacher token is too weak (6 characters)" in capsys.readouterr().err
