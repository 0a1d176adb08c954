"""Shared test settings: hypothesis profiles, and each catalogue problem's comparison.

* ``dev`` (default): random examples, no deadline (sympy's first call of anything is slow).
* ``ci``: the same, derandomized, so a CI run is reproducible; chosen when ``CI`` is set.

``HYPOTHESIS_PROFILE=name`` overrides the choice.

Tests that take seconds of CPU each are marked ``@pytest.mark.slow`` (registered in
pyproject.toml): ``python -m pytest -n 2 -q -m "not slow"`` is the quick run, and CI runs all.
"""
from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, settings

settings.register_profile("dev", deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("ci", deadline=None, derandomize=True, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE")
                      or ("ci" if os.environ.get("CI") else "dev"))


@pytest.fixture(scope="session")
def compared():
    """``compared(name)``: :func:`dualmech.compare` of the catalogue problem ``name``, computed
    once per test process and shared by the catalogue's checks and each problem's own tests."""
    from dualmech import compare
    from dualmech.problems import get
    cache = {}

    def comparison(name: str):
        if name not in cache:
            cache[name] = compare(get(name))
        return cache[name]

    return comparison
