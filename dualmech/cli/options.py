"""Option values every command reads the same way: positive numbers and bounded whole numbers.

Each is an ``argparse`` ``type=``: a value out of its range is an ``ArgumentTypeError``, which
argparse turns into a usage error (exit status 2) naming the option.

Example
-------
>>> positive_number("0.5"), whole_number(2, 10)("3")
(0.5, 3)
>>> whole_number(2, 10)("11")
Traceback (most recent call last):
argparse.ArgumentTypeError: expected a whole number from 2 to 10, got 11
"""
from __future__ import annotations

import argparse
import math

__all__ = ["positive_number", "whole_number"]


def positive_number(text: str) -> float:
    """A finite number above zero."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}") from None
    if not (value > 0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f"expected a positive finite number, got {text!r}")
    return value


def whole_number(least: int = 1, most: int | None = None):
    """A ``type=`` for a whole number from ``least`` to ``most`` (no upper bound: ``None``)."""
    span = f"from {least} to {most}" if most is not None else f"of at least {least}"

    def read(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected a whole number {span}, got "
                                             f"{text!r}") from None
        if value < least or (most is not None and value > most):
            raise argparse.ArgumentTypeError(f"expected a whole number {span}, got {value}")
        return value
    read.__name__ = f"whole_number_{least}_{most}"
    return read
