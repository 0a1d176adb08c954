"""The report (dualmech.report): what the charts and pages say, checked against hand facts.

Hand facts used: the falling container's guides push nothing sideways (H1 = H2 = 0, from the
free-body diagrams in problems/falling_container.py); the pendulum-on-mass's sliding mass
moves vertically only, so its horizontal balance is F_Rx - F_N = 0 (F_N = F_Rx exactly); the
block on the wedge reaches the end of its 2 m incline at t = sqrt(2 * 0.8 / q1'').
"""
import re
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from dualmech import coordinate, t
from dualmech.verify.check import compare
from dualmech.report import write_report
from dualmech.report.charts import SAME, group_curves, trajectory_chart
from dualmech.report.mathml import equation
from dualmech.problems import get


@pytest.fixture(scope="module")
def charts(tmp_path_factory):
    out = tmp_path_factory.mktemp("charts")
    return out, {n: trajectory_chart(get(n), out, 5.0)
                 for n in ("falling_container", "pendulum_on_mass", "block_on_wedge")}


def test_zero_reactions_are_named_not_drawn(charts):
    _, c = charts
    assert "H₁, H₂ = 0 along the whole motion (not drawn)" in c["falling_container"].notes


def test_coinciding_reactions_are_drawn_once_and_named(charts):
    _, c = charts
    assert "F_N and F_Rx coincide along the whole motion (drawn once)" in \
        c["pendulum_on_mass"].notes


def test_the_wedge_chart_stops_at_the_end_of_the_incline(charts):
    _, c = charts
    m, M, g, al = 1.0, 3.0, 9.81, 0.6
    acc = (M + m) * g * np.sin(al) / (M + m * np.sin(al)**2)
    chart = c["block_on_wedge"]
    assert chart.span[1] == pytest.approx(np.sqrt(2 * 0.8 / acc), abs=64 * np.finfo(float).eps)
    assert "q1 leaves its declared range [0, 2]" in chart.notes[0]
    assert all(p.stat().st_size > 0 for p in chart.paths)
    assert sorted(p.suffix for p in chart.paths) == [".png", ".svg"]


def test_curves_are_the_same_only_within_the_stated_fraction():
    base = np.sin(np.linspace(0, 3, 50))
    near = base + 0.5 * SAME
    far = base + 2 * SAME
    assert group_curves(["a", "b", "c"], [base, near, far], 1.0) == [["a", "b"], ["c"]]


def test_rates_are_printed_with_dots():
    th = coordinate("theta1")
    text = equation(th.diff(t, 2) + sp.sin(th), 0)
    assert "<msub><mi>&#952;&#776;</mi><mi>1</mi></msub>" in text   # theta, two dots, sub 1
    assert text.startswith('<math xmlns="http://www.w3.org/1998/Math/MathML"')


class _Broken:
    """A stand-in for a problem that could not be compared (what the CLI passes on)."""

    def __init__(self, problem):
        self.problem, self.equivalent, self.method, self.reactions = problem, False, "error", {}

    def __str__(self):
        return f"{self.problem.name}: could not be compared -- ValueError: broken on purpose"


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    comparisons = [compare(get("block_on_wedge")), _Broken(get("falling_container"))]
    return out, comparisons, write_report(comparisons, out, 5.0, progress=False)


def test_html_page_is_self_contained_and_typeset(report):
    out, comparisons, written = report
    page = written.html.read_text(encoding="utf-8")
    assert "<script" not in page.lower()
    assert re.findall(r'(?:src|href)="(?!data:|#)', page) == []   # nothing to fetch
    wedge = comparisons[0]
    ref = wedge.problem.model("lagrange")
    assert page.count("<math ") >= len(ref.equations) + len(wedge.reactions)
    assert page.count('src="data:image/png;base64,') == 2


def test_verdicts_and_printed_answers_are_in_tables(report):
    _, comparisons, written = report
    page = written.html.read_text(encoding="utf-8")
    wedge = comparisons[0]
    assert '<td class="yes">yes</td>' in page and '<td class="NO">NO</td>' in page
    for p in wedge.published:
        assert f'<td class="{p.verdict}">{p.verdict.upper()}</td>' in page
    md = written.markdown.read_text()
    assert "| [block_on_wedge](#block_on_wedge) | 2 | yes |" in md
    assert "![block_on_wedge: simulated motion and reactions](block_on_wedge_reactions.png)" \
        in md
    assert "could not be compared -- ValueError: broken on purpose" in md


def test_unwritable_directory_raises_oserror(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(OSError):
        write_report([], Path(blocker / "sub"), 5.0)


def test_a_panel_of_constant_reactions_is_not_drawn_but_said(charts):
    # regression: the wedge's force panel was an empty box with text in it.  Both normal
    # forces are constant (the wedge's acceleration is constant); by hand, N1 = m M g
    # cos(al) / (M + m sin^2 al) with m = 1 kg, M = 3 kg, al = 0.6 rad
    _, c = charts
    chart = c["block_on_wedge"]
    assert chart.panels == ["m"]
    m, M, g, al = 1.0, 3.0, 9.81, 0.6
    n1 = m * M * g * np.cos(al) / (M + m * np.sin(al)**2)
    assert f"$N_{{1}}$ = {n1:.4g} N" in chart.caption
    assert chart.caption.startswith(r"$m$ = 1 kg, $M$ = 3 kg, $g$ = 9.81 m/s^2, $\alpha$ = "
                                    r"0.6 rad; from $q_{1}$ = 1.2 m, $q_{2}$ = 0.2 m")


def test_kapitza_chart_shows_it_held_up_and_falling_when_shaken_too_slowly(tmp_path):
    # Landau & Lifshitz section 30 problem 1: the inverted position is stable when
    # a^2 Omega^2 > 2 g l.  Defaults: 0.01^2 (80 pi)^2 = 6.3 > 3.9 m^2/s^2 (held up); the
    # declared contrast scene: 0.01^2 (40 pi)^2 = 1.6 < 3.9 (it falls)
    from dualmech.numeric.simulation import simulate
    problem = get("kapitza_pendulum")
    (lo, hi) = problem.coordinate_info(problem.coordinates[0].function).range
    assert lo < -np.pi and np.pi < hi                 # the inverted position is in range
    held = simulate(problem, t_span=(0.0, 5.0), samples=2001)
    assert np.abs(held.q[0] - np.pi).max() < 0.3
    (slow,) = problem.chart_scenes
    assert 0.01**2 * slow.params["Omega"]**2 < 2 * 9.81 * 0.2
    fell = simulate(problem, t_span=(0.0, 5.0), samples=2001, params=slow.params)
    assert np.abs(fell.q[0] - np.pi).max() > 2.0
    chart = trajectory_chart(problem, tmp_path, 5.0)
    assert "Dashed: shaken too slowly" in chart.caption and r"$\Omega$ = 251.3 1/s" in \
        chart.caption
    # no aliasing of the 40 Hz tension: at least 24 samples per period of the drive
    assert chart.samples >= 24 * 5.0 / (2 * np.pi / (80 * np.pi))
