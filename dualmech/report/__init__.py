"""The report a teacher reads: ``report.md``, ``report.html`` and a chart per problem.

:func:`write_report` takes the comparisons of :func:`dualmech.compare.compare` (anything with
``problem``, ``equivalent``, ``method``, ``str()``; ``published``, ``reactions`` and
``verdict_line()`` when present, so a stand-in for a problem that could not be compared
works too), draws each problem's chart (:mod:`.charts`: one panel per unit, units on every
axis, coinciding curves drawn once and named, zero reactions named and not drawn, spans cut
to fit the scene) and writes both pages (:mod:`.pages`).

Example
-------
>>> from dualmech.compare import compare                              # doctest: +SKIP
>>> from dualmech.problems import all_problems                                  # doctest: +SKIP
>>> write_report([compare(p) for p in all_problems()], Path("out"), 5.0)  # doctest: +SKIP
Written(markdown=PosixPath('out/report.md'), html=PosixPath('out/report.html'), ...)
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Sequence

from .charts import Chart, trajectory_chart
from .pages import html_page, markdown_page

__all__ = ["write_report", "Written", "Chart", "trajectory_chart"]


@dataclass
class Written:
    """What :func:`write_report` wrote: the two pages and the charts (``{name: Chart}``)."""

    markdown: Path
    html: Path
    charts: dict = field(default_factory=dict)

    @property
    def failed(self) -> dict:
        """``{problem: why}`` for the charts that could not be drawn."""
        return {k: c.error for k, c in self.charts.items() if c.error}


def write_report(comparisons: Sequence, out_dir: Path, duration: float = 5.0,
                 progress: bool = True) -> Written:
    """Draw every problem's chart and write ``out_dir/report.md`` and ``out_dir/report.html``.

    ``duration`` is the longest simulated span in seconds; each chart stops earlier where
    its scene ends.  Raises ``OSError`` when ``out_dir`` cannot be written.
    """
    if not duration > 0:
        raise ValueError(f"`duration` must be positive, got {duration!r}.")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    comparisons = list(comparisons)
    charts = {}
    from ..progress import progress as _progress   # a bar on a terminal, lines otherwise
    for c in _progress(comparisons, "charts", quiet=not progress,
                       label=lambda c: c.problem.name):
        charts[c.problem.name] = trajectory_chart(c.problem, out, duration)
    md = out / "report.md"
    md.write_text(markdown_page(comparisons, charts, duration))
    page = out / "report.html"
    page.write_text(html_page(comparisons, charts, out, duration), encoding="utf-8")
    return Written(md, page, charts)
