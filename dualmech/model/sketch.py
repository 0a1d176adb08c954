"""The sign-convention sketch a problem file draws in its module docstring.

A problem module shows its frames and signs as a literal block (a paragraph ending in ``::``)
near the words "sign convention"; pages and handouts print it as the problem's figure.

Example
-------
>>> from dualmech.problems import get
>>> "pivot" in sketch_of(get("simple_pendulum"))
True
"""
from __future__ import annotations

import inspect
import textwrap

__all__ = ["sketch_of"]


def sketch_of(problem) -> str:
    """The sign-convention sketch of ``problem``'s module docstring (its first literal block
    after a line that mentions the sign convention, else its first literal block); ``""``
    when there is none."""
    doc = inspect.getmodule(type(problem)).__doc__ or ""
    lines = doc.splitlines()
    starts = [i for i, line in enumerate(lines) if line.rstrip().endswith("::")]
    if not starts:
        return ""
    preferred = [i for i in starts if "sign convention" in " ".join(
        lines[max(0, i - 3):i + 1]).lower()]
    i = (preferred or starts)[0]
    base = len(lines[i]) - len(lines[i].lstrip())
    block: list[str] = []
    for line in lines[i + 1:]:
        if line.strip() and len(line) - len(line.lstrip()) <= base:
            break
        block.append(line)
    return textwrap.dedent("\n".join(block)).strip("\n")
