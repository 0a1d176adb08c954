"""What a problem declares: parameters, coordinates, reactions, its models and the source's answers.

A problem module subclasses :class:`Problem`, declares its quantities with their physical
dimensions, default values and admissible ranges, and implements one method per derivation
(each returning an :class:`~dualmech.model.equations.EquationSet`), written independently of each
other.  The source's printed answers are transcribed as :class:`Published` entries; the
comparator decides for each whether it is right.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t, Lagrangian
>>> from dualmech.model.problem import Problem, Parameter, Coordinate
>>> from dualmech.model.dimensions import MASS, STIFFNESS, LENGTH
>>> m, k = sp.symbols("m k", positive=True); x = coordinate("x")
>>> class Oscillator(Problem):
...     name, title, source = "oscillator", "Mass on a spring", "000: example 11"
...     parameters = (Parameter(m, MASS, 2, (0.1, 10)), Parameter(k, STIFFNESS, 50, (1, 500)))
...     coordinates = (Coordinate(x, LENGTH, (-1, 1)),)
...     def lagrange(self):
...         lg = Lagrangian(coordinates=[x])
...         lg.kinetic("T", m*x.diff(t)**2/2); lg.potential("V", k*x**2/2)
...         return lg.equations()
>>> Oscillator().validate()
>>> list(Oscillator().models())
['lagrange']
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from dualmech.model._expr import as_expr
from dualmech.model.dimensions import ENERGY, Dimension, as_dimension, audit_rows, quoted, reduce
from dualmech.model.equations import EquationSet, ModelError, Rows
from dualmech.model.drawing import ChartScene, Drawing, drawing_errors
from dualmech.model.facts import (FidelityRung, Probe, SteadyMotion, StiffScene,
                                  declaration_errors)
from dualmech.model.inputs import Input, input_errors
from dualmech.model.phases import phase_errors
from dualmech.model.kinematics import t

__all__ = ["Parameter", "Coordinate", "Reaction", "Published", "Problem", "ProblemError",
           "Probe", "StiffScene", "FidelityRung"]


class ProblemError(ModelError):
    """A problem declaration with one or more mistakes (all listed in the message).

    Examples
    --------
    >>> from dualmech import Problem
    >>> class Empty(Problem):
    ...     name = "empty"
    >>> Empty().validate()  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    dualmech.model.problem.ProblemError: problem `empty` has ... mistake(s):
    ...
    """


@dataclass(frozen=True)
class Parameter:
    """A constant of the problem: symbol, dimension, default value and admissible range.

    The exact test samples inside ``range``; a simulation refuses values outside it.

    Examples
    --------
    >>> import sympy as sp
    >>> from dualmech import LENGTH, Parameter
    >>> l = sp.Symbol("l", positive=True)
    >>> Parameter(l, LENGTH, 0.5, (0.1, 3.0), "length of the rod").range
    (0.1, 3.0)
    """

    symbol: sp.Symbol
    dimension: Dimension
    default: float
    range: tuple[float, float]
    description: str = ""

    def __post_init__(self):
        if isinstance(self.symbol, str):
            raise TypeError(f"`Parameter` needs a sympy symbol, got the text {self.symbol!r}: "
                            f"use `sp.Symbol({self.symbol!r}, positive=True)` (or the "
                            "assumptions it has).")
        if not isinstance(self.symbol, sp.Symbol):
            raise TypeError(f"`Parameter` needs a sympy Symbol, got {self.symbol!r} "
                            f"({type(self.symbol).__name__}).")
        if isinstance(self.default, (str, bytes, bool)) or not isinstance(
                self.default, (int, float, sp.Number)):
            raise TypeError(f"parameter `{self.symbol}`: the default must be a number, got "
                            f"{self.default!r}.")
        _check_range(f"parameter `{self.symbol}`", self.range)
        _own_dimension(self)


@dataclass(frozen=True)
class Coordinate:
    """A generalised coordinate ``q(t)`` with its dimension and the ranges of ``q`` and ``q'``.

    The ranges bound the sampled states (and the default initial state); ``domain`` is the
    interval where the model holds: identities that leave the rational world are decided over
    it, and a chart's scene, an animation or a phased run stops where the coordinate leaves
    it (a ladder's angle past the floor), saying so.

    Examples
    --------
    >>> from dualmech import ANGLE, Coordinate, coordinate
    >>> c = Coordinate(coordinate("theta"), ANGLE, (-2.5, 2.5), (-4.0, 4.0), "from the vertical")
    >>> c.name, c.rate_range
    ('theta', (-4.0, 4.0))
    """

    function: sp.Expr
    dimension: Dimension
    range: tuple[float, float]
    rate_range: tuple[float, float] = (-2.0, 2.0)
    description: str = ""
    domain: tuple | None = None

    def __post_init__(self):
        if isinstance(self.function, str):
            raise TypeError(f"`Coordinate` needs a coordinate, got the text {self.function!r}: "
                            f"use `dualmech.coordinate({self.function!r})`.")
        if not (isinstance(self.function, sp.core.function.AppliedUndef)
                and len(self.function.args) == 1 and self.function.args[0].is_Symbol):
            raise TypeError(f"`Coordinate` needs a function of time made by "
                            f"`dualmech.coordinate(name)`, got {self.function!r}.")
        _check_range(f"coordinate `{self.function.func.__name__}`", self.range)
        _check_range(f"coordinate `{self.function.func.__name__}` rate", self.rate_range)
        if self.domain is not None:
            _check_range(f"coordinate `{self.function.func.__name__}` domain", self.domain,
                         finite=False)
        _own_dimension(self)

    @property
    def name(self) -> str:
        return self.function.func.__name__


@dataclass(frozen=True)
class Reaction:
    """An unknown reaction (or multiplier) named as in the direct model, with its meaning.

    ``direction`` says in words which way a positive value acts and on what.

    Examples
    --------
    >>> from dualmech import FORCE, Reaction
    >>> Reaction("T", FORCE, "rod on bob, towards the pivot").name
    'T'
    """

    name: str
    dimension: Dimension
    direction: str

    def __post_init__(self):
        _own_dimension(self)


def _own_dimension(declared) -> None:
    """A sympy Dimension declared for a quantity, converted to ours (what is no dimension is
    left for :meth:`Problem.validate` to report)."""
    try:
        dimension = as_dimension(declared.dimension)
    except (TypeError, ValueError):
        return
    object.__setattr__(declared, "dimension", dimension)


@dataclass(frozen=True)
class Published:
    """A printed answer from the source, transcribed for checking.

    ``kind``:
      * ``"equation"`` -- ``printed`` are left sides of equations (``= 0``) that must follow
        from the equations of motion (any combination of them is accepted); they may use the
        coordinates' derivatives and the reaction symbols;
      * ``"motion"`` -- ``printed`` claims to *be* the equations of motion: each must follow
        from the derivations, and together they must determine every acceleration (a set
        such as ``(e1, 2*e1)`` or ``0 = 0`` is wrong: it determines nothing);
      * ``"expression"`` -- ``printed`` must equal ``reference`` (our own derivation, in the
        same order) at every state of motion;
      * ``"eigenvalues"`` -- ``printed`` are the eigenvalues (numbers, complex ones with
        ``sympy.I``) of the problem's declared
        :attr:`~dualmech.model.problem.Problem.steady_motion`, linearised in the reference
        model, at the value ``at`` of its parameter: the ones that do not vanish at every
        value (a heading, a neighbouring steady motion), each within ``tolerance``;
      * ``"critical"`` -- ``printed`` is one value of the steady motion's parameter where its
        stability changes (the number of eigenvalues with a positive real part changes: a
        weave speed, a capsize speed, a critical speed), within ``tolerance``.

    ``coordinates`` names the model whose coordinates the printed answer uses (default: the
    reference model's).  ``where`` says where in the source it is printed.

    Examples
    --------
    The pendulum's equation as a source prints it, and a kinetic energy against our own:

    >>> import sympy as sp
    >>> from dualmech import Published, coordinate, rate
    >>> theta = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
    >>> eom = Published("equation of motion", "motion",
    ...                 (m * l**2 * rate(theta, 2) + m * g * l * sp.sin(theta),), where="(3)")
    >>> T = Published("T", "expression", (m * (l * rate(theta))**2 / 2,),
    ...               (m * l**2 * rate(theta)**2 / 2,), where="(2)")
    >>> eom.kind, T.reference == (m * l**2 * rate(theta)**2 / 2,)
    ('motion', True)

    A critical speed, as a benchmark prints it (judged against the linearised steady motion):

    >>> Published("weave speed", "critical", (4.29238253634111,), tolerance=1e-6).printed
    (4.29238253634111,)
    """

    label: str
    kind: str
    printed: tuple
    reference: tuple = ()
    where: str = ""
    coordinates: str | None = None
    at: object = None
    tolerance: float = 0.0

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"`kind` must be one of {', '.join(map(repr, KINDS))}, got "
                             f"{self.kind!r}.")
        if self.kind in ("eigenvalues", "critical"):
            _stability_claim(self)
            return
        object.__setattr__(self, "printed", tuple(as_expr(p) for p in _tuple(self.printed)))
        object.__setattr__(self, "reference", tuple(as_expr(p) for p in _tuple(self.reference)))
        if self.kind == "expression" and len(self.reference) != len(self.printed):
            raise ValueError(f"published `{self.label}`: {len(self.printed)} printed expressions "
                             f"but {len(self.reference)} reference expressions.")


#: the kinds of printed answer :class:`Published` takes
KINDS = ("equation", "motion", "expression", "eigenvalues", "critical")


def _stability_claim(pub: Published) -> None:
    """Check and normalise a claim about a steady motion's stability (numbers, not formulas)."""
    import math
    values = []
    for p in _tuple(pub.printed):
        z = as_expr(p)
        if z.free_symbols or not z.is_number or z.is_finite is False:
            raise ValueError(f"published `{pub.label}`: a {pub.kind} claim prints numbers, "
                             f"got {p!r:.60}.")
        values.append(z)
    if not values or (pub.kind == "critical" and len(values) != 1):
        raise ValueError(f"published `{pub.label}`: a critical claim prints one value, an "
                         "eigenvalues claim at least one.")
    if pub.kind == "critical" and not values[0].is_real:
        raise ValueError(f"published `{pub.label}`: a critical value is real, got {values[0]}.")
    if isinstance(pub.tolerance, bool) or not isinstance(pub.tolerance, (int, float)) or \
            not math.isfinite(pub.tolerance) or pub.tolerance <= 0:
        raise ValueError(f"published `{pub.label}`: give `tolerance`, a positive number (how "
                         "close a computed value must be to the printed one).")
    if pub.kind == "eigenvalues":
        at = as_expr(pub.at) if pub.at is not None else None
        if at is None or at.free_symbols or not at.is_real:
            raise ValueError(f"published `{pub.label}`: give `at`, the value of the steady "
                             "motion's parameter the eigenvalues are printed for.")
    elif pub.at is not None:
        raise ValueError(f"published `{pub.label}`: a critical claim takes no `at`.")
    object.__setattr__(pub, "printed", tuple(values))
    object.__setattr__(pub, "reference", ())


def _check_range(what: str, rng, finite: bool = True) -> None:
    import math
    if isinstance(rng, (str, bytes)) or any(isinstance(x, (str, bytes, bool)) for x in rng):
        raise TypeError(f"{what}: range must be two numbers (low, high), got the text "
                        f"{rng!r:.60}.")
    try:
        lo, hi = (float(x) for x in rng)
    except (TypeError, ValueError):
        raise TypeError(f"{what}: range must be two numbers (low, high), got {rng!r}.") \
            from None
    if finite and not (math.isfinite(lo) and math.isfinite(hi)):
        raise ValueError(f"{what}: range {rng!r} must be finite.")
    if math.isnan(lo) or math.isnan(hi):
        raise ValueError(f"{what}: range {rng!r} must be numbers, not NaN.")


def prescribed_coordinates(models) -> set:
    """The coordinates some model of ``models`` gives a known motion (``lg.prescribe(phi,
    Omega * t)``): declared, and used, though no model has them among its unknowns."""
    from dualmech.model.declared import builder_of
    return {q for m in models for q in getattr(builder_of(m), "prescribed", {})}


def _tuple(x) -> tuple:
    if isinstance(x, (list, tuple)):
        return tuple(x)
    if isinstance(x, sp.MatrixBase):
        return tuple(x)
    return (x,)


class Problem:
    """Base class of every problem; see the module docstring.

    A problem class declares what it is made of as class attributes, and one method per
    derivation (``newton_euler``, ``lagrange`` and those named in ``extra_models``), each
    returning an :class:`~dualmech.model.equations.EquationSet`.

    Attributes
    ----------
    name, title, source, summary : str
        The catalogue name, a title, the source file and place, one line on what it shows.
    parameters, coordinates, reactions : tuple
        :class:`Parameter`, :class:`Coordinate` (of the reference model) and
        :class:`Reaction` declarations.
    singular : tuple
        Expressions whose zeros are the singular set, e.g. ``(sp.cos(theta),)``.
    reference : str
        The model the others are compared with (default ``"lagrange"``).
    extra_models : tuple of str
        Model methods besides ``newton_euler`` and ``lagrange`` (:attr:`model_names`).
    aliases : dict
        Names students use for the source's symbols (``{"l": "a"}`` where the source writes
        ``a`` for a length students call ``l``); the grader accepts an alias only when no
        symbol of the problem has that name.
    referee, referee_note : bool, str
        ``referee = False`` (with ``referee_note`` saying why) declares that the direct
        models are deliberately not the mechanics of their declared bodies (a simplified
        model that neglects a coupling), so no referee (:mod:`dualmech.verify.referee`) is
        derived from them.
    dimensions_unchecked : str
        Why the dimension audit cannot judge this problem's equations, when it cannot: a
        problem whose lengths are fixed at numbers (the benchmark bicycle's geometry) leaves
        the audit no dimension to read in them, and every term would be listed.  ``check``
        then says "dimension audit: not run (...)" with this reason instead.

    The facts below are physics, or a choice of scene, that the equations do not carry; the
    numeric studies read them from here and nothing else (all default to none declared).
    A *state* is ``[q..., q'...]`` in the reference coordinates, or a mapping
    ``{q: value, q.diff(t): rate}`` with missing rates zero.

    unilateral : dict
        One-sided reactions, ``{reaction name: what happens when it would change sign}``:
        each must stay >= 0 along its declared direction (a track that can only push, a
        string that can only pull).  Simulations stop where one would have to change sign
        and say so (:func:`~dualmech.numeric.contacts.watch`), e.g.
        ``unilateral = {"T": "the string goes slack"}``.
    probes : tuple of :class:`~dualmech.model.facts.Probe`
        Runs heading for the singular set, for the atlas's singularities section:
        ``probes = (Probe((1.3, 1e-3, 3.5, 0.0), "lagrange", 1.0, "the car runs over the
        pivot axis"),)`` -- the state, the formulation to watch, the seconds to run, why.
    stiff_scene : :class:`~dualmech.model.facts.StiffScene` or None
        The scene of the stiffness sweep: ``StiffScene("k", (2.2, 2.5, 0.0, 0.0), 0.5,
        "released at rest with the spring at its free length")``.
    fidelity_ladder : tuple of :class:`~dualmech.model.facts.FidelityRung`
        Simpler models below the richest (last):  ``(FidelityRung("point masses",
        lambda: NLinkPendulum(n=3), "the rods' mass distribution"), FidelityRung("rigid
        rods", lambda: NLinkRigidPendulum(n=3)))``.
    chaotic_state : state
        Where the chaos section starts, a state whose motion is chaotic (default: the
        initial state), e.g. ``chaotic_state = (2.0, 2.5, 0.0, 0.0)``.
    initial_state : state
        Where simulations, charts and studies start by default (otherwise 60 % into each
        coordinate's range, at rest), e.g. ``initial_state = {theta: 2.0, rate(theta): 4.0}``.
    steady_motion : :class:`~dualmech.model.facts.SteadyMotion` or None
        The steady motion ``dualmech stability`` linearises about by default, e.g.
        ``SteadyMotion({rate(phi): v / r, rate(x): v}, "v", (0, 10, 101), "upright
        rolling")`` (:mod:`dualmech.model.stability`).
    inputs : tuple of :class:`~dualmech.model.inputs.Input`
        Given inputs: a load's magnitude known only as a function of time, written in the
        models as a plain symbol where the load acts.  The verdict treats it as a free value
        at each sample point (the models agree for every input history); a simulation takes
        its history from the caller (``simulate(p, inputs={"F": lambda t: 2 * sin(t)})``, a
        table ``(times, values)``, or ``dualmech simulate --input 'F=2*sin(t)'``), e.g.
        ``inputs = (Input(F, FORCE, "push on the block"),)`` with ``ne.force("push", block,
        F * O.x)`` and ``lg.generalized_force("push", [F])``; a force vector is one input per
        component, a motor torque one on an axis (``ne.torque``, ``lg.torque_on``).
        ``Input(F, FORCE, "push", history=2 * sp.sin(3 * t))`` declares a default history,
        used by a run given none and by charts, atlases and animations (their stated
        conditions say so); a simulation with neither is refused, naming the input
        (:mod:`dualmech.numeric.inputs`).
    fidelity_inputs : dict
        The scene's given inputs for ``dualmech fidelity`` (:mod:`~dualmech.numeric.studies.
        fidelity`), ``{input name: expression of t and the parameters}``, one for every
        declared input; with it the fidelity ladder of a driven problem runs every rung
        driven by that history from the initial state (the linearised rung about the
        equilibrium without inputs), e.g. ``fidelity_inputs = {"F": F0 * sp.sin(w * t)}``
        with ``t`` from ``dualmech``; without it the inputs' default histories serve when
        each input declares one as an expression, else a driven problem has no ladder and
        ``dualmech fidelity`` says to declare it.
    phases : dict
        What follows when a one-sided reaction lets go: ``{reaction: Phase(next problem,
        {next coordinate: expression of these coordinates}, why)}``, the reaction declared in
        ``unilateral`` (:mod:`dualmech.model.phases`); e.g. a ladder on a smooth floor and
        wall, ``phases = {"N_w": Phase(FreeLadder, {x: L / 2 * sp.sin(theta), theta: theta},
        "the ladder leaves the wall")}``.  :func:`~dualmech.numeric.phases.simulate_phases`
        continues with it, the state mapped across.
    drawing : :class:`~dualmech.model.drawing.Drawing` or None
        How pictures draw the bodies (points and the lines joining them), e.g.
        ``Drawing({"pivot": (0, y_p), "bob": (l * sp.sin(theta), y_p - l * sp.cos(theta))},
        lines=(("pivot", "bob"),))``; default: the direct form's mass centres and reaction
        points, no lines (:mod:`dualmech.numeric.scene`).
    chart_scenes : tuple of :class:`~dualmech.model.drawing.ChartScene`
        Further scenes the report's chart draws beside the default one -- other parameter
        values or initial states that teach the contrast, e.g. ``ChartScene({"Omega": 20},
        {theta: 3.0}, "too slow: a^2 Omega^2 < 2 g l, the pendulum falls")``.

    Every declaration is checked by :meth:`validate`: a reaction, parameter or model it
    names must exist, a state must have one value per coordinate and rate.

    Examples
    --------
    >>> import sympy as sp
    >>> from dualmech import (Problem, Parameter, Coordinate, Reaction, StiffScene, NewtonEuler,
    ...                       Particle, Point, Frame, coordinate, MASS, STIFFNESS, LENGTH,
    ...                       FORCE, ACCELERATION)
    >>> m, k, g = sp.symbols("m k g", positive=True); x = coordinate("x")
    >>> class Block(Problem):
    ...     name, title, source = "block", "Block on a spring, on a floor", "000: example"
    ...     parameters = (Parameter(m, MASS, 2, (0.1, 10)), Parameter(k, STIFFNESS, 50, (1, 500)),
    ...                   Parameter(g, ACCELERATION, 9.81, (9, 10)))
    ...     coordinates = (Coordinate(x, LENGTH, (-1, 1)),)
    ...     reactions = (Reaction("N", FORCE, "floor on block, up"),)
    ...     unilateral = {"N": "the block lifts off the floor"}
    ...     stiff_scene = StiffScene("k", (0.0, 0.0), 1.0, "at rest where the spring is free")
    ...     initial_state = {x: 0.3}
    ...     reference = "newton_euler"
    ...     def newton_euler(self):
    ...         O = Frame.ground("O"); block = Particle("block", m, Point.origin(O).locate(
    ...             "B", x * O.x))
    ...         ne = NewtonEuler(coordinates=[x], ground=O)
    ...         ne.gravity(-g * O.y); ne.force("spring", block, -k * x * O.x)
    ...         ne.reaction("N", block, O.y)
    ...         ne.linear_momentum(block, O.x); ne.linear_momentum(block, O.y)
    ...         return ne.equations()
    >>> Block().validate()
    >>> class Typo(Block):
    ...     unilateral = {"n": "the block lifts off the floor"}
    >>> Typo().validate()
    Traceback (most recent call last):
    ...
    dualmech.model.problem.ProblemError: problem `block` has 1 mistake(s):
      - `unilateral`: `n` is not a declared reaction (declared: N)
    """

    name: str = ""
    title: str = ""
    source: str = ""
    summary: str = ""
    parameters: tuple = ()
    coordinates: tuple = ()
    reactions: tuple = ()
    singular: tuple = ()
    reference: str = "lagrange"
    extra_models: tuple = ()
    aliases: dict = {}
    # -- facts the equations do not carry (see the class docstring) ----------------------
    unilateral: dict = {}
    probes: tuple = ()
    stiff_scene: StiffScene | None = None
    fidelity_ladder: tuple = ()
    chaotic_state: tuple | dict = ()
    initial_state: tuple | dict = ()
    steady_motion: SteadyMotion | None = None
    inputs: tuple = ()
    fidelity_inputs: dict = {}
    phases: dict = {}
    drawing: Drawing | None = None
    chart_scenes: tuple = ()
    referee: bool = True
    referee_note: str = ""
    dimensions_unchecked: str = ""

    # -- to be provided by subclasses --------------------------------------------------
    def coordinate_maps(self) -> dict:
        """``{model name: {that model's q(t): expression in the reference coordinates}}``."""
        return {}

    def published(self) -> list[Published]:
        return []

    # -- derived -----------------------------------------------------------------------
    @property
    def model_names(self) -> list[str]:
        names = [n for n in ("newton_euler", "lagrange") if callable(getattr(self, n, None))]
        return names + [n for n in self.extra_models if n not in names]

    def models(self) -> dict[str, EquationSet]:
        """Every derivation, built once per problem instance."""
        if "_models" not in self.__dict__:
            built = {}
            for n in self.model_names:
                eqs = getattr(self, n)()
                if not isinstance(eqs, EquationSet):
                    raise ProblemError(f"`{type(self).__name__}.{n}()` must return an "
                                       f"EquationSet, got {type(eqs).__name__}.")
                built[n] = eqs
            self.__dict__["_models"] = built
        return self.__dict__["_models"]

    def model(self, name: str) -> EquationSet:
        try:
            return self.models()[name]
        except KeyError:
            raise KeyError(f"problem `{self.name}` has no model {name!r}; it has "
                           f"{list(self.models())}.") from None

    @property
    def parameter_symbols(self) -> tuple:
        """Every symbol a sample point gives a value to: the parameters, then the given
        inputs (:attr:`inputs`: free values at each point, like a rate)."""
        return tuple(p.symbol for p in self.parameters) + self.input_symbols

    @property
    def input_symbols(self) -> tuple:
        """The symbols of the given inputs (:attr:`inputs`), in declaration order."""
        return tuple(x.symbol for x in (self.inputs or ()) if isinstance(x, Input))

    @property
    def coordinate_functions(self) -> tuple:
        return tuple(c.function for c in self.coordinates)

    def defaults(self) -> dict:
        return {p.symbol: p.default for p in self.parameters}

    def dimensions(self) -> dict:
        """Declared dimension of every symbol and coordinate (and ``t``)."""
        dims = {p.symbol: p.dimension for p in self.parameters}
        dims.update({x.symbol: x.dimension for x in (self.inputs or ())
                     if isinstance(x, Input)})
        for c in self.all_coordinates():
            dims[c.function] = c.dimension
        for r in self.reactions:
            dims[sp.Symbol(r.name, real=True)] = r.dimension
        return dims

    def all_coordinates(self) -> list[Coordinate]:
        """Coordinates of the reference model plus those of other models (``extra_coordinates``)."""
        return list(self.coordinates) + list(getattr(self, "extra_coordinates", ()))

    def coordinate_info(self, q) -> Coordinate:
        for c in self.all_coordinates():
            if c.function == q:
                return c
        raise ProblemError(f"problem `{self.name}`: coordinate {q} is not declared.")

    def reaction_info(self) -> dict:
        return {r.name: r for r in self.reactions}

    def in_reference_coordinates(self, eqs: EquationSet) -> EquationSet:
        """``eqs`` rewritten in the reference model's coordinates (if it uses others)."""
        ref = self.model(self.reference)
        if set(eqs.coordinates) == set(ref.coordinates):
            return eqs
        cache = self.__dict__.setdefault("_mapped", {})
        hit = cache.get(id(eqs))
        if hit is not None and hit[0] is eqs:
            return hit[1]
        maps = self.coordinate_maps()
        if eqs.name not in maps:
            raise ProblemError(f"problem `{self.name}`: model `{eqs.name}` uses coordinates "
                               f"{list(eqs.coordinates)}, the reference uses "
                               f"{list(ref.coordinates)}; give the map in coordinate_maps().")
        mapped = eqs.change_coordinates(ref.coordinates, maps[eqs.name], name=eqs.name)
        cache[id(eqs)] = (eqs, mapped)  # keep eqs alive so its id is not reused
        return mapped

    # -- validation --------------------------------------------------------------------
    def validate(self) -> None:
        """Check the declaration; raise one :class:`ProblemError` listing every mistake."""
        errors: list[str] = []
        for attr in ("name", "title", "source"):
            if not getattr(self, attr):
                errors.append(f"`{attr}` is empty")
        declared = set(self.parameter_symbols) | {t}
        for p in self.parameters:
            lo, hi = p.range
            if not lo < hi:
                errors.append(f"parameter `{p.symbol}`: range {p.range} must have low < high")
            elif not lo <= p.default <= hi:
                errors.append(f"parameter `{p.symbol}`: default {p.default} is outside {p.range}")
            try:
                reduce(p.dimension)
            except (TypeError, ValueError) as exc:
                errors.append(f"parameter `{p.symbol}`: {exc}")
        for c in self.all_coordinates():
            if not c.range[0] < c.range[1]:
                errors.append(f"coordinate `{c.name}`: range {c.range} must have low < high")
        try:
            models = self.models()
        except ModelError as exc:
            raise ProblemError(f"problem `{self.name}`: {exc}") from exc
        if self.reference not in models:
            errors.append(f"reference model `{self.reference}` is not among {list(models)}")
        dims = self.dimensions()
        reaction_names = {r.name for r in self.reactions}
        for mname, eqs in models.items():
            for u in eqs.unknowns:
                if u.name not in reaction_names:
                    errors.append(f"model `{mname}`: reaction `{u}` is not declared in "
                                  "`reactions`")
            for s in sorted(eqs.free_symbols() - declared - set(eqs.unknowns), key=str):
                errors.append(f"model `{mname}`: symbol `{s}` is not a declared parameter")
            for q in eqs.coordinates:
                if q not in dims:
                    errors.append(f"model `{mname}`: coordinate {q} is not declared")
        used_unknowns = {u.name for eqs in models.values() for u in eqs.unknowns}
        for r in self.reactions:
            if r.name not in used_unknowns:
                errors.append(f"reaction `{r.name}` is declared but no model uses it (a typo "
                              "in the model's reaction name, or a stale declaration)")
        used_coords = {q for eqs in models.values() for q in eqs.coordinates}
        used_coords |= prescribed_coordinates(models.values())   # a declared motion: used
        for c in self.all_coordinates():
            if c.function not in used_coords:
                errors.append(f"coordinate `{c.name}` is declared but no model uses it")
        errors += declaration_errors(self)
        errors += input_errors(self)
        errors += phase_errors(self)
        errors += drawing_errors(self)
        if errors:
            raise ProblemError(f"problem `{self.name or type(self).__name__}` has "
                               f"{len(errors)} mistake(s):\n  - " + "\n  - ".join(errors))

    def dimension_issues(self) -> list[str]:
        """Dimensional inconsistencies of every derived equation (empty when all consistent),
        as plain text; :meth:`dimension_audit` gives the same sentences with their terms as
        expressions."""
        return [quoted(s) for s in self.dimension_audit()]

    def dimension_audit(self) -> list[tuple]:
        """Dimensional inconsistencies of every derived equation, each a sentence: a tuple of
        text and the sympy expressions of the terms it names (empty when all consistent)."""
        dims = self.dimensions()
        out = []
        for mname, eqs in self.models().items():
            rows = eqs.equations
            held = isinstance(rows, Rows)   # audited in symengine, as the derivation left them
            names = rows.names if held else None
            expected = []
            for label in eqs.labels:
                x = None
                if label.startswith("Lagrange, "):
                    q = next(q for q in eqs.coordinates if q.func.__name__ == label[10:])
                    x = ENERGY / dims[q]
                expected.append(x)
            found = audit_rows(rows.se if held else rows, dims, expected, names=names)
            for label, issues in zip(eqs.labels, found):
                out += [(f"{mname} [{label}]: ",) + issue.sentence() for issue in issues]
        return out

    def __repr__(self) -> str:
        return f"<Problem {self.name}: {self.title}>"

    def _repr_html_(self) -> str:
        """Jupyter: the problem's card (symbols, models, equations typeset)."""
        from dualmech.report.jupyter import problem_html
        return problem_html(self)
