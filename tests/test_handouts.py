"""Handouts (issue 29, point 5): a problem sheet with the student's numbers and no solution, a
solution sheet with both derivations, the reactions and the printed answers' errata; every
string from a problem file or the numbers escaped for LaTeX."""
from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest
import sympy as sp

from dualmech import Lagrangian, Parameter, Problem, coordinate, rate
from dualmech.cli.main import main
from dualmech.model.dimensions import ACCELERATION, ANGLE, LENGTH, MASS
from dualmech.problems import get
from dualmech.report.handouts import (escape, numbers_of, parse_numbers, problem_sheet,
                                      solution_sheet, write_handout)

HOSTILE = r"\input{/etc/passwd}\immediate\write18{rm -rf ~}$x^2$ & 100% #1 _ {} ~ \end{document}"


def _commands(tex: str) -> set:
    """The control words a LaTeX source uses (``\\textbackslash`` counted, ``\\{`` not)."""
    return set(re.findall(r"\\([A-Za-z]+)", tex))


def test_escape_leaves_no_command_and_no_group_of_the_input():
    out = escape(HOSTILE)
    assert not {"input", "immediate", "write", "end"} & _commands(out)
    # every brace left is one escape's own (\textbackslash{}, \{ ...): none is unbalanced
    assert out.count("\\{") == HOSTILE.count("{") and "$" not in out.replace("\\$", "")


def test_problem_sheet_has_the_numbers_and_no_solution():
    tex = problem_sheet(get("toy_car"), {"R": 0.75, "m": 0.3})
    assert "& 0.75 &" in tex and "& 0.3 &" in tex and "& 9.81 &" in tex   # g: the default
    assert r"\theta" in tex and "Figure and sign convention" in tex
    assert "The derivations" not in tex and "Reactions" not in tex and "printed answers" not in tex
    assert r"\ddot" not in tex      # no equation of motion is printed


def test_solution_sheet_has_both_derivations_the_reactions_and_the_errata():
    tex = solution_sheet(get("toy_car"), {"R": 0.75})
    assert "newton" in tex and "lagrange" in tex
    # the track's normal force, derived independently: F_r = m (R phi'^2 cos^2 + R theta'^2
    # + g cos(phi) cos(theta)) (source 001, quiz 1)
    assert r"F_{r} &= m \left(R \dot{\phi}^{2} \cos^{2}{\left(\theta \right)} + R " \
           r"\dot{\theta}^{2} + g \cos{\left(\phi \right)} \cos{\left(\theta \right)}\right)" \
        in tex
    # with R = 0.75, m = 0.2 the theta row is 0.1125 theta'' + ... (R^2 m) and 1.4715 (R g m)
    assert r"0.1125 \ddot{\theta}" in tex and "1.4715" in tex
    assert r"\section*{The printed answers}" in tex and ": correct" in tex


def test_the_errata_of_a_wrong_printed_answer_are_on_the_solution_sheet():
    # read with a horizontal spring and dashpot, the source's printed U, R and equation of
    # motion are right only to first order in theta (tests/test_restrained_pendulum.py)
    tex = solution_sheet(get("restrained_pendulum_horizontal"))
    assert tex.count("erratum") >= 3, tex[-3000:]


def test_numbers_are_read_without_evaluating_and_checked():
    assert parse_numbers("m=1.2, l = 5e-1") == {"m": 1.2, "l": 0.5}
    for bad in ["m=__import__('os')", "m", "m=1+1", "=3"]:
        with pytest.raises(ValueError):
            parse_numbers(bad)
    p = get("simple_pendulum")
    with pytest.raises(ValueError, match="not a parameter"):
        numbers_of(p, {"zz": 1.0})
    with pytest.raises(ValueError, match="outside its declared range"):
        numbers_of(p, {"a": 1e9})
    with pytest.raises(ValueError, match="must be a number"):
        numbers_of(p, {"a": "1.0"})


class _Hostile(Problem):
    """A teacher's file whose names and texts try to run LaTeX."""

    name = "hostile"
    title = HOSTILE
    source = HOSTILE
    summary = HOSTILE

    def __init__(self):
        self.th = coordinate("theta")
        self.m, self.l, self.g = sp.symbols("m l g", positive=True)
        self.odd = sp.Symbol(r"k\input{x}", positive=True)
        self.parameters = (Parameter(self.m, MASS, 1.0, (0.1, 2.0), HOSTILE),
                           Parameter(self.l, LENGTH, 1.0, (0.1, 2.0), "length"),
                           Parameter(self.g, ACCELERATION, 9.81, (1.0, 20.0), "gravity"),
                           Parameter(self.odd, ANGLE, 0.5, (0.0, 1.0), HOSTILE))
        from dualmech import Coordinate
        self.coordinates = (Coordinate(self.th, ANGLE, (-1.0, 1.0), description=HOSTILE),)

    def lagrange(self):
        lg = Lagrangian(coordinates=[self.th], description=HOSTILE)
        lg.kinetic("T", self.m * (self.l * rate(self.th))**2 / 2)
        lg.potential(HOSTILE, -self.m * self.g * self.l * sp.cos(self.th) * (1 + self.odd))
        return lg.equations()


def test_hostile_names_and_texts_are_printed_never_run(tmp_path):
    p = _Hostile()
    for solution in (False, True):
        h = write_handout(p, {r"k\input{x}": 0.25, "m": 1.5}, tmp_path, solution=solution,
                          engine=None)
        tex = h.tex.read_text()
        assert not {"input", "immediate", "write"} & _commands(tex), tex
        assert tex.count(r"\end{document}") == 1 and tex.rstrip().endswith(r"\end{document}")
        assert tex.count(r"\begin{") == tex.count(r"\end{")
        assert "0.25" in tex and "1.5" in tex


def test_pdf_when_a_latex_engine_is_present(tmp_path):
    h = write_handout(get("simple_pendulum"), {"a": 0.5}, tmp_path)
    if shutil.which("pdflatex") is None:
        assert h.pdf is None and "not installed" in h.note
        pytest.skip("pdflatex is not installed: the .tex is checked, the PDF cannot be")
    assert h.pdf is not None and h.pdf.read_bytes()[:4] == b"%PDF", h.note


def test_the_handout_command(tmp_path, capsys):
    assert main(["handout", "simple_pendulum", "--numbers", "a=0.5, M=2", "-o",
                 str(tmp_path), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    tex = Path(out["tex"]).read_text()
    assert Path(out["tex"]).name == "simple_pendulum_problem.tex" and "& 0.5 &" in tex
    assert main(["handout", "simple_pendulum", "--solution", "-o", str(tmp_path)]) == 0
    assert (tmp_path / "simple_pendulum_solution.tex").exists()
    assert main(["handout", "simple_pendulum", "--numbers", "a=oops", "-o",
                 str(tmp_path)]) == 2
    assert "not a number" in capsys.readouterr().err
