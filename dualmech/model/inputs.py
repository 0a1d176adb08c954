"""Given inputs: a force or torque magnitude known only as a function of time, ``F(t)``.

A problem declares each one on :attr:`Problem.inputs <dualmech.model.problem.Problem>` as an
:class:`Input` and writes it in its models as a plain symbol (``F = sp.Symbol("F")``), where
a load's magnitude goes: ``ne.force("push", block, F * O.x)`` in the direct form, the matching
generalised force ``lg.generalized_force("push", [F])`` in Lagrange's.  What the symbol means:

* in the **verdict** it is a free value at each sample point, like a coordinate's rate: two
  models agree when they agree for every value ``F`` can take at an instant, hence for every
  input history (a force enters the equations at the instant it acts, never through its
  history);
* in a **simulation** it is the user's function of time -- a closed form (a sympy expression
  of ``t``), a table of ``(times, values)`` interpolated linearly, a Python callable, or on
  the command line an expression of ``t`` read by the grader's safe parser
  (:mod:`dualmech.numeric.inputs`) -- else the input's own default ``history``, which is what
  charts and studies (no caller to ask) drive the problem with.

An input is a scalar; a given force *vector* or *moment* is written with one input per
component along a frame's axes (``Fx * O.x + Fy * O.y`` in ``ne.force``, the same vector in
``lg.force_at``), a motor torque as ``tau * B.z`` (``ne.torque``, ``lg.torque_on``).

A given *motion* (a support moved as ``u(t)``) is not an input of this kind: its rates and
accelerations enter the equations; declare it as a prescribed coordinate instead.  So an
input may not appear in a Lagrangian's ``T``, ``V``, ``R`` or constraints, nor in a direct
model's body positions or rotations (:func:`input_errors` says so), where its time derivative
would be needed and lost.

Example
-------
>>> import sympy as sp
>>> from dualmech import FORCE
>>> F = sp.Symbol("F", real=True)
>>> Input(F, FORCE, "push on the block").symbol
F
"""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Input", "input_errors", "fidelity_input_errors"]


@dataclass(frozen=True)
class Input:
    """A given input of a problem: a load's magnitude known as a function of time.

    Parameters
    ----------
    symbol : sympy.Symbol
        How the models write it (a plain symbol, not ``F(t)``).
    dimension : Dimension
        Its dimension (``FORCE``, ``TORQUE``, ...), for the dimension audit.
    description : str
        What it is, in words (error messages name it).
    history : sympy expression of ``t``, or a table ``(times, values)``, optional
        The default history: what a simulation, a chart or a study drives the problem with
        when its caller gives none (and says so in its stated conditions), e.g.
        ``2 * sp.sin(3 * t)`` with ``t`` from ``dualmech`` (parameters of the problem may
        appear: their values in the run are used).

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import TORQUE, t
    >>> Input(sp.Symbol("tau"), TORQUE, "motor torque").description
    'motor torque'
    >>> Input(sp.Symbol("tau"), TORQUE, "motor torque", sp.sin(t)).history
    sin(t)
    """

    symbol: object
    dimension: object
    description: str = ""
    history: object = None

    def __post_init__(self):
        import sympy as sp
        if not isinstance(self.symbol, sp.Symbol):
            raise TypeError(f"`Input.symbol` must be a sympy Symbol (write F = "
                            f"sp.Symbol(\"F\") and use F in the models), got "
                            f"{self.symbol!r:.60} ({type(self.symbol).__name__}).")
        if not isinstance(self.description, str):
            raise TypeError(f"`Input.description` must be text, got {self.description!r:.60}.")
        h = self.history
        if h is not None and not isinstance(h, sp.Expr) and not (
                isinstance(h, (tuple, list)) and len(h) == 2):
            raise TypeError(f"`Input.history` of {self.symbol} must be a sympy expression of "
                            f"t or a table (times, values), got {h!r:.60}.")

    @property
    def name(self) -> str:
        return self.symbol.name


