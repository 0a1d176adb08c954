"""The install: every package folder is installed, the catalogue is dualmech.problems, and the
test extra names only what the project uses."""
from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    tomllib = pytest.importorskip("tomli")


def _pyproject() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text())


def _setuptools() -> dict:
    return _pyproject()["tool"]["setuptools"]


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


def _names(requirements) -> set:
    """Distribution names of requirement strings, lower case, without extras or versions."""
    return {re.match(r"[A-Za-z0-9_.-]+", r).group().lower() for r in requirements}


#: the test extra's distributions that no file imports, and what uses them
INDIRECT = {"pytest-xdist": "pytest -n (.ci/run)", "ipykernel": "the notebooks' kernel (nbclient)",
            "httpx": "starlette's TestClient before 1.10 (tests/test_web*.py)",
            "httpx2": "starlette's TestClient from 1.10 on (tests/test_web*.py)"}
#: import names that are not the distribution's name
MODULES = {"dask": "distributed"}


def test_every_test_dependency_is_used():
    sources = "\n".join(p.read_text(encoding="utf-8", errors="replace")
                        for folder in ("tests", "dualmech", "bench")
                        for p in (ROOT / folder).rglob("*.py"))
    for dist in _names(_pyproject()["project"]["optional-dependencies"]["test"]) - set(INDIRECT):
        module = re.escape(MODULES.get(dist, dist.replace("-", "_")))
        used = re.search(rf"^\s*(import|from)\s+{module}\b|importorskip\(\"{module}\"",
                         sources, re.M)
        assert used, f"the test extra lists `{dist}`, which nothing here imports: drop it"
