"""Every notebook in notebooks/ runs from top to bottom without an error (nbclient).

Each notebook derives its problem both ways, compares them, recovers the reactions,
simulates, and shows a work-precision chart or a stability finding; the outputs checked here
are the ones a reader relies on (verdicts, the detected breaks), not the pictures.  The
notebooks are kept small: the whole file runs in well under a minute on one core.
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
    "kane_toy_car": ["all derivations agree", "`kane` disagrees with", "cos(theta(t))**2"],
}


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


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs_and_shows_its_findings(path):
    book = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(book, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(path.parent.parent)}})
    client.execute()
    text = "".join(_text(c) for c in book.cells if c.cell_type == "code")
    for phrase in EXPECTED[path.stem]:
        assert phrase in text, f"{path.name} does not show {phrase!r}"
    images = sum("image/png" in o.get("data", {}) for c in book.cells if c.cell_type == "code"
                 for o in c.get("outputs", []))
    assert images == (1 if any("work_precision" in c.source for c in book.cells) else 0)
