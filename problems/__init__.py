"""The problems of the course sources, each written twice (Newton--Euler and Lagrange).

Each module defines one or more :class:`dualmech.problem.Problem` subclasses and lists their
instances in ``PROBLEMS``.  :func:`all_problems` gathers them; :func:`get` finds one by name.
"""
from __future__ import annotations

import importlib

from dualmech.problem import Problem

#: Problem modules, in the order `dualmech list` shows them.
MODULES = ("toy_car", "falling_container", "block_on_wedge", "pendulum_on_mass",
           "cart_pendulum")


def all_problems() -> list[Problem]:
    """One instance of every problem, in catalogue order."""
    out = []
    for mod in MODULES:
        module = importlib.import_module(f"problems.{mod}")
        out.extend(cls() for cls in module.PROBLEMS)
    return out


def get(name: str) -> Problem:
    """The problem called ``name``; ``KeyError`` lists the known names."""
    found = {p.name: p for p in all_problems()}
    if name not in found:
        raise KeyError(f"no problem named {name!r}; known problems: {', '.join(found)}.")
    return found[name]
