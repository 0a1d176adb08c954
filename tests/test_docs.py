"""The manual in docs/ stays true to the package.

The pages' ``>>>`` examples run as doctests (``--doctest-glob=*.md`` over ``docs/``, see
pyproject.toml); ``.ci/run`` builds the pages with Sphinx, warnings as errors.  What neither
catches is checked here: a table or a list that must name everything the package has.
"""
from __future__ import annotations

import re
from pathlib import Path

import dualmech
from dualmech import problems

DOCS = Path(__file__).resolve().parent.parent / "docs"


def test_catalogue_table_lists_every_declared_problem():
    text = (DOCS / "catalogue.md").read_text(encoding="utf-8")
    table = text.split("# The catalogue", 1)[1].split("\n## ", 1)[0]
    names = {line.split("|")[1].strip() for line in table.splitlines()
             if line.startswith("| ") and not line.startswith(("| problem", "| ---"))}
    assert {d.name for d in problems.declarations()} == names


def test_api_reference_names_every_front_door_export():
    """Every name of ``dualmech.__all__`` is on the API page: in an autosummary list, or
    (the dimensions) named in its text."""
    text = (DOCS / "api.md").read_text(encoding="utf-8")
    listed = set(re.findall(r"^   (\w+)$", text, re.M)) | set(re.findall(r"`(\w+)`", text))
    missing = sorted(set(dualmech.__all__) - listed)
    assert not missing, f"docs/api.md does not name {missing}"


def test_every_page_is_in_the_index_and_every_picture_is_shown():
    index = (DOCS / "index.md").read_text(encoding="utf-8")
    pages = sorted(p.stem for p in DOCS.glob("*.md") if p.stem != "index")
    assert pages and all(re.search(rf"^{p}$", index, re.M) for p in pages), pages
    text = "".join(p.read_text(encoding="utf-8") for p in DOCS.glob("*.md"))
    for picture in DOCS.glob("*.png"):
        assert f"]({picture.name})" in text, f"no page shows {picture.name}"


def test_hypothesis_example_builds_the_problem_once():
    """The example builds the problem outside the test: built inside, every example derives
    the models again and shrinking a failure takes minutes.  (It runs as a doctest.)"""
    text = (DOCS / "writing_a_problem.md").read_text(encoding="utf-8")
    example = text.split("from hypothesis import given", 1)[1].split("```", 1)[0]
    body = example.split("def test_", 1)[1]
    assert "PENDULUM = Pendulum()" in example
    assert "Pendulum()" not in body and "get(" not in body
    assert "test_pendulum_both_ways()" in example
