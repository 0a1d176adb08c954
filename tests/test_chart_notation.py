"""Charts speak textbook: every legend, axis label and panel text of a drawn figure names a
coordinate or reaction by its symbol (matplotlib mathtext from the problem's names, theta1 as
$\\theta_{1}$), never by the raw Python name.  The figures are inspected as matplotlib objects
(their texts), not as images; each is also saved, so a label mathtext cannot parse fails here."""
import re

import pytest

import dualmech.numeric.charts as charts
from dualmech.model.notation import mathtext
from dualmech.problems import get
from dualmech.report.charts import trajectory_chart


@pytest.fixture
def figures(monkeypatch, tmp_path):
    """Every figure handed to ``save`` (which still writes it: mathtext must render)."""
    drawn = []
    real = charts.save

    def keep(fig, stem, *args, **kwargs):
        drawn.append(fig)
        return real(fig, tmp_path / stem.name, *args, **kwargs)

    monkeypatch.setattr(charts, "save", keep)
    return drawn


def _texts(fig) -> list[str]:
    """Legend entries and titles, axis labels, texts and annotations of every panel."""
    out = []
    for ax in fig.axes:
        out += [ax.get_xlabel(), ax.get_ylabel(), ax.get_title()]
        out += [t.get_text() for t in ax.texts]
        if ax.get_legend():
            out += [t.get_text() for t in ax.get_legend().get_texts()]
    for leg in fig.legends:
        out += [t.get_text() for t in leg.get_texts()]
    out += [t.get_text() for t in fig.texts]       # the caption: the scene and what is said
    return [t for t in out if t]


def _raw(texts, names) -> list[str]:
    """Texts where a raw name shows outside mathtext (``$...$``)."""
    words = re.compile(r"(?<![\w\\])(" + "|".join(map(re.escape, names)) + r")(?!\w)")
    return [t for t in texts if words.search(re.sub(r"(?<!\\)\$.*?(?<!\\)\$", "", t))]


def _names(problem) -> list[str]:
    return [c.name for c in problem.all_coordinates()] + [r.name for r in problem.reactions]


@pytest.mark.parametrize("name", ["toy_car", "compound_double_pendulum", "wheel_on_pivot"])
def test_trajectory_chart_names_every_curve_by_its_symbol(figures, tmp_path, name):
    p = get(name)
    chart = trajectory_chart(p, tmp_path, 1.0)
    assert not chart.error and len(figures) == 1
    texts = _texts(figures[0])
    assert _raw(texts, _names(p)) == []
    if name == "toy_car":     # theta, phi, F_r as the source writes them
        legends = [[t.get_text() for t in ax.get_legend().get_texts()]
                   for ax in figures[0].axes]
        assert legends == [[r"$\theta$", r"$\phi$"], [r"$F_{r}$"]]
    elif name == "compound_double_pendulum":
        assert {r"$\theta_{1}$", r"$\theta_{2}$", r"$R_{x}$", r"$R_{y}$"} <= set(texts)
    else:   # the constant tilt drawn flat (not an empty box); the zero reactions said
        assert any(r"$\phi$ = 0.6 rad" in t for t in texts)
        assert any(r"$F_{x}$, $F_{y}$, $R_{x}$" in t for t in texts)
        # the caption's text is the page's one-line text, no markup; its HTML typesets
        # each name (F_y with a real subscript, where unicode has no subscript y)
        assert "\u03c6 stays at 0.6 rad (drawn flat: nothing on its panel varies)" in \
            chart.notes
        assert not any("$" in n for n in chart.notes)
        assert len(chart.notes_html) == len(chart.notes)
        fy = "<msub><mi>F</mi><mi>y</mi></msub>"
        assert fy in chart.notes_html[1] and chart.notes_html[1].count("<math") == 5
        assert chart.notes_html[1].endswith("</math> = 0 along the whole motion (not drawn)")


