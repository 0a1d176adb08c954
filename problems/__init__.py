"""The problems of the course sources, each written twice (Newton--Euler and Lagrange).

Every module of this package (names not starting with ``_``) defines one or more
:class:`dualmech.model.problem.Problem` subclasses and lists them in ``PROBLEMS``.  The catalogue is
found by reading the modules' *declarations* (their source text, parsed with :mod:`ast`):
listing it imports nothing, so ``dualmech list`` never builds a model.  :func:`all_problems`
imports the modules and gives instances; :func:`get` (or :func:`load`) finds one problem by
name -- or from a *spec*: a file ``path.py[:Class]``, ``module:Class``, or a catalogue a course
package registers under the entry-point group ``dualmech.problems`` (see :mod:`._loader`).

A problem class declares, as literals, ``name``, ``title``, ``source`` (and optionally
``summary``), ``coordinates = (Coordinate(...), ...)`` and ``reactions = (Reaction("F", ...),
...)``; :func:`declarations` reads those.  A parametric problem (``n_link_pendulum``) declares
``parametric = "n"`` and builds its coordinates in ``__init__``.

Systems of the sources that are deliberately not modelled are listed in :data:`OUT_OF_SCOPE`
with the reason.
"""
from __future__ import annotations

import ast
import importlib
from dataclasses import dataclass
from pathlib import Path

from dualmech.problems._loader import (GROUP, SpecError, canonical, catalogue_classes,
                                       catalogue_specs, problem_files, registered, user_error)
from dualmech.problems._loader import resolve as _resolve

__all__ = ["Declaration", "OUT_OF_SCOPE", "declarations", "all_problems", "registered_specs",
           "get", "load", "named", "is_name", "resolve", "module_of", "SpecError", "canonical",
           "registered", "catalogue_classes", "catalogue_specs", "problem_files", "user_error",
           "GROUP"]

_HERE = Path(__file__).resolve().parent

#: Systems of the sources that the catalogue does not model: ``(name, source, reason)``.
OUT_OF_SCOPE = (
    ("shaft_torsion", "004_f75aa9bb64d0737a.txt: problem 3",
     "a continuous elastic shaft (a field phi(x), solved by the calculus of variations): "
     "dualmech models systems with finitely many coordinates; a discretised shaft would be a "
     "different problem from the one the source solves"),
    ("string_modes", "002_df41972c66c4514e.txt: vibration of a taut string",
     "a continuous string (a wave equation in u(x, t)): dualmech models systems with finitely "
     "many coordinates; the beaded string (taut_string_masses) is its finite version"),
)


@dataclass(frozen=True)
class Declaration:
    """What a problem module declares about one problem, read without importing it."""

    module: str
    cls: str
    name: str
    title: str
    source: str
    summary: str
    coordinates: tuple
    reactions: tuple
    parametric: str = ""

    @property
    def dof(self) -> int | str:
        return self.parametric or len(self.coordinates)

    @property
    def source_file(self) -> str:
        return self.source.split(":")[0]


def _literal(node):
    try:
        return ast.literal_eval(node)
    except ValueError:
        return None


def _call_names(node, func: str) -> tuple:
    """First arguments of the ``func(...)`` calls in a tuple literal (coordinate/reaction names)."""
    out = []
    if isinstance(node, (ast.Tuple, ast.List)):
        for elt in node.elts:
            if isinstance(elt, ast.Call) and getattr(elt.func, "id", "") == func and elt.args:
                arg = elt.args[0]
                if isinstance(arg, ast.Constant):
                    out.append(str(arg.value))
                elif isinstance(arg, ast.Name):
                    out.append(arg.id)
                else:
                    out.append(ast.unparse(arg))
    return tuple(out)


def _read(path: Path) -> list[Declaration]:
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found = []
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        attrs = {}
        for stmt in node.body:
            if isinstance(stmt, ast.Assign):
                targets = stmt.targets[0]
                names = [t.id for t in (targets.elts if isinstance(targets, ast.Tuple)
                                        else [targets]) if isinstance(t, ast.Name)]
                values = (stmt.value.elts if isinstance(stmt.value, ast.Tuple)
                          and isinstance(targets, ast.Tuple) else [stmt.value])
                for n, v in zip(names, values):
                    attrs[n] = v
            elif isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name) \
                    and stmt.value is not None:
                attrs[stmt.target.id] = stmt.value
        name = _literal(attrs["name"]) if "name" in attrs else None
        if not isinstance(name, str) or not name:
            continue
        found.append(Declaration(
            module=path.stem, cls=node.name, name=name,
            title=str(_literal(attrs.get("title", ast.Constant(""))) or ""),
            source=str(_literal(attrs.get("source", ast.Constant(""))) or ""),
            summary=str(_literal(attrs.get("summary", ast.Constant(""))) or ""),
            coordinates=_call_names(attrs.get("coordinates"), "Coordinate"),
            reactions=_call_names(attrs.get("reactions"), "Reaction"),
            parametric=str(_literal(attrs.get("parametric", ast.Constant(""))) or "")))
    return found


