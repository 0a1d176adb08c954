"""Shared test settings: hypothesis profiles.

* ``dev`` (default): random examples, no deadline (sympy's first call of anything is slow).
* ``ci``: the same, derandomized, so a CI run is reproducible; chosen when ``CI`` is set.

``HYPOTHESIS_PROFILE=name`` overrides the choice.
"""
from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

settings.register_profile("dev", deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("ci", deadline=None, derandomize=True, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE")
                      or ("ci" if os.environ.get("CI") else "dev"))
