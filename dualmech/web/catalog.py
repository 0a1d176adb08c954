r"""What the page shows about one problem: title, source, sketch, names with units, quantities.

A :class:`ProblemInfo` is built once per served problem from the problem itself (never from
anything a client sends): its declared coordinates and parameters with SI units, the
quantities a student may be asked for, the names an answer may use (the grader's
:class:`~dualmech.grade.vocabulary.Vocabulary`) and the sign-convention sketch of the
problem's module, which every problem module carries.

Example
-------
>>> info = ProblemInfo.build("simple_pendulum")
>>> info.title, [c["name"] for c in info.coordinates], info.parameters[1]["unit"]
('Simple pendulum', ['theta'], 'm')
>>> "eom" in info.quantities and "pivot" in info.sketch
True
"""
from __future__ import annotations

from dataclasses import dataclass, field

from dualmech.model.sketch import sketch_of

__all__ = ["ProblemInfo", "unit", "sketch_of"]

_SI = (("mass", "kg"), ("length", "m"), ("time", "s"))
_SUPER = str.maketrans("-0123456789/", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹ᐟ")


def unit(dimension) -> str:
    """The SI unit of a dimension, as text (``kg m s⁻²``); ``rad`` for an angle, ``1`` for a
    pure number.

    >>> from dualmech.model.dimensions import FORCE, ANGLE
    >>> unit(FORCE), unit(ANGLE)
    ('kg m s⁻²', 'rad')
    """
    from dualmech.model.dimensions import as_dimension, reduce
    dimension = as_dimension(dimension)
    if dimension.power("angle") and not reduce(dimension):
        return "rad"
    exps = dict(reduce(dimension))
    parts = []
    for name, symbol in _SI:
        e = exps.pop(name, 0)
        if e:
            parts.append(symbol if e == 1 else f"{symbol}{str(e).translate(_SUPER)}")
    parts += [f"{n}{str(e).translate(_SUPER)}" for n, e in exps.items()]
    return " ".join(parts) or "1"


@dataclass
class ProblemInfo:
    """One served problem as the page and the API show it (see the module docstring).

    ``spec`` is what the server was started with (a catalogue name); ``name`` the problem's
    own name, which clients use; ``accepted`` the names an answer may use, by kind, each with
    its aliases.
    """

    name: str
    spec: str
    title: str
    source: str
    summary: str
    sketch: str
    coordinates: list = field(default_factory=list)
    parameters: list = field(default_factory=list)
    reactions: list = field(default_factory=list)
    quantities: dict = field(default_factory=dict)
    accepted: dict = field(default_factory=dict)
    context: object = field(default=None, repr=False)

    @classmethod
    def build(cls, spec: str) -> "ProblemInfo":
        """Load problem ``spec`` (a catalogue name) and gather what the page shows."""
        from dualmech.grade import Grader
        grader = Grader.of(spec)
        problem = grader.problem
        ctx = grader.context
        coords = [{"name": c.name, "description": c.description, "unit": unit(c.dimension),
                   "range": list(c.range)} for c in problem.coordinates]
        params = [{"name": str(p.symbol), "description": p.description,
                   "unit": unit(p.dimension), "default": p.default}
                  for p in problem.parameters]
        reactions = [{"name": r.name, "unit": unit(r.dimension), "direction": r.direction}
                     for r in problem.reactions]
        voc = ctx.vocabulary
        accepted = {kind: [{"name": n, "aliases": [a for a in voc.aliases.get(n, [])
                                                  if voc.table.get(a) is not None]}
                           for n in names]
                    for kind, names in voc.canonical.items()}
        return cls(problem.name, spec, problem.title, problem.source, problem.summary,
                   sketch_of(problem), coords, params, reactions, grader.quantities(),
                   accepted, ctx)

    def to_dict(self) -> dict:
        """The JSON form (``/api/problems/{name}``)."""
        from dualmech.sources import source_fields
        return {"name": self.name, "title": self.title, **source_fields(self.source),
                "summary": self.summary, "sketch": self.sketch,
                "coordinates": self.coordinates, "parameters": self.parameters,
                "reactions": self.reactions, "quantities": self.quantities,
                "accepted_names": self.accepted}
