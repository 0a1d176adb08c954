r"""Handouts per assignment: a problem sheet for a student and a solution sheet for the teacher.

The **problem sheet** (LaTeX, and PDF when a LaTeX engine is installed) has the statement, the
sign-convention figure of the problem's file, the coordinates to use and the student's own
numbers -- no solution.  The **solution sheet** adds both derivations (every model of the
problem, its equations as derived), the reactions recovered from the direct form, the
reference equations with the student's numbers put in, and the errata of the printed answers
(each printed answer's verdict, checked exactly, :func:`dualmech.verify.published.check_published`).

Everything that comes from a problem file or from the numbers -- titles, descriptions, names,
the figure, values -- is escaped before it reaches LaTeX (:func:`escape`): a name such as
``\input{/etc/passwd}`` is printed, never run.  Symbols are typeset by sympy only when their
names are plain identifiers; any other name is printed as escaped text.  The engine, when
present, runs with ``-no-shell-escape`` under a time limit.

Example
-------
>>> import tempfile
>>> from pathlib import Path
>>> from dualmech.problems import get
>>> with tempfile.TemporaryDirectory() as out:
...     h = write_handout(get("simple_pendulum"), {"a": 0.75}, Path(out), engine=None)
...     text = h.tex.read_text()
>>> h.tex.name, "0.75" in text, "Solution" in text
('simple_pendulum_problem.tex', True, False)
"""
from __future__ import annotations

import math
import re
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

from dualmech.model.sketch import sketch_of

__all__ = ["write_handout", "problem_sheet", "solution_sheet", "parse_numbers", "escape",
           "Handout", "numbers_of"]

_SPECIAL = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
            "#": r"\#", "%": r"\%", "_": r"\_", "^": r"\textasciicircum{}",
            "~": r"\textasciitilde{}", "<": r"\textless{}", ">": r"\textgreater{}",
            "|": r"\textbar{}", '"': r"\textquotedbl{}"}
_IDENT = re.compile(r"[A-Za-z][A-Za-z0-9]*(_[A-Za-z0-9]+)?")
_ENGINE_SECONDS = 60


def escape(text) -> str:
    r"""``text`` as LaTeX prints it literally: every special character escaped, control
    characters dropped.

    >>> escape(r"\input{x} 50% & $y_1$")
    '\\textbackslash{}input\\{x\\} 50\\% \\& \\$y\\_1\\$'
    """
    out = []
    for ch in str(text):
        if ch in _SPECIAL:
            out.append(_SPECIAL[ch])
        elif ch in "\n\t":
            out.append(" ")
        elif ord(ch) < 32 or ord(ch) == 127:
            continue
        else:
            out.append(ch)
    return "".join(out)


@dataclass
class Handout:
    """What :func:`write_handout` wrote: the ``.tex`` file, the ``.pdf`` (None when no LaTeX
    engine ran) and why there is no PDF (``""`` when there is one)."""

    tex: Path
    pdf: Path | None
    note: str = ""


def parse_numbers(text: str) -> dict[str, float]:
    """``'m=1.2, l=0.5'`` as ``{'m': 1.2, 'l': 0.5}``: names and decimal numbers only (each
    value is read by ``float``, never evaluated); a clear ``ValueError`` otherwise.

    >>> parse_numbers("m=1.2, l = 5e-1")
    {'m': 1.2, 'l': 0.5}
    """
    out: dict[str, float] = {}
    for part in filter(None, (p.strip() for p in re.split(r"[,;]", text or ""))):
        name, eq, value = part.partition("=")
        name, value = name.strip(), value.strip()
        if not eq or not name or not value:
            raise ValueError(f"`{part[:40]}`: write each number as NAME=VALUE, e.g. 'm=1.2'.")
        try:
            out[name] = float(value)
        except ValueError:
            raise ValueError(f"`{name[:40]}`: `{value[:40]}` is not a number; write a decimal "
                             "number such as 1.2 or 5e-1.") from None
    return out


def numbers_of(problem, numbers: Mapping | None = None) -> dict:
    """``{parameter symbol: value}``: the problem's defaults with ``numbers`` (names or symbols
    to values) put in; an unknown name, a value that is not a finite number, or one outside
    the parameter's declared range is a ``ValueError`` saying what to fix."""
    params = {p.symbol.name: p for p in problem.parameters}
    out = {p.symbol: float(p.default) for p in problem.parameters}
    for key, value in (numbers or {}).items():
        name = getattr(key, "name", key)
        if name not in params:
            known = ", ".join(params) or "none"
            raise ValueError(f"`{str(name)[:40]}` is not a parameter of {problem.name}; "
                             f"its parameters are: {known}.")
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"`{name}`: the value must be a number, got {type(value).__name__}.")
        value = float(value)
        lo, hi = (float(x) for x in params[name].range)
        if not math.isfinite(value) or not lo <= value <= hi:
            raise ValueError(f"`{name}` = {value:g} is outside its declared range "
                             f"[{lo:g}, {hi:g}]; choose a value inside it.")
        out[params[name].symbol] = value
    return out


