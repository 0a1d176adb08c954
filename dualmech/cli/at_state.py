"""``--at 'theta=0.3, theta_dot=1'``: reaction values at a state, for ``show`` and ``check``.

The option's text is read by the strict ``name=number`` grammar of ``dualmech stability
--about`` (:func:`dualmech.cli.stability.parse_about`): nothing in it is evaluated.  The values
themselves come from :func:`dualmech.numeric.reactions_state.reactions_at_state` -- the direct
form's value and the Kane referee's beside it.  Without ``--at`` they are shown only when a
reaction's formula is past the display budget, at the problem's default state (and it says so).

>>> parse_at("theta=0.3, theta_dot=-1")
{'theta': 0.3, 'theta_dot': -1.0}
>>> split_time({"theta": 0.3, "t": 2.0})
({'theta': 0.3}, 2.0)
>>> parse_at("theta=nan")
Traceback (most recent call last):
dualmech.cli.errors.UsageError: `--at`: "nan" is not a number (theta=...); write name=number \
pairs separated by commas, e.g. 'theta=0.1, theta_dot=2'.
"""
from __future__ import annotations

import argparse

from dualmech.cli.errors import UsageError

__all__ = ["add_at_option", "parse_at", "split_time", "check_at", "values_wanted",
           "state_values", "with_values", "report_data"]


def add_at_option(p: argparse.ArgumentParser) -> None:
    """Add ``--at`` to the sub-command ``p``."""
    p.add_argument("--at", metavar="'q=V, q_dot=W'", default=None,
                   help="also give every reaction's value at this state (coordinates of the "
                        "reference model, rates as name_dot, t for the time of a driven "
                        "problem, default 0; unnamed ones keep the default state), by the "
                        "direct form and by the Kane referee; without it, values are shown "
                        "only for reactions past the display budget")


def parse_at(text: str) -> dict:
    """``--at``'s text as ``{name: float}`` (a :class:`UsageError` naming what to fix)."""
    from dualmech.cli.stability import parse_about
    try:
        return parse_about(text)
    except UsageError as exc:
        raise UsageError(str(exc).replace("`--about`", "`--at`")) from None


def split_time(at: dict) -> tuple[dict, float]:
    """``(state names, time)``: ``t`` in ``--at`` is the time (a driven problem's inputs and
    prescribed motions are taken then), 0 when not given."""
    at = dict(at)
    return at, float(at.pop("t", 0.0))


def check_at(problem, text: str) -> dict:
    """``--at`` parsed and its names checked against ``problem``'s coordinates, before any
    derivation is compared (a :class:`UsageError` naming the coordinates)."""
    at = parse_at(text)
    from dualmech.numeric.reactions_state import state_from_names
    try:
        state_from_names(problem, split_time(at)[0])
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return at


def values_wanted(problem, c, at_text: str | None) -> bool:
    """Whether to give values: ``--at`` was given, or a declared reaction has no formula."""
    formulas = getattr(c, "reactions", None)   # None: a failure, or a worker's finished text
    if not getattr(problem, "reactions", ()) or formulas is None \
            or not getattr(c, "equivalent", False):
        return False
    return at_text is not None or any(r.name not in formulas for r in problem.reactions)


def state_values(problem, c, at_text: str | None):
    """The :class:`~dualmech.numeric.reactions_state.StateReactions` for ``show``/``check``;
    a bad ``--at`` (an unknown name) is a :class:`UsageError`."""
    at, time = split_time(parse_at(at_text)) if at_text is not None else (None, 0.0)
    from dualmech.numeric.reactions_state import reactions_at_state
    try:
        return reactions_at_state(problem, at, time=time, comparison=c)
    except ValueError as exc:
        if at is not None and str(exc).startswith("`--at`"):
            raise UsageError(str(exc)) from None
        raise


def with_values(problem, c, text: str | None, data: dict | None, at_text: str | None):
    """``check``'s ``(text, data)`` of ``c`` with the reaction values at a state added (when
    :func:`values_wanted`): a section after the text, ``values_at_state`` in the data."""
    if not values_wanted(problem, c, at_text):
        return text, data
    values = state_values(problem, c, at_text)
    if text is not None:
        text += ("\n  reaction values at a state (direct form; Kane referee beside it):\n  "
                 + "\n  ".join(values.lines()))
    if data is not None:
        data = {**data, "values_at_state": values.to_dict()}
    return text, data


def report_data(problem, c) -> dict:
    """``c.to_dict()`` for ``dualmech report``'s ``<name>.json``, with the values at the default
    state of reactions past the display budget; a state where they cannot be solved (a
    singular matrix) is said in ``values_at_state.error``, never a lost report."""
    from dualmech.numeric.model import SingularityError
    data = c.to_dict()
    try:
        return with_values(problem, c, None, data, None)[1]
    except (ValueError, SingularityError) as exc:
        return {**data, "values_at_state": {"error": str(exc)}}