def declarations() -> list[Declaration]:
    """Every problem's declaration, ordered by source file, then module, then class order."""
    out = []
    for path in sorted(_HERE.glob("*.py")):
        if path.name.startswith("_"):
            continue
        out.extend(_read(path))
    order = {d.module: i for i, d in enumerate(out)}
    return sorted(out, key=lambda d: (d.source_file, order[d.module]))


#: problem name -> the module file found to declare it (read again, if changed, on each use)
_FOUND: dict = {}
#: module file -> ((modification time, size), its declarations)
_PARSED: dict = {}


def _read_once(path: Path) -> list[Declaration]:
    """:func:`_read`, parsed again only when the file changed."""
    st = path.stat()
    stamp = (st.st_mtime_ns, st.st_size)
    hit = _PARSED.get(path)
    if hit is None or hit[0] != stamp:
        hit = _PARSED[path] = (stamp, _read(path))
    return hit[1]


def module_of(name: str) -> Declaration:
    """The declaration of problem ``name``; ``KeyError`` names the close matches.

    Only the module that declares ``name = "<name>"`` is parsed when one does; a second
    look-up of the same name reads that module's declarations again (parsed again only if
    the file changed) instead of searching the catalogue."""
    import re
    known = _FOUND.get(name)
    if known is not None:
        try:
            for d in _read_once(known):
                if d.name == name:
                    return d
        except OSError:
            pass
    pattern = re.compile(r'^\s+name\s*=\s*["\']' + re.escape(name) + r'["\']', re.M)
    for path in sorted(_HERE.glob("*.py")):
        if not path.name.startswith("_") and pattern.search(path.read_text(encoding="utf-8")):
            for d in _read_once(path):
                if d.name == name:
                    _FOUND[name] = path
                    return d
    decls = {d.name: d for d in declarations()}
    if name not in decls:
        import difflib
        close = difflib.get_close_matches(name, list(decls), n=3)
        hint = f" Did you mean {', '.join(repr(c) for c in close)}?" if close else ""
        raise KeyError(f"no problem named {name!r}.{hint} known problems: "
                       f"{', '.join(decls)}.")
    return decls[name]


def _class(decl: Declaration):
    module = importlib.import_module(f"dualmech.problems.{decl.module}")
    return getattr(module, decl.cls)


def all_problems() -> list:
    """One instance of every problem (parametric ones at their default size), catalogue order."""
    return [_class(d)() for d in declarations()]


def registered_specs() -> list:
    """A spec (``catalogue:problem``) for every problem of every catalogue that installed
    course packages register, catalogue by catalogue; :class:`SpecError` names a catalogue
    that does not load.

    >>> registered_specs() == [s for c in sorted(registered()) for s in catalogue_specs(c)]
    True
    """
    return [spec for name in sorted(registered()) for spec in catalogue_specs(name)]


def _class_named(name: str):
    """The class of catalogue problem ``name`` (``KeyError`` with close matches)."""
    return _class(module_of(name))


def resolve(spec: str):
    """The problem class ``spec`` names: a catalogue name, ``path.py[:Class]``,
    ``module:Class``, or a registered catalogue's problem (``catalogue:problem`` or its name).

    >>> resolve("toy_car").__name__
    'ToyCar'
    """
    return _resolve(spec, _class_named)


def load(spec: str, **options):
    """An instance of the problem ``spec`` names (see :func:`resolve`); ``options`` go to a
    parametric problem, e.g. ``n=10``.  Raises :class:`SpecError` (a ``KeyError``) when
    ``spec`` names nothing, ``ValueError`` for options a fixed-size problem does not take.

    >>> load("simple_pendulum").name
    'simple_pendulum'
    >>> load("n_link_pendulum", n=2).name
    'n_link_pendulum'
    """
    cls = resolve(spec)
    if options and not getattr(cls, "parametric", ""):
        raise ValueError(f"`{getattr(cls, 'name', '') or cls.__name__}` has a fixed size; it "
                         f"takes no {', '.join(options)}.")
    try:
        return cls(**options)
    except TypeError as exc:
        if exc.__traceback__.tb_next is not None:   # raised inside __init__: its own error
            raise
        raise ValueError(f"{cls.__name__}: {exc}") from None


def get(spec: str, **options):
    """The problem ``spec`` names (the same as :func:`load`): a catalogue name such as
    ``"toy_car"``, a file ``path.py[:Class]``, ``module:Class``, or a registered catalogue's
    problem; ``options`` go to a parametric problem, e.g. ``n=10``."""
    return load(spec, **options)


def is_name(spec: str) -> bool:
    """Whether ``spec`` is a plain problem name (``toy_car``), which :func:`get` resolves in
    the catalogues only -- never by importing a file or a module that the text names.

    >>> is_name("toy_car"), is_name("/tmp/x.py"), is_name("os:path")
    (True, False, False)
    """
    import re
    return isinstance(spec, str) and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,99}", spec) \
        is not None


def named(name: str, **options):
    """The catalogue (or registered catalogue) problem called ``name``; for names from
    untrusted text (a CSV, a web form): a path or ``module:Class`` is refused, never
    imported.  Raises :class:`SpecError` (a ``KeyError``)."""
    if not is_name(name):
        raise SpecError(f"{str(name)[:80]!r} is not a problem name: here a problem is named "
                        "by its catalogue name (dualmech list), not by a file or module.")
    return load(name, **options)