def write_handout(problem, numbers: Mapping | None = None, out: Path | str = ".",
                  solution: bool = False, stem: str | None = None,
                  engine: str | None = "pdflatex") -> Handout:
    """Write the problem sheet (``solution=False``) or the solution sheet of ``problem`` with
    ``numbers`` (see :func:`numbers_of`) to ``out/STEM_problem.tex`` (``_solution``), and its
    PDF when ``engine`` is installed (``None``: no PDF).  ``stem`` defaults to the problem's
    name (only letters, digits, ``-`` and ``_`` are kept)."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    stem = re.sub(r"[^A-Za-z0-9_-]", "_", stem or problem.name or "problem")[:80]
    kind = "solution" if solution else "problem"
    text = solution_sheet(problem, numbers) if solution else problem_sheet(problem, numbers)
    tex = out / f"{stem}_{kind}.tex"
    tex.write_text(text, encoding="utf-8")
    if engine is None:
        return Handout(tex, None, "no LaTeX engine asked for")
    exe = shutil.which(engine)
    if exe is None:
        return Handout(tex, None, f"`{engine}` is not installed: the .tex is written, "
                                  "typeset it where LaTeX is")
    try:
        run = subprocess.run([exe, "-interaction=nonstopmode", "-halt-on-error",
                              "-no-shell-escape", tex.name], cwd=out, capture_output=True,
                             timeout=_ENGINE_SECONDS, check=False)
    except subprocess.TimeoutExpired:
        return Handout(tex, None, f"`{engine}` took longer than {_ENGINE_SECONDS} s")
    pdf = tex.with_suffix(".pdf")
    if run.returncode != 0 or not pdf.exists():
        return Handout(tex, None, f"`{engine}` failed (exit {run.returncode}); see "
                                  f"{tex.with_suffix('.log').name}")
    return Handout(tex, pdf, "")


# -- the two sheets -------------------------------------------------------------------------
def problem_sheet(problem, numbers: Mapping | None = None) -> str:
    """The LaTeX source of the student's sheet: statement, figure, coordinates, numbers."""
    values = numbers_of(problem, numbers)
    body = _statement(problem, values) + [
        r"\section*{What to do}",
        "Derive the equations of motion twice: by Newton--Euler (free-body diagrams, with the "
        "unknown reactions) and by Lagrange's method (kinetic and potential energy, "
        "generalised forces), in the coordinates above." + _reactions_task(problem),
        "Show that the two derivations agree, then evaluate your equations with your numbers.",
    ]
    return _document(problem, "Problem", body)


def solution_sheet(problem, numbers: Mapping | None = None) -> str:
    """The LaTeX source of the teacher's sheet: the problem sheet's statement and numbers, both
    derivations, the reactions, the equations with the numbers, the printed answers' errata."""
    values = numbers_of(problem, numbers)
    body = _statement(problem, values)
    body += _derivations(problem)
    body += _reactions(problem)
    body += _with_numbers(problem, values)
    body += _errata(problem)
    return _document(problem, "Solution", body)


def _document(problem, kind: str, body: list) -> str:
    title = escape(problem.title or problem.name)
    head = [r"\documentclass[11pt]{article}", r"\usepackage[utf8]{inputenc}",
            r"\usepackage[T1]{fontenc}", r"\usepackage{amsmath,amssymb}",
            r"\usepackage[margin=2cm]{geometry}", r"\setlength{\parindent}{0pt}",
            r"\setlength{\parskip}{0.6em}", r"\allowdisplaybreaks",
            r"\begin{document}", rf"\section*{{{kind}: {title}}}"]
    if problem.source:
        head.append(rf"\textit{{Source: {escape(problem.source)}}}")
    return "\n".join(head + body + [r"\end{document}", ""])


def _statement(problem, values: dict) -> list:
    out = []
    if problem.summary:
        out.append(escape(problem.summary))
    figure = sketch_of(problem)
    if figure:
        out += [r"\subsection*{Figure and sign convention}", r"{\ttfamily\small"]
        out += [("~" if not line.strip() else "".join(
            "~" if ch == " " else escape(ch) for ch in line)) + r"\\" for line in
            figure.splitlines()]
        out.append("}")
    out.append(r"\subsection*{Coordinates}")
    out.append(r"\begin{itemize}")
    for c in problem.coordinates:
        out.append(rf"\item {_name(c.name)}: {escape(c.description)}")
    out.append(r"\end{itemize}")
    out += [r"\subsection*{Your numbers}", r"\begin{tabular}{lll}",
            r"\textbf{name} & \textbf{value (SI)} & \textbf{meaning}\\"]
    for p in problem.parameters:
        out.append(rf"{_name(p.symbol.name)} & {escape(format(values[p.symbol], '.6g'))} & "
                   rf"{escape(p.description)}\\")
    out.append(r"\end{tabular}")
    return out


