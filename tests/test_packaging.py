"""The install: every package folder is installed, and the catalogue is dualmech.problems."""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    tomllib = pytest.importorskip("tomli")


def _setuptools() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]


def test_every_package_folder_is_installed():
    listed = set(_setuptools()["packages"])
    found = {".".join(p.parent.relative_to(ROOT).parts)
             for p in (ROOT / "dualmech").rglob("__init__.py")}
    assert found - listed == set(), "add these packages to pyproject.toml"
    assert "dualmech.problems" in listed


def test_catalogue_installs_under_dualmech_not_as_top_level_problems():
    assert _setuptools()["package-dir"]["dualmech.problems"] == "problems"
    import dualmech.problems as catalogue
    assert Path(catalogue.__file__).resolve().parent == ROOT / "problems"
    assert catalogue.get("simple_pendulum").name == "simple_pendulum"
    assert type(catalogue.get("toy_car")).__module__ == "dualmech.problems.toy_car"
