"""Printed claims about a steady motion's stability (eigenvalues at a speed, critical speeds)
are judged like every printed answer: right, wrong with the computed value, or not judged
with the reason.  Reference values: the rolling disk's ``v_c = sqrt(g r / 3)`` and lean
eigenvalues ``+-sqrt(4 (g r - 3 v^2) / (5 r^2))``, derived by hand in
``problems/rolling_disk.py``."""
import pytest
import sympy as sp

from dualmech import Published
from dualmech.problems import get
from dualmech.verify.published import check_published


def _judged(*claims):
    base = type(get("rolling_disk"))

    class Claimed(base):
        def published(self):
            return list(claims)

    return {v.label: v for v in check_published(Claimed())}


def test_right_claims_are_right():
    out = _judged(Published("v_c", "critical", (1.0,), tolerance=1e-9),
                  Published("at 2", "eigenvalues", (sp.sqrt(80) * sp.I, -sp.sqrt(80) * sp.I),
                            at=2, tolerance=1e-12))
    assert out["v_c"].verdict == "correct"
    assert out["at 2"].verdict == "correct"
    assert "mpmath" in out["v_c"].to_dict()["method"]


def test_a_wrong_critical_speed_is_wrong_with_the_computed_value():
    out = _judged(Published("v_c", "critical", (1.1,), tolerance=1e-6))
    v = out["v_c"]
    assert v.verdict == "wrong"
    # the computed critical speed, sqrt(0.3 * 10 / 3) = 1, is named
    number = float(v.detail.split("changes at v = ")[1].split(",")[0])
    assert abs(number - 1.0) < 1e-9


def test_a_critical_speed_just_outside_its_tolerance_is_wrong():
    assert _judged(Published("v_c", "critical", (1.0 + 2e-9,), tolerance=1e-9)
                   )["v_c"].verdict == "wrong"


def test_wrong_eigenvalues_are_wrong_with_the_computed_ones():
    # sqrt(20) = 4.47213595499958; a slip in the fifth digit is caught
    out = _judged(Published("at 0.5", "eigenvalues", (4.47215, -4.47215), at=0.5,
                            tolerance=1e-9),
                  Published("too many", "eigenvalues", (4.47, -4.47, 1), at=0.5,
                            tolerance=1e-2))
    assert out["at 0.5"].verdict == "wrong"
    assert "4.472135955" in out["at 0.5"].detail
    assert out["too many"].verdict == "wrong"
    assert "2 nonzero eigenvalues, not 3" in out["too many"].detail


def test_a_problem_without_a_steady_motion_leaves_the_claim_unchecked():
    base = type(get("simple_pendulum"))

    class Claimed(base):
        def published(self):
            return [Published("crit", "critical", (1.0,), tolerance=1e-6)]

    (v,) = check_published(Claimed())
    assert v.verdict == "unchecked"
    assert "declares no steady motion" in v.detail


@pytest.mark.parametrize("kwargs, message", [
    (dict(kind="critical", printed=(1.0,)), "tolerance"),
    (dict(kind="critical", printed=(1.0, 2.0), tolerance=1e-3), "one value"),
    (dict(kind="eigenvalues", printed=(1.0,), tolerance=1e-3), "`at`"),
    (dict(kind="eigenvalues", printed=(sp.Symbol("v"),), at=1, tolerance=1e-3), "numbers"),
])
def test_malformed_claims_are_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        Published("claim", **kwargs)
