"""Facts about one problem that its equations do not carry, declared for the numeric studies.

Which reactions can only push or only pull, from where a run heads into the singular set,
which scene shows stiffness, which simpler models sit below this one, from where the motion
is chaotic, where a simulation starts: each is physics (or a choice of scene) the equations
of motion do not say.  A problem class declares them as class attributes -- documented on
:class:`~dualmech.model.problem.Problem` -- with the small records of this module, and the
studies of :mod:`dualmech.numeric` read those declarations and nothing else, so a teacher's
own problem file makes them the same way the catalogue does.

A state is declared in the reference model's coordinates: a sequence of ``2 n`` numbers (the
coordinates, then their rates), or a mapping ``{q: value, q.diff(t): rate}`` whose missing
rates are zero.  :func:`state_vector` reads either; :func:`declaration_errors` lists every
mistake in a problem's declarations for :meth:`Problem.validate
<dualmech.model.problem.Problem.validate>`.

This module imports nothing heavy: declaring a fact costs a problem file nothing.

Example
-------
>>> p = Probe((1.3, 1e-3, 3.5, 0.0), "lagrange", 1.0, "runs over the pivot axis")
>>> p.duration, p.state[1]
(1.0, 0.001)
>>> StiffScene("k", (2.2, 2.5, 0.0, 0.0), 0.5).parameter
'k'
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Callable

__all__ = ["Probe", "StiffScene", "FidelityRung", "SteadyMotion", "state_vector",
           "is_declared", "declaration_errors", "not_declared"]


@dataclass(frozen=True)
class Probe:
    """A run that heads for the problem's declared singular set (``Problem.singular``).

    Parameters
    ----------
    state : sequence of 2n numbers, or mapping
        The initial state in the reference coordinates (see the module docstring).
    formulation : str
        The formulation to watch: a model's name (``"lagrange_x"``), or a DAE form of a
        multiplier model as the studies name it (``"multiplier (DAE, index 1)"``).
    duration : float
        Seconds to run, from ``t = 0``.
    why : str
        What happens on the way, in words (printed with the runs).

    Example
    -------
    >>> Probe((2.7, 3.0), "lagrange_x", 1.0, "the spring throws the rods flat").formulation
    'lagrange_x'
    """

    state: tuple
    formulation: str
    duration: float
    why: str = ""

    def __post_init__(self):
        object.__setattr__(self, "state", _state_field("Probe", self.state))
        _text("Probe", "formulation", self.formulation, empty=False)
        _text("Probe", "why", self.why)
        _seconds("Probe", self.duration)


@dataclass(frozen=True)
class StiffScene:
    """A scene for the stiffness sweep: a stiffness parameter pushed past its range from a
    state that leaves the fast mode at rest, so the exact motion stays smooth.

    Parameters
    ----------
    parameter : str
        The name of the stiffness parameter to sweep (a declared parameter).
    state : sequence of 2n numbers, or mapping
        The initial state in the reference coordinates.
    duration : float
        Seconds to run, from ``t = 0``.
    why : str
        Why the exact motion is smooth, in words.
    exact : callable, optional
        ``exact(values, y0, times)`` -> the exact states at ``times`` (arrays), ``2 n`` rows
        of ``len(times)`` values, where ``values`` maps each parameter's *name* to its
        value; without it each run is measured against a tight run of the implicit Radau
        method.

    Example
    -------
    >>> StiffScene("k", (0.0, 0.0), 1.0, "at rest at its equilibrium").exact is None
    True
    """

    parameter: str
    state: tuple
    duration: float
    why: str = ""
    exact: Callable | None = None

    def __post_init__(self):
        _text("StiffScene", "parameter", self.parameter, empty=False)
        object.__setattr__(self, "state", _state_field("StiffScene", self.state))
        _text("StiffScene", "why", self.why)
        _seconds("StiffScene", self.duration)
        if self.exact is not None and not callable(self.exact):
            raise TypeError(f"`StiffScene.exact` must be a function (values, y0, times) -> "
                            f"states, got {self.exact!r:.60}.")


@dataclass(frozen=True)
class FidelityRung:
    """One model of a fidelity ladder: a problem, and what it neglects against the richest.

    A ladder is the tuple ``fidelity_ladder = (FidelityRung(...), ...)``, simplest first; the
    last rung is the richest model, the one the others are measured against.

    Parameters
    ----------
    label : str
        The rung's name in the table (``"point masses on massless rods"``).
    problem : callable
        A problem class, or a function of no arguments returning a problem instance
        (``lambda: NLinkPendulum(n=3)``); called when the ladder is measured, so it may
        name a class defined further down the file.
    neglects : str
        What this rung leaves out, in words (empty for the richest).
    neglected_reactions : tuple of str
        Reactions of the richest model this rung neglects; the ladder reports their size.

    Example
    -------
    >>> from dualmech import Problem
    >>> FidelityRung("detailed", Problem).neglected_reactions
    ()
    """

    label: str
    problem: Callable
    neglects: str = ""
    neglected_reactions: tuple = ()

    def __post_init__(self):
        _text("FidelityRung", "label", self.label, empty=False)
        _text("FidelityRung", "neglects", self.neglects)
        if not callable(self.problem):
            raise TypeError(f"`FidelityRung.problem` of rung {self.label!r} must be a problem "
                            f"class or a function returning a problem, got "
                            f"{self.problem!r:.60}.")
        names = self.neglected_reactions
        if isinstance(names, str):
            names = (names,)
        names = tuple(names)
        for name in names:
            _text("FidelityRung", "neglected_reactions", name, empty=False)
        object.__setattr__(self, "neglected_reactions", names)


@dataclass(frozen=True)
class SteadyMotion:
    """A steady motion whose stability ``dualmech stability`` studies without options.

    Parameters
    ----------
    about : mapping
        ``{q: value, q.diff(t): rate}`` in the reference model's coordinates (missing ones
        are zero); values may hold the free ``parameter`` and the problem's parameters.
    parameter : str, optional
        The name of the swept quantity: the free symbol of ``about`` (a forward speed ``v``)
        or a declared parameter; empty for a steady motion studied at one point.
    sweep : (start, stop, count), optional
        The values swept by default (``count`` >= 2).
    why : str
        What the motion is, in words.

    Example
    -------
    >>> SteadyMotion({}, "v", (0, 10, 101), "upright rolling").sweep
    (0.0, 10.0, 101)
    """

    about: dict
    parameter: str = ""
    sweep: tuple = ()
    why: str = ""

    def __post_init__(self):
        if not isinstance(self.about, Mapping):
            raise TypeError(f"`SteadyMotion.about` must be a mapping {{q: value, rate(q): "
                            f"value}}, got {self.about!r:.60}.")
        object.__setattr__(self, "about", dict(self.about))
        _text("SteadyMotion", "parameter", self.parameter)
        _text("SteadyMotion", "why", self.why)
        if self.sweep:
            if isinstance(self.sweep, (str, bytes)) or len(tuple(self.sweep)) != 3:
                raise ValueError(f"`SteadyMotion.sweep` must be (start, stop, count), got "
                                 f"{self.sweep!r:.60}.")
            start, stop = _numbers("`SteadyMotion.sweep`", tuple(self.sweep)[:2])
            count = tuple(self.sweep)[2]
            if isinstance(count, bool) or not isinstance(count, int) or count < 2:
                raise ValueError(f"`SteadyMotion.sweep` count must be a whole number >= 2, "
                                 f"got {count!r:.20}.")
            if not self.parameter:
                raise ValueError("`SteadyMotion.sweep` needs `parameter`: the name of the "
                                 "swept quantity.")
            object.__setattr__(self, "sweep", (start, stop, count))


def _text(kind: str, field: str, value, empty: bool = True) -> None:
    if not isinstance(value, str):
        raise TypeError(f"`{kind}.{field}` must be text, got {value!r:.60} "
                        f"({type(value).__name__}).")
    if not empty and not value.strip():
        raise ValueError(f"`{kind}.{field}` is empty.")


def _seconds(kind: str, value) -> None:
    if isinstance(value, (bool, str, bytes)) or not isinstance(value, (int, float)) \
            or not math.isfinite(value) or value <= 0:
        raise ValueError(f"`{kind}.duration` must be a positive number of seconds, got "
                         f"{value!r:.60}.")


def _state_field(kind: str, state):
    """A declared state as a tuple of floats, or a dict (a mapping's keys are checked
    against the problem by :func:`state_vector`)."""
    if isinstance(state, Mapping):
        return dict(state)
    return _numbers(f"`{kind}.state`", state)


def _numbers(what: str, values) -> tuple:
    if isinstance(values, (str, bytes)):
        raise TypeError(f"{what} must be numbers, got the text {values!r:.60}.")
    try:
        items = list(values)
    except TypeError:
        raise TypeError(f"{what} must be a sequence of numbers (the coordinates, then their "
                        f"rates) or a mapping, got {values!r:.60}.") from None
    out = []
    for x in items:
        if isinstance(x, (bool, str, bytes)):
            raise TypeError(f"{what} must be numbers, got {x!r:.40} in {values!r:.60}.")
        try:
            v = float(x)
        except (TypeError, ValueError):
            raise TypeError(f"{what} must be numbers, got {x!r:.40} in {values!r:.60}.") \
                from None
        if not math.isfinite(v):
            raise ValueError(f"{what} must be finite, got {x!r} in {values!r:.60}.")
        out.append(v)
    return tuple(out)


def state_vector(problem, state, what: str = "the state") -> list[float]:
    """``state`` as ``[q..., q'...]`` in the reference model's coordinates.

    ``state`` is a sequence of ``2 n`` numbers or a mapping ``{q: value, q.diff(t): rate}``
    (every coordinate given, missing rates zero); ``ValueError`` says what is wrong.

    >>> from dualmech.problems import get
    >>> p = get("simple_pendulum"); theta = p.coordinates[0].function
    >>> state_vector(p, {theta: 0.5}), state_vector(p, (0.5, 2))
    ([0.5, 0.0], [0.5, 2.0])
    """
    coords = list(problem.model(problem.reference).coordinates)
    n = len(coords)
    names = [q.func.__name__ for q in coords]
    if not isinstance(state, Mapping):
        values = list(_numbers(what, state))
        if len(values) != 2 * n:
            raise ValueError(f"{what} has {len(values)} number{'s' * (len(values) != 1)}; it "
                             f"needs {2 * n}: the coordinates {', '.join(names)}, then their "
                             "rates.")
        return values
    rates = {q.diff(q.args[0]): i for i, q in enumerate(coords)}
    where = {q: i for i, q in enumerate(coords)}
    out: list = [None] * n + [0.0] * n
    for key, value in state.items():
        (v,) = _numbers(what, [value])
        if key in where:
            out[where[key]] = v
        elif key in rates:
            out[n + rates[key]] = v
        else:
            raise ValueError(f"{what}: {key!r:.40} is not a coordinate of the reference model "
                             f"or its rate; the coordinates are {', '.join(names)}.")
    missing = [names[i] for i in range(n) if out[i] is None]
    if missing:
        raise ValueError(f"{what} gives no value for {', '.join(missing)}.")
    return out


# -- validation -----------------------------------------------------------------------------
def declaration_errors(problem) -> list[str]:
    """Every mistake in ``problem``'s declared facts, one sentence each (empty when none).

    The problem's models must already build; the states are checked against its reference
    model's coordinates.
    """
    errors = _unilateral_errors(problem)
    models = list(problem.models())
    has_reference = problem.reference in models
    for i, p in enumerate(_tuple_of(problem, "probes", Probe, errors)):
        if has_reference:
            errors += _state_errors(problem, p.state, f"`probes[{i}].state`")
        if p.formulation.split(" (")[0] not in models:
            errors.append(f"`probes[{i}]`: formulation `{p.formulation}` is not one of the models "
                          f"{', '.join(models)}")
    errors += _stiff_errors(problem, has_reference)
    errors += _ladder_errors(problem)
    errors += _steady_errors(problem)
    for attr in ("chaotic_state", "initial_state"):
        state = getattr(problem, attr, None)
        if has_reference and is_declared(state):
            errors += _state_errors(problem, state, f"`{attr}`")
    return errors


def _steady_errors(problem) -> list[str]:
    steady = getattr(problem, "steady_motion", None)
    if steady is None:
        return []
    if not isinstance(steady, SteadyMotion):
        return [f"`steady_motion` must be a SteadyMotion(...), got {steady!r:.60}"]
    errors = []
    coords = [c.function for c in problem.coordinates]
    rates = [q.diff(q.args[0]) for q in coords]
    for key in steady.about:
        if key not in coords and key not in rates:
            errors.append(f"`steady_motion.about`: {key!r:.40} is not a coordinate of the "
                          "reference model or its rate")
    return errors


def is_declared(state) -> bool:
    """Whether a state attribute declares something (``()``, ``{}`` and ``None`` do not)."""
    return state is not None and not (isinstance(state, (Mapping, tuple, list))
                                      and len(state) == 0)


def _state_errors(problem, state, what: str) -> list[str]:
    try:
        state_vector(problem, state, what)
    except (TypeError, ValueError) as exc:
        return [str(exc).rstrip(".")]
    return []


def _unilateral_errors(problem) -> list[str]:
    declared = getattr(problem, "unilateral", {})
    if not isinstance(declared, Mapping):
        return [f"`unilateral` must be a mapping {{reaction name: what happens when it would "
                f"change sign}}, got {declared!r:.60}"]
    reactions = [r.name for r in problem.reactions]
    errors = []
    for name, meaning in declared.items():
        if name not in reactions:
            errors.append(f"`unilateral`: `{name}` is not a declared reaction (declared: "
                          f"{', '.join(reactions) or 'none'})")
        if not isinstance(meaning, str) or not meaning.strip():
            errors.append(f"`unilateral[{name!r}]` must say in words what happens when the "
                          f"reaction would change sign, got {meaning!r:.60}")
    return errors


def _tuple_of(problem, attr: str, kind: type, errors: list) -> tuple:
    value = getattr(problem, attr, ())
    if isinstance(value, kind):
        value = (value,)
    if not isinstance(value, (tuple, list)):
        errors.append(f"`{attr}` must be a tuple of {kind.__name__}(...), got {value!r:.60}")
        return ()
    bad = [x for x in value if not isinstance(x, kind)]
    if bad:
        errors.append(f"`{attr}` must hold {kind.__name__}(...) records, got {bad[0]!r:.60}")
        return ()
    return tuple(value)


def _stiff_errors(problem, has_reference: bool) -> list[str]:
    scene = getattr(problem, "stiff_scene", None)
    if scene is None:
        return []
    if not isinstance(scene, StiffScene):
        return [f"`stiff_scene` must be a StiffScene(...), got {scene!r:.60}"]
    errors = []
    names = [p.symbol.name for p in problem.parameters]
    if scene.parameter not in names:
        errors.append(f"`stiff_scene.parameter`: `{scene.parameter}` is not a declared "
                      f"parameter (declared: {', '.join(names) or 'none'})")
    if has_reference:
        errors += _state_errors(problem, scene.state, "`stiff_scene.state`")
    return errors


def _ladder_errors(problem) -> list[str]:
    errors: list[str] = []
    rungs = _tuple_of(problem, "fidelity_ladder", FidelityRung, errors)
    if not rungs or errors:
        return errors
    if len(rungs) < 2:
        return ["`fidelity_ladder` needs at least two rungs (a simpler model below the "
                "richest); the small-oscillation rung is added without a declaration"]
    try:
        richest = rungs[-1].problem()
    except Exception as exc:  # noqa: BLE001 - a teacher's factory may fail any way
        return [f"`fidelity_ladder`: building the richest rung {rungs[-1].label!r} raised "
                f"{type(exc).__name__}: {exc}"]
    if not callable(getattr(richest, "models", None)):
        return [f"`fidelity_ladder`: the richest rung {rungs[-1].label!r} must give a problem, "
                f"got {richest!r:.60}"]
    reactions = [r.name for r in richest.reactions]
    for rung in rungs:
        for name in rung.neglected_reactions:
            if name not in reactions:
                errors.append(f"`fidelity_ladder` rung {rung.label!r}: `{name}` is not a "
                              "reaction of the richest rung (its reactions: "
                              f"{', '.join(reactions) or 'none'})")
    return errors


def not_declared(declaration: str, example: str) -> str:
    """The sentence a study prints when a problem does not declare what it needs.

    >>> not_declared("stiff scene", "stiff_scene = StiffScene(...)")
    'no stiff scene declared: add `stiff_scene = StiffScene(...)` to the problem class'
    """
    return f"no {declaration} declared: add `{example}` to the problem class"
