"""Every notebook in notebooks/ runs from top to bottom without an error (nbclient), and is
stored with its outputs so that it reads online without running.

Each notebook is teaching material: markdown with the mathematics, a sketch of the system
(matplotlib), the problem and its comparison shown with rich display, simulation and a
work-precision chart or a stability finding, and questions to try.  The outputs checked here
are the ones a reader relies on (verdicts, the detected breaks, the sketch).  The notebooks
are kept small: each runs in seconds.
"""
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

NOTEBOOKS = sorted((Path(__file__).resolve().parent.parent / "notebooks").glob("*.ipynb"))
#: What each notebook must print (a verdict or a detection it exists to show).
EXPECTED = {
    "toy_car": ["all derivations agree", "the car leaves the track", "det M = 0"],
    "falling_container": ["all derivations agree", "x2 leaves its declared range",
                          "explicit RK45 costs more than implicit Radau"],
    "block_on_wedge": ["all derivations agree", "q1 leaves its declared range",
                       "every one-sided contact holds"],
    "pendulum_on_mass": ["all derivations agree", "WRONG:", "1 % at amplitude"],
    "mobile_robot": ["all derivations agree", "the pivot reaction H (max |H|"],
    "pendulum_dae": ["all derivations agree", "|g| ~ t^", "largest difference"],
    # a weight with the wrong sign leaves twice the gravity term in each of Kane's rows
    "kane_toy_car": ["all derivations agree", "`kane` disagrees with `lagrange`",
                     "residual after the best combination: -2 R g m sin(\u03b8) cos(\u03c6)",
                     "residual after the best combination: -2 R g m sin(\u03c6) cos(\u03b8)"],
}
#: The notebooks written as teaching material (sketch, typeset comparison, questions to try).
TEACHING = {"toy_car", "falling_container", "block_on_wedge", "pendulum_on_mass",
            "mobile_robot", "pendulum_dae", "kane_toy_car"}


def _text(cell) -> str:
    parts = []
    for o in cell.get("outputs", []):
        if o.get("output_type") == "stream":
            parts.append(o.get("text", ""))
        elif "data" in o:
            parts.append(o["data"].get("text/plain", ""))
    return "".join(parts)


def test_every_family_has_a_notebook():
    assert sorted(p.stem for p in NOTEBOOKS) == sorted(EXPECTED)


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs_and_shows_its_findings(path, monkeypatch):
    monkeypatch.delenv("MPLBACKEND", raising=False)   # the kernel draws inline, as in Jupyter
    book = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(book, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(path.parent.parent)}})
    client.execute()
    text = "".join(_text(c) for c in book.cells if c.cell_type == "code")
    for phrase in EXPECTED[path.stem]:
        assert phrase in text, f"{path.name} does not show {phrase!r}"
    if path.stem not in TEACHING:
        return
    images = sum("image/png" in o.get("data", {}) for c in book.cells if c.cell_type == "code"
                 for o in c.get("outputs", []))
    # the sketch of the system, and the work-precision chart where there is one
    assert images == 1 + any("work_precision" in c.source for c in book.cells)
    html = "".join(o.get("data", {}).get("text/html", "") for c in book.cells
                   if c.cell_type == "code" for o in c.get("outputs", []))
    assert "<math" in html                                  # the comparison, typeset
    assert "Derivative(" not in text and "(t)" not in html


@pytest.mark.parametrize("path", [p for p in NOTEBOOKS if p.stem in TEACHING],
                         ids=[p.stem for p in NOTEBOOKS if p.stem in TEACHING])
def test_notebook_is_teaching_material_stored_with_outputs(path):
    book = nbformat.read(path, as_version=4)
    code = [c for c in book.cells if c.cell_type == "code"]
    markdown = "\n".join(c.source for c in book.cells if c.cell_type == "markdown")
    assert [c.execution_count for c in code] == list(range(1, len(code) + 1))   # run in order
    assert not any(o.get("output_type") == "error" for c in code for o in c.outputs)
    stored_png = sum("image/png" in o.get("data", {}) for c in code for o in c.outputs)
    assert stored_png >= 1                                  # the sketch reads online
    assert "$" in markdown and "## Questions to try" in markdown
