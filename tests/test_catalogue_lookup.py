"""Looking a problem up by name twice reads the catalogue again where it changed: a renamed or
edited module is never answered from what an earlier look-up found."""
import textwrap

import pytest

import dualmech.problems as catalogue


def _module(folder, stem: str, name: str, title: str) -> None:
    (folder / f"{stem}.py").write_text(textwrap.dedent(f'''
        class Thing:
            name = "{name}"
            title = "{title}"
            source = "000: example"
        '''), encoding="utf-8")


@pytest.fixture
def folder(tmp_path, monkeypatch):
    monkeypatch.setattr(catalogue, "_HERE", tmp_path)
    monkeypatch.setattr(catalogue, "_FOUND", {})
    monkeypatch.setattr(catalogue, "_PARSED", {})
    return tmp_path


def test_a_second_lookup_sees_an_edited_module(folder):
    _module(folder, "thing", "thing", "First title")
    assert catalogue.module_of("thing").title == "First title"
    _module(folder, "thing", "thing", "A longer second title")   # size changes with it
    assert catalogue.module_of("thing").title == "A longer second title"


def test_a_renamed_problem_is_not_found_under_its_old_name(folder):
    _module(folder, "thing", "thing", "T")
    assert catalogue.module_of("thing").module == "thing"
    _module(folder, "thing", "other", "T")
    with pytest.raises(KeyError, match="no problem named 'thing'"):
        catalogue.module_of("thing")
    assert catalogue.module_of("other").name == "other"


def test_a_problem_moved_to_another_module_is_found_there(folder):
    _module(folder, "first", "thing", "T")
    assert catalogue.module_of("thing").module == "first"
    (folder / "first.py").unlink()
    _module(folder, "second", "thing", "T")
    assert catalogue.module_of("thing").module == "second"
