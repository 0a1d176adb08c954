"""The report a teacher reads: ``report.md``, ``report.html`` and a chart per problem.

:func:`write_report` takes the comparisons of :func:`dualmech.verify.check.compare` (anything with
``problem``, ``equivalent``, ``method``, ``str()``; ``published``, ``reactions`` and
``verdict_line()`` when present, so a stand-in for a problem that could not be compared
works too), draws each problem's chart (:mod:`.charts`: one panel per unit, units on every
axis, coinciding curves drawn once and named, zero reactions named and not drawn, spans cut
to fit the scene) and writes both pages (:mod:`.pages`).

Example
-------
>>> import tempfile
>>> from dualmech.verify.check import compare
>>> from dualmech.problems import get
>>> with tempfile.TemporaryDirectory() as out:
...     w = write_report([compare(get("simple_pendulum"))], Path(out), 1.0)
...     sorted(p.name for p in Path(out).iterdir())
['report.html', 'report.md', 'simple_pendulum_motion.gif', 'simple_pendulum_reactions.png', 'simple_pendulum_reactions.svg']
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Sequence

from dualmech.report.charts import Chart, animation_for, trajectory_chart
from dualmech.report.pages import AUDIENCES, check_audience, html_page, markdown_page

__all__ = ["write_report", "Written", "Chart", "trajectory_chart", "AUDIENCES"]


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
                 progress: bool = True, audience: str = "teachers",
                 notation: str = "dots", animations: bool = True) -> Written:
    """Draw every problem's chart and write ``out_dir/report.md`` and ``out_dir/report.html``.

    ``duration`` is the longest simulated span in seconds; each chart stops earlier where
    its scene ends.  ``audience`` is ``"teachers"`` (why each wrong printed answer is wrong,
    and the full text report) or ``"students"`` (verdicts only, corrections hidden: a page
    to hand out).  ``notation`` writes rates as ``"dots"`` (``θ̇``) or ``"primes"`` (``θ′``)
    in every expression of both pages.  ``animations`` adds each problem's motion as a GIF
    with the reaction forces as arrows (:mod:`.animation`; ``NAME_motion.gif``, embedded in
    the HTML page).  Raises ``OSError`` when ``out_dir`` cannot be written.

    Examples
    --------
    >>> import tempfile
    >>> from dualmech import compare, get, write_report
    >>> with tempfile.TemporaryDirectory() as out:
    ...     written = write_report([compare(get("simple_pendulum"))], out, 1.0, progress=False)
    ...     written.markdown.name, written.failed
    ('report.md', {})
    """
    check_audience(audience)
    from dualmech.model.notation import check_notation
    check_notation(notation)
    if not duration > 0:
        raise ValueError(f"`duration` must be positive, got {duration!r}.")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    comparisons = list(comparisons)
    charts = {}
    from dualmech.progress import progress as _progress   # a bar on a terminal, lines otherwise
    for c in _progress(comparisons, "charts", quiet=not progress,
                       label=lambda c: c.problem.name):
        charts[c.problem.name] = trajectory_chart(c.problem, out, duration)
        if animations and not charts[c.problem.name].error:
            animation_for(c.problem, charts[c.problem.name], out, duration)
    md = out / "report.md"
    md.write_text(markdown_page(comparisons, charts, duration, audience, notation),
                  encoding="utf-8")
    page = out / "report.html"
    page.write_text(html_page(comparisons, charts, out, duration, audience, notation),
                    encoding="utf-8")
    return Written(md, page, charts)
