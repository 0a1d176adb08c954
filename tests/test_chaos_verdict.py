"""Chaos is claimed only for chaotic motion (dualmech.numeric.studies.regimes.chaos).

References: the toy car is a spherical pendulum written in other angles (``T = m R^2
(theta'^2 + phi'^2 cos^2 theta)/2``, ``V = -m g R cos theta cos phi``: a point on a sphere
under gravity), which is integrable (energy and the angular momentum about the vertical), so
it has no positive Lyapunov exponent; a shear ``x' = y, y' = 0`` separates nearby states
like ``t`` (finite-time exponent ``ln(t)/t`` by hand); a saddle ``x' = x/2, y' = -y`` has the
exponent 1/2 exactly.
"""
import numpy as np
import pytest

from dualmech.numeric.studies.atlas import atlas
from dualmech.numeric.studies.horizon import finite_time_exponents, regular
from dualmech.numeric.studies.regimes import chaos
from dualmech.problems import get

W = (5.0, 10.0, 20.0, 40.0, 80.0)


def test_a_shear_is_regular_and_its_exponents_fall_like_log_t_over_t():
    e = finite_time_exponents(lambda t, y: np.array([y[1], 0.0]), [0.0, 1.0], W, every=1.0)
    # by hand: an offset (a, b) becomes (a + b t, b): it grows like t, so ln(growth) / T
    # falls like ln(T) / T -- 16 times the window, at least 4 times smaller
    assert e[0] > 0 and e[-1] < e[0] / 4
    assert regular(W, e)


def test_a_saddle_is_chaotic_in_this_sense_with_its_exponent():
    e = finite_time_exponents(lambda t, y: np.array([0.5 * y[0], -y[1]]), [1.0, 1.0],
                              (2.0, 4.0, 8.0), transient=2.0)
    assert not regular((2.0, 4.0, 8.0), e)
    assert e[-1] == pytest.approx(0.5, abs=1e-3)


@pytest.fixture(scope="module")
def toy():
    return chaos(get("toy_car"), duration=5.0, tolerances=(1e-4, 1e-6, 1e-8))


def test_the_regular_toy_car_gets_no_chaos_verdict(toy):
    # regression: the section printed positive Lyapunov exponents and `lambda = nan` for it
    assert toy.regular
    assert np.isnan(toy.lyapunov)
    text = str(toy)
    assert "regular motion, no chaos" in text
    assert "chaotic" not in text and "nan" not in text
    # the exponents fall with the window (spherical pendulum: integrable)
    assert toy.exponents[-1] < toy.exponents[0] / 3


@pytest.mark.slow
def test_the_atlas_shows_one_exponent_with_its_window():
    a = atlas(get("compound_double_pendulum"), sections=("chaos",), progress=False)
    text = str(a)
    assert text.count("Lyapunov exponent") == 1
    c, h = a.results["chaos"]
    assert h.lyapunov == c.lyapunov and f"window {W[-1]:g} s" in text
    assert f"Benettin's {c.lyapunov:.3g} 1/s" in text    # the horizons quote the same one
