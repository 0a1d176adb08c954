"""Doctests of the catalogue, each module imported once, under its real name.

The repository's ``problems/`` folder installs as ``dualmech.problems``.  Collected as a plain
folder, pytest would import its modules a second time as ``problems.*`` (two copies of every
class, and a top-level ``problems`` that the package is careful never to occupy).  Here the
doctest collector of each catalogue module imports ``dualmech.problems.<module>`` instead.
"""
from __future__ import annotations

import importlib
from pathlib import Path

import pytest
from _pytest.doctest import DoctestModule

_CATALOGUE = Path(__file__).resolve().parent / "problems"


class CatalogueDoctests(DoctestModule):
    """The doctests of one catalogue module, imported as ``dualmech.problems.<module>``."""

    def _getobj(self):
        stem = self.path.stem
        return importlib.import_module("dualmech.problems" if stem == "__init__"
                                       else f"dualmech.problems.{stem}")


@pytest.hookimpl(wrapper=True)
def pytest_collect_file(file_path, parent):
    collected = yield
    if file_path.suffix != ".py" or file_path.resolve().parent != _CATALOGUE:
        return collected
    return [CatalogueDoctests.from_parent(parent, path=file_path)
            if type(c) is DoctestModule else c for c in collected]