def input_errors(problem) -> list[str]:
    """Every mistake in ``problem.inputs`` (empty when none): a declaration that is not an
    :class:`Input`, a name declared twice or also a parameter, an input no model uses, or one
    inside a Lagrangian's energies or constraints or a direct model's body positions (a given
    motion, not a load)."""
    from dualmech.model.declared import builder_of
    declared = getattr(problem, "inputs", ()) or ()
    errors, seen = [], set()
    params = {p.symbol.name for p in problem.parameters}
    for i, x in enumerate(declared):
        if not isinstance(x, Input):
            errors.append(f"`inputs[{i}]` must be an Input(symbol, dimension, description), "
                          f"got {x!r:.60}")
            continue
        if x.name in seen or x.name in params:
            errors.append(f"input `{x.name}` is declared twice (as an input, or also as a "
                          "parameter)")
        seen.add(x.name)
        errors += _history_errors(x, params)
    errors += fidelity_input_errors(problem)
    if not seen:
        return errors
    models = problem.models()
    used = set()
    for name, eqs in models.items():
        used |= {s.name for s in eqs.free_symbols()}
        builder = builder_of(eqs)
        for part, exprs in _energies(builder).items():
            inside = sorted(seen & {s.name for e in exprs for s in _symbols(e)})
            for s in inside:
                errors.append(f"model `{name}`: input `{s}` appears in {part}; an input is a "
                              "load's magnitude (a force or torque), written where the load "
                              "acts -- a given motion needs its rates and is a prescribed "
                              "coordinate instead")
    for s in sorted(seen - used):
        errors.append(f"input `{s}` is declared but no model uses it")
    return errors


def fidelity_input_errors(problem) -> list[str]:
    """Every mistake in ``problem.fidelity_inputs`` (empty when none): not a mapping, a name
    that is not a declared input, a declared input left out, a history that is not an
    expression of ``t`` and the parameters.

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import FORCE, Problem, t
    >>> class Pushed(Problem):
    ...     name, inputs = "pushed", (Input(sp.Symbol("F"), FORCE, "push"),)
    ...     fidelity_inputs = {"G": sp.sin(t)}
    >>> fidelity_input_errors(Pushed())    # doctest: +NORMALIZE_WHITESPACE
    ['`fidelity_inputs`: `G` is not a declared input (declared: F)',
     '`fidelity_inputs` gives no history for input `F`']
    """
    drive = getattr(problem, "fidelity_inputs", None) or {}
    if not drive:
        return []
    if not isinstance(drive, dict):
        return [f"`fidelity_inputs` must be a dict {{input name: expression of t}}, got "
                f"{drive!r:.60}"]
    import sympy as sp
    declared = [x.name for x in (getattr(problem, "inputs", ()) or ()) if isinstance(x, Input)]
    params = {p.symbol.name for p in problem.parameters}
    errors = []
    for key, history in drive.items():
        name = getattr(key, "name", key)
        if name not in declared:
            errors.append(f"`fidelity_inputs`: `{name}` is not a declared input (declared: "
                          f"{', '.join(declared) or 'none'})")
        elif not isinstance(history, sp.Expr):
            errors.append(f"`fidelity_inputs`: `{name}` must be a sympy expression of t and "
                          f"the parameters, e.g. F0 * sp.sin(w * t), got {history!r:.60}")
        else:
            errors += _history_errors(Input(sp.Symbol(name), None, "", history), params)
    given = {getattr(k, "name", k) for k in drive}
    errors += [f"`fidelity_inputs` gives no history for input `{name}`"
               for name in declared if name not in given]
    return [e.replace("its default history", "its `fidelity_inputs` history") for e in errors]


def _history_errors(x: Input, params: set) -> list[str]:
    """A declared default history naming something other than ``t`` and the parameters."""
    from dualmech.model.kinematics import t
    h = x.history
    if h is None or not hasattr(h, "free_symbols"):
        return []
    extra = sorted(s.name for s in h.free_symbols if s != t and s.name not in params)
    if extra:
        return [f"input `{x.name}`: its default history {h} names {', '.join(extra)}, "
                "which are neither t (from dualmech) nor parameters"]
    return []


def _energies(builder) -> dict:
    """``{"T": [...], "V": [...], ...}`` of a Lagrangian builder, ``{"the position of B":
    [...]}`` of each body of a direct model's builder (nothing for any other)."""
    out = {}
    declarations = getattr(builder, "declarations", None)
    if callable(declarations) and hasattr(builder, "_reactions"):
        decl = declarations()
        for body in decl.bodies:
            where = body.masscenter.pos_from().express(decl.ground).components
            spin = getattr(body, "frame", None)
            turn = spin.ang_vel_in(decl.ground).express(decl.ground).components \
                if spin is not None else []
            out[f"the position or rotation of body `{body.name}`"] = list(where) + list(turn)
    for part, attr in (("T", "_T"), ("V", "_V"), ("R (dissipation)", "_R")):
        terms = getattr(builder, attr, None)
        if isinstance(terms, dict):
            out[part] = list(terms.values())
    cons = getattr(builder, "_constraints", None)
    if isinstance(cons, list):
        out["a constraint"] = [level for _, level, _ in cons]
    return out


def _symbols(expr) -> set:
    return getattr(expr, "free_symbols", set())