def _reactions_task(problem) -> str:
    names = [r.name for r in problem.reactions]
    if not names:
        return ""
    return " Find the reactions " + ", ".join(_name(n) for n in names) + "."


# -- typesetting expressions safely ------------------------------------------------------------
def _name(name: str) -> str:
    """A name from the problem file in math (a plain identifier) or as escaped text."""
    import sympy as sp
    if _IDENT.fullmatch(name or ""):
        return f"${sp.latex(sp.Symbol(name))}$"
    return rf"\texttt{{{escape(name)}}}"


def _math(expr, coordinates) -> str:
    """``expr`` in LaTeX (math mode content), with coordinates' rates as dots and every symbol
    whose name is not a plain identifier printed as escaped text."""
    import sympy as sp
    from dualmech.model.equations import state_symbols, to_plain
    plain = to_plain(expr, coordinates)
    names = {}
    for q in coordinates:
        s = state_symbols(q)
        head = _symbol_latex(s.name)
        names[s.q], names[s.qd], names[s.qdd] = head, rf"\dot{{{head}}}", rf"\ddot{{{head}}}"
    for sym in plain.free_symbols:
        names.setdefault(sym, _symbol_latex(sym.name))
    return sp.latex(plain, symbol_names=names)


def _symbol_latex(name: str) -> str:
    import sympy as sp
    if _IDENT.fullmatch(name):
        return sp.latex(sp.Symbol(name))
    return rf"\text{{\texttt{{{escape(name)}}}}}"


def _equations(rows, labels, coordinates) -> list:
    out = [r"\begin{align*}"]
    for i, e in enumerate(rows):
        label = escape(labels[i]) if i < len(labels) else ""
        tag = rf" && \text{{{label}}}" if label else ""
        out.append(rf"{_math(e, coordinates)} &= 0{tag}\\")
    out.append(r"\end{align*}")
    return out


def _derivations(problem) -> list:
    out = [r"\section*{The derivations}"]
    for name, m in problem.models().items():
        what = f" ({escape(m.description)})" if m.description else ""
        unknowns = ", ".join(f"${_symbol_latex(u.name)}$" for u in m.unknowns)
        out.append(rf"\subsection*{{{escape(name)}{what}}}")
        if unknowns:
            out.append(f"Unknown reactions or multipliers: {unknowns}.")
        out += _equations(m.equations, m.labels, m.coordinates)
    return out


def _reactions(problem) -> list:
    from dualmech.verify.check import recover_reactions
    if not problem.reactions:
        return []
    out = [r"\section*{Reactions}"]
    try:
        found = recover_reactions(problem)
    except Exception as exc:  # noqa: BLE001 - a sheet is written even if one part is not
        return out + [f"Not printed: {escape(type(exc).__name__)} ({escape(str(exc)[:200])})."]
    coords = problem.model(problem.reference).coordinates
    out.append(r"\begin{align*}")
    for name, expr in found.items():
        out.append(rf"{_symbol_latex(name)} &= {_math(expr, coords)}\\")
    out.append(r"\end{align*}")
    return out


def _with_numbers(problem, values: dict) -> list:
    import sympy as sp
    ref = problem.model(problem.reference)
    subs = {k: sp.Float(v, 6) for k, v in values.items()}
    rows = [sp.N(sp.expand(e.subs(subs)), 6) for e in ref.equations]
    return [r"\section*{The reference equations with these numbers}"] + \
        _equations(rows, ref.labels, ref.coordinates)


def _errata(problem) -> list:
    from dualmech.verify.published import check_published
    out = [r"\section*{The printed answers}"]
    try:
        verdicts = check_published(problem)
    except Exception as exc:  # noqa: BLE001 - a sheet is written even if one part is not
        return out + [f"Not checked: {escape(type(exc).__name__)}."]
    if not verdicts:
        return out + ["The source prints no answer to check."]
    out.append(r"\begin{itemize}")
    for v in verdicts:
        where = f" ({escape(v.where)})" if v.where else ""
        line = rf"\item \textbf{{{escape(v.label)}}}{where}: {escape(v.verdict)}"
        if v.verdict != "correct" and v.detail:
            line += rf" -- \emph{{erratum}}: {_typeset(v, problem)}"
        out.append(line)
    out.append(r"\end{itemize}")
    return out


def _typeset(verdict, problem) -> str:
    """Why a printed answer is wrong: its sentences with their expressions typeset (the plain
    text when an expression cannot be)."""
    import sympy as sp
    coords = problem.model(problem.reference).coordinates
    try:
        out = []
        for part in verdict.parts:
            out.append("".join(f"${_math(x, coords)}$" if isinstance(x, sp.Basic)
                               else escape(x) for x in part))
        return " ".join(out)
    except Exception:  # noqa: BLE001 - the plain text says the same
        return escape(verdict.detail[:600])