def test_the_page_caption_typesets_the_names(tmp_path):
    from dualmech.verify.check import compare
    from dualmech.report import write_report
    written = write_report([compare(get("falling_container"))], tmp_path, 1.0, progress=False)
    page = written.html.read_text(encoding="utf-8")
    # the chart's caption, then the animation's (one sentence on the arrows)
    caption, animation = re.findall(r"<figcaption>(.*?)</figcaption>", page, flags=re.S)
    assert animation.startswith("The motion, each reaction force an arrow")
    # H1, H2 vanish along the whole motion (the guides push nothing sideways)
    h1 = "<msub><mi>H</mi><mi>1</mi></msub>"
    assert caption.startswith("Simulated for t in [0, ") and h1 in caption
    assert caption.endswith("</math> = 0 along the whole motion (not drawn).")
    assert "H1" not in caption and "H\u2081" not in caption


def test_atlas_axes_are_the_coordinates_symbols(figures, tmp_path):
    from dualmech.numeric.studies.atlas import atlas
    p = get("toy_car")
    atlas(p, sections=("singularities", "linearisation"), progress=False).write(tmp_path)
    texts = [t for fig in figures for t in _texts(fig)]
    assert _raw(texts, _names(p) + ["kappa"]) == []
    assert {r"$\theta$ [rad]", r"$\phi$ [rad]", r"degeneracy $\kappa$ [1]"} <= set(texts)
    assert any(t.startswith(r"amplitude of $\theta$") or t.startswith(r"amplitude of $\phi$")
               for t in texts)


def test_floquet_legends_write_the_rates_with_dots(figures, tmp_path):
    # the orbits are named by their state at t = 0: theta and its rate, theta' in the data
    from dualmech.numeric.studies.atlas import atlas
    atlas(get("kapitza_pendulum"), sections=("floquet",), progress=False).write(tmp_path)
    (fig,) = figures
    texts = _texts(fig)
    assert _raw(texts, ["theta", "mu", "alpha", "Omega"]) == [] and \
        not any("theta'" in t for t in texts)
    # the Mathieu panels: alpha and Omega typeset, the DLMF curves a_0, b_1, ...
    assert r"$\alpha$ [1]" in texts and r"$a_0(q)$, DLMF 28.6 series" in texts
    assert any(r"$a^2\Omega^2 = 2gl$" in t for t in texts)
    orbits = [t for t in texts if "largest" in t]
    assert orbits and all(t.startswith(r"$\theta$ = ") and r", $\dot{\theta}$ = 0: largest "
                          r"$|\mu|$ = " in t for t in orbits)


def test_fidelity_legend_names_the_neglected_reaction(figures, tmp_path):
    from dualmech.numeric.studies.fidelity import ladder
    ladder(get("mobile_robot")).write(tmp_path)
    (fig,) = figures
    (label,) = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert label == r"simplified: pivot reaction $H$ neglected in the base's balance"


def test_work_precision_labels_typeset_the_drifts(figures, tmp_path):
    from dualmech.numeric.studies.workprecision import work_precision
    wp = work_precision(get("toy_car"), duration=0.5, tolerances=(1e-6,), steps=(),
                        methods=("DOP853",), models=("lagrange", "multiplier"), progress=False)
    wp.write(tmp_path)
    texts = [t for fig in figures for t in _texts(fig)]
    assert "energy drift $|E - E_0|$ [N m]" in texts
    assert not any("E0" in t for t in texts)


@pytest.mark.parametrize("problem", ["toy_car", "n_link_rigid_pendulum", "wheel_on_pivot",
                                     "pendulum_on_mass", "inertia_wheel_pendulum"])
def test_every_catalogue_name_is_valid_mathtext(problem):
    # each coordinate (and its rates) and reaction name parses, as a legend would draw it
    from matplotlib.mathtext import MathTextParser
    parser = MathTextParser("path")
    for n in _names(get(problem)):
        for order in (0, 1, 2):
            for notation in ("dots", "primes"):
                s = mathtext(n, order, notation)
                assert s.startswith("$") and "_" not in s.strip("$").replace("_{", "")
                parser.parse(s)
