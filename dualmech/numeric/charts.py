"""Shared chart plumbing: a headless matplotlib, PNG and SVG side by side, stable styles.

Example
-------
>>> import tempfile
>>> fig, axes = panels(2, "a title")
>>> with tempfile.TemporaryDirectory() as out:
...     [p.name for p in save(fig, Path(out) / "example")]
['example.png', 'example.svg']
"""
from __future__ import annotations

from pathlib import Path

__all__ = ["pyplot", "panels", "save", "METHOD_COLORS", "FORM_STYLES", "style_of"]

#: One colour per integrator, one line style and marker per formulation (cycled).
METHOD_COLORS = {"RK45": "#1f77b4", "DOP853": "#ff7f0e", "Radau": "#2ca02c", "BDF": "#d62728",
                 "LSODA": "#9467bd", "midpoint": "#8c564b",
                 "IDA": "#e377c2"}
FORM_STYLES = [("-", "o"), ("--", "s"), (":", "^"), ("-.", "D"), ((0, (5, 1)), "v"),
               ((0, (1, 1)), "P"), ((0, (3, 1, 1, 1)), "X"), ((0, (5, 3)), "*")]


def pyplot():
    """matplotlib's pyplot on the non-interactive Agg backend (no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def panels(count: int, title: str, *, width: float = 8.0, height: float = 2.8,
           sharex: bool = True, columns: int = 1):
    """A figure with ``count`` stacked panels; returns ``(fig, [axes...])``."""
    plt = pyplot()
    rows = -(-count // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(width, height * rows + 0.6),
                             sharex=sharex, squeeze=False)
    fig.suptitle(title, fontsize="medium")
    flat = list(axes.flat)
    for ax in flat[count:]:
        ax.set_visible(False)
    return fig, flat[:count]


def save(fig, stem: Path, dpi: int = 110, tight: bool = True) -> list[Path]:
    """Write ``stem.png`` and ``stem.svg`` (folders created) and close the figure."""
    stem = Path(stem)
    stem.parent.mkdir(parents=True, exist_ok=True)
    if tight:
        fig.tight_layout()
    out = [stem.with_suffix(".png"), stem.with_suffix(".svg")]
    fig.savefig(out[0], dpi=dpi)
    fig.savefig(out[1])
    pyplot().close(fig)
    return out


def style_of(index: int) -> tuple:
    """``(linestyle, marker)`` of the ``index``-th formulation."""
    return FORM_STYLES[index % len(FORM_STYLES)]
