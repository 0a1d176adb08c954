"""SI unit names of the catalogue's dimensions, for chart axes and tables.

Example
-------
>>> from dualmech.model.dimensions import ANGLE, FORCE, STIFFNESS
>>> unit(ANGLE), unit(FORCE), unit(STIFFNESS), unit(FORCE / ANGLE)
('rad', 'N', 'N/m', 'N/rad')
"""
from __future__ import annotations

from dualmech.model.dimensions import (ACCELERATION, ANGLE, DAMPING, ENERGY, FORCE, FREQUENCY,
                                      INERTIA, LENGTH, MASS, STIFFNESS, TIME, VELOCITY,
                                      as_dimension, reduce)

__all__ = ["unit", "rate_unit", "work_conjugate_unit"]

_NAMED = [(LENGTH, "m"), (FORCE, "N"), (ENERGY, "N m"), (MASS, "kg"), (TIME, "s"),
          (VELOCITY, "m/s"), (ACCELERATION, "m/s^2"), (STIFFNESS, "N/m"), (DAMPING, "N s/m"),
          (INERTIA, "kg m^2"), (FREQUENCY, "1/s"), (FREQUENCY**2, "1/s^2"),
          (ENERGY * TIME, "N m s")]
_BASE = {"mass": "kg", "length": "m", "time": "s"}


def _angle_power(dimension) -> int:
    """Power of ``angle`` in ``dimension`` (a Dimension keeps it; :func:`reduce` drops it)."""
    return int(as_dimension(dimension).power("angle"))


def unit(dimension) -> str:
    """The SI unit of ``dimension`` (``"rad"`` for angles, ``"1"`` for pure numbers)."""
    if dimension is None:
        return "?"
    dimension = as_dimension(dimension)
    angle = _angle_power(dimension)
    base = reduce(dimension)
    if not base:
        return {0: "1", 1: "rad", -1: "1/rad"}.get(angle, f"rad^{angle}")
    text = None
    for dim, name in _NAMED:
        if reduce(dim) == base:
            text = name
            break
    if text is None:
        num = [f"{_BASE.get(k, k)}" + (f"^{e}" if e != 1 else "") for k, e in base if e > 0]
        den = [f"{_BASE.get(k, k)}" + (f"^{-e}" if e != -1 else "") for k, e in base if e < 0]
        text = " ".join(num) or "1"
        if den:
            text += "/" + (" ".join(den) if len(den) == 1 else f"({' '.join(den)})")
    if angle > 0:
        rad = "rad" if angle == 1 else f"rad^{angle}"
        return rad + text[1:] if text.startswith("1/") else f"{text} {rad}"
    if angle < 0:
        return f"{text}/rad" if angle == -1 else f"{text}/rad^{-angle}"
    return text


def rate_unit(dimension) -> str:
    """Unit of the rate of a quantity of ``dimension`` (``m/s``, ``rad/s``)."""
    return unit(as_dimension(dimension) / TIME) if dimension is not None else "?"


def work_conjugate_unit(dimension) -> str:
    """Unit of the coordinate conjugate to a force-like ``dimension`` (``N`` -> ``m``)."""
    if dimension is None:
        return "?"
    dimension = as_dimension(dimension)
    if reduce(dimension) == reduce(ENERGY) and not _angle_power(dimension):
        return unit(ANGLE)  # a torque does work on an angle
    return unit(ENERGY / dimension)
