"""The Mathieu stability chart against scipy's characteristic values (an independent code).

``scipy.special.mathieu_a(m, q)`` and ``mathieu_b(m, q)`` are the characteristic values of
``y'' + (a - 2 q cos 2x) y = 0`` (NIST DLMF 28.2, the convention of
:mod:`dualmech.numeric.studies.mathieu`), computed from continued fractions, not by
integrating the equation.  For ``q > 0`` they interlace ``a0 < b1 < a1 < b2 < a2 < b3 < ...``
and the motion is bounded exactly in ``(a0, b1), (a1, b2), (a2, b3), ...`` (DLMF 28.17).
"""
import numpy as np
import pytest
from scipy.special import mathieu_a, mathieu_b

from dualmech.numeric.charts import pyplot
from dualmech.numeric.studies.mathieu import boundary, draw_chart, stable

CURVES = {"a0": lambda q: mathieu_a(0, q), "b1": lambda q: mathieu_b(1, q),
          "a1": lambda q: mathieu_a(1, q), "b2": lambda q: mathieu_b(2, q)}


@pytest.mark.parametrize("name", sorted(CURVES))
@pytest.mark.parametrize("q", [0.05, 0.7, 1.9])
def test_boundary_matches_scipy(name, q):
    # the trace's RK4 error at 1600 steps bounds the curve's (measured: below 2e-10)
    assert boundary(name, q) == pytest.approx(CURVES[name](q), abs=1e-9)


def test_boundary_refuses_where_its_search_would_find_another_curve():
    # regression: at q = 3 the search for a0 returned 19.1 above scipy's a0(3) = -2.36
    with pytest.raises(ValueError, match="another curve"):
        boundary("a0", 3.0)


def _bounded(alpha, q):
    """Stability by the interlacing of scipy's characteristic values (module docstring)."""
    edges = [mathieu_a(0, q)] + [v for m in range(1, 8)
                                 for v in (mathieu_b(m, q), mathieu_a(m, q))]
    inside = int(np.searchsorted(edges, alpha))
    near = min(abs(alpha - e) for e in edges)
    return inside % 2 == 1, near


def test_chart_shading_matches_scipy():
    rng = np.random.default_rng(27)
    alphas, qs = rng.uniform(-2.0, 5.0, 300), rng.uniform(0.05, 3.0, 300)
    shaded = stable(alphas, qs, 240)             # the steps draw_chart shades with
    checked = 0
    for a, q, s in zip(alphas, qs, shaded):
        expected, near = _bounded(a, q)
        if near > 1e-3:                          # on a curve the trace is 2 to rounding
            assert bool(s) == expected, (a, q)
            checked += 1
    assert checked > 280


def test_chart_contour_lies_on_scipy_curves():
    plt = pyplot()
    fig, ax = plt.subplots()
    draw_chart(ax, (0.0, 3.0), (-2.0, 5.0), resolution=121)
    vertices = np.vstack([p.vertices for c in ax.collections if hasattr(c, "get_paths")
                          for p in c.get_paths() if c.get_linewidths()[0] == 0.8
                          and len(p.vertices)])
    plt.close(fig)
    assert len(vertices) > 500
    # the marching-squares line is within a grid cell of a curve (cell 7/120 x 3/120;
    # the curves' slopes here stay below 3)
    tol = 7 / 120 + 3 * 3 / 120
    worst = 0.0
    for q, a in vertices[:: max(1, len(vertices) // 400)]:
        edges = [mathieu_a(0, q)] + [v for m in range(1, 5)
                                     for v in (mathieu_b(m, q), mathieu_a(m, q))]
        worst = max(worst, min(abs(a - e) for e in edges))
    assert worst < tol
    # and every curve inside the window is drawn: a vertex near each at q = 1.5
    for name, f in CURVES.items():
        target = f(1.5)
        if -2.0 < target < 5.0:
            close = vertices[np.abs(vertices[:, 0] - 1.5) < 0.05]
            assert np.abs(close[:, 1] - target).min() < tol, name
