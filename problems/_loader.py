"""Find a problem class from a *spec*: a catalogue name, a file, ``module:Class`` or an entry point.

Specs, tried in this order:

* ``path/to/file.py`` or ``path/to/file.py:Class`` -- a file anywhere (``Class`` may also be the
  problem's ``name``); the file is imported as a module of its own;
* ``package.module:Class`` -- an importable module (the current directory is tried too, as
  ``python -m`` would);
* ``catalogue:problem`` -- a problem of a catalogue that a course package registers under the
  entry-point group ``dualmech.problems`` (the entry point names a module whose ``PROBLEMS``, or
  whose :class:`~dualmech.model.problem.Problem` subclasses, form the catalogue);
* ``problem`` -- a problem of dualmech's catalogue, then of every registered catalogue.

Every failure raises :class:`SpecError` (a ``KeyError``) with a message that says what to fix.

Example
-------
>>> resolve("simple_pendulum").__name__
'SimplePendulum'
>>> try:
...     resolve("simple_pendulm")
... except SpecError as exc:
...     print(str(exc)[:65])
no problem named 'simple_pendulm'. Did you mean 'simple_pendulum'
"""
from __future__ import annotations

import hashlib
import importlib
import importlib.util
import inspect
import os
import re
import sys
import traceback
from pathlib import Path

__all__ = ["SpecError", "resolve", "canonical", "registered", "catalogue_classes",
           "problem_classes", "GROUP"]

#: the entry-point group through which course packages register catalogues
GROUP = "dualmech.problems"

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_MODULE = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*$")
#: longest spec accepted (a path and a class name)
MAX_SPEC = 4096


class SpecError(KeyError):
    """A problem spec that names nothing loadable; the message says what to fix."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def _problem_base():
    from dualmech.model.problem import Problem
    return Problem


def _is_problem_class(obj) -> bool:
    base = _problem_base()
    return inspect.isclass(obj) and issubclass(obj, base) and obj is not base


def problem_classes(module) -> list:
    """The problem classes a module offers: its ``PROBLEMS`` if it has one, else the
    :class:`~dualmech.model.problem.Problem` subclasses defined in it (not imported into it)."""
    listed = getattr(module, "PROBLEMS", None)
    if listed is not None:
        return [c for c in listed if _is_problem_class(c)]
    return [obj for obj in vars(module).values()
            if _is_problem_class(obj) and obj.__module__ == module.__name__]


def _pick(classes: list, wanted: str | None, where: str):
    """The class of ``classes`` called ``wanted`` (class name or problem name), or the only one."""
    if not classes:
        raise SpecError(f"{where} defines no Problem subclass (a class deriving from "
                        "dualmech.model.problem.Problem); write one, or name the file that does.")
    if wanted is None:
        if len(classes) == 1:
            return classes[0]
        names = ", ".join(c.__name__ for c in classes)
        raise SpecError(f"{where} defines several problems ({names}); name one, e.g. "
                        f"{where}:{classes[0].__name__}.")
    for c in classes:
        if wanted in (c.__name__, getattr(c, "name", None)):
            return c
    import difflib
    names = [c.__name__ for c in classes] + [c.name for c in classes if getattr(c, "name", "")]
    close = difflib.get_close_matches(wanted, names, n=3)
    hint = f" Did you mean {', '.join(repr(x) for x in close)}?" if close else ""
    raise SpecError(f"{where} has no problem {wanted!r}.{hint} It has "
                    f"{', '.join(c.__name__ for c in classes)}.")


def _user_error(exc: BaseException, path: Path) -> str:
    """``exc``, raised while importing the user's ``path``, as the user's error at its line."""
    if isinstance(exc, SyntaxError) and exc.filename and Path(exc.filename).resolve() == path:
        text = (exc.text or "").strip()
        return (f"{path}, line {exc.lineno}: {type(exc).__name__}: {exc.msg}"
                + (f"\n    {text}" if text else ""))
    frames = [f for f in traceback.extract_tb(exc.__traceback__)
              if Path(f.filename).resolve() == path]
    where = f"{path}, line {frames[-1].lineno}" if frames else str(path)
    line = f"\n    {frames[-1].line}" if frames and frames[-1].line else ""
    return f"{where}: {type(exc).__name__}: {exc}{line}"


def _import_file(path: Path):
    """Import the file ``path`` as a module of its own (its folder on ``sys.path`` meanwhile,
    so that it may import its neighbours)."""
    digest = hashlib.sha1(str(path).encode()).hexdigest()[:10]
    modname = f"dualmech_user_{re.sub(r'[^0-9A-Za-z_]', '_', path.stem)}_{digest}"
    if modname in sys.modules:
        return sys.modules[modname]
    spec = importlib.util.spec_from_file_location(modname, path)
    if spec is None or spec.loader is None:
        raise SpecError(f"{path} is not a Python file dualmech can import.")
    module = importlib.util.module_from_spec(spec)
    sys.modules[modname] = module
    folder = str(path.parent)
    sys.path.insert(0, folder)
    try:
        spec.loader.exec_module(module)
    except Exception as exc:  # noqa: BLE001 - the user's own error, shown at its line
        sys.modules.pop(modname, None)
        raise SpecError(f"importing {path} failed: {_user_error(exc, path)}") from None
    finally:
        try:
            sys.path.remove(folder)
        except ValueError:
            pass
    return module


def _split_file(spec: str) -> tuple[str, str | None] | None:
    """``(path, Class or None)`` when ``spec`` names a file, else None."""
    head, sep, tail = spec.rpartition(":")
    if sep and head.endswith(".py") and (_NAME.match(tail) or tail == ""):
        return head, (tail or None)
    if spec.endswith(".py") or os.sep in spec or (os.altsep and os.altsep in spec):
        return spec, None
    return None


def _from_file(path_text: str, wanted: str | None):
    path = Path(path_text).expanduser()
    if not path.is_file():
        hint = "" if path.suffix == ".py" else " (a problem file ends in .py)"
        raise SpecError(f"no file {path}{hint}; give a catalogue name (dualmech list), a "
                        "file path.py[:Class] or module:Class.")
    path = path.resolve()
    module = _import_file(path)
    obj = getattr(module, wanted, None) if wanted else None
    if obj is not None and not _is_problem_class(obj):
        raise SpecError(f"{path}:{wanted} is a {type(obj).__name__}, not a Problem subclass "
                        "(a class deriving from dualmech.model.problem.Problem).")
    return obj if obj is not None else _pick(problem_classes(module), wanted, str(path))


def _import_module(name: str):
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as exc:
        top = name.split(".")[0]
        if exc.name != top or os.getcwd() in sys.path:
            raise SpecError(f"cannot import {name}: {exc}") from None
    sys.path.insert(0, os.getcwd())   # as `python -m` would: the current directory
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as exc:
        raise SpecError(f"cannot import module {name!r} ({exc}); put its folder on PYTHONPATH, "
                        "or give the file: path/to/module.py:Class.") from None
    except Exception as exc:  # noqa: BLE001
        raise SpecError(f"importing {name} failed: {type(exc).__name__}: {exc}") from None
    finally:
        try:
            sys.path.remove(os.getcwd())
        except ValueError:
            pass


def registered() -> dict:
    """``{catalogue name: entry point}`` of the catalogues installed packages register."""
    from importlib.metadata import entry_points
    return {ep.name: ep for ep in entry_points(group=GROUP)}


def catalogue_classes(ep) -> list:
    """The problem classes of the registered catalogue ``ep`` (an entry point)."""
    try:
        obj = ep.load()
    except Exception as exc:  # noqa: BLE001 - a broken course package is named, not a crash
        raise SpecError(f"the catalogue {ep.name!r} ({ep.value}, registered in the entry-point "
                        f"group {GROUP}) does not load: {type(exc).__name__}: {exc}") from None
    if inspect.ismodule(obj):
        return problem_classes(obj)
    if _is_problem_class(obj):
        return [obj]
    try:
        return [c for c in obj if _is_problem_class(c)]
    except TypeError:
        raise SpecError(f"the catalogue {ep.name!r} ({ep.value}) is neither a module, a Problem "
                        "subclass nor a list of them.") from None


def _from_module(module: str, wanted: str):
    eps = registered()
    if module in eps and _NAME.match(module):
        return _pick(catalogue_classes(eps[module]), wanted, f"catalogue {module!r}")
    mod = _import_module(module)
    obj = getattr(mod, wanted, None)
    if obj is not None and not _is_problem_class(obj):
        raise SpecError(f"{module}:{wanted} is a {type(obj).__name__}, not a Problem subclass "
                        "(a class deriving from dualmech.model.problem.Problem).")
    return obj if obj is not None else _pick(problem_classes(mod), wanted, module)


def resolve(spec: str, catalogue_class=None):
    """The problem class ``spec`` names (see the module docstring).

    ``catalogue_class(name)`` finds a name in dualmech's own catalogue (``KeyError`` when it
    is not there); the package passes its own."""
    if not isinstance(spec, str):
        raise TypeError(f"a problem spec is text, got {type(spec).__name__}.")
    spec = spec.strip()
    if not spec or len(spec) > MAX_SPEC or "\x00" in spec:
        raise SpecError("give a problem: a catalogue name (dualmech list), a file "
                        "path.py[:Class] or module:Class.")
    as_file = _split_file(spec)
    if as_file is not None:
        return _from_file(*as_file)
    module, sep, wanted = spec.rpartition(":")
    if sep:
        if not (_MODULE.match(module) and _NAME.match(wanted)):
            raise SpecError(f"cannot read the problem spec {spec!r}: expected module:Class "
                            "(e.g. my_course.pendulum:Pendulum) or path.py:Class.")
        return _from_module(module, wanted)
    if catalogue_class is None:
        from dualmech.problems import _class_named as catalogue_class
    try:
        return catalogue_class(spec)
    except KeyError as exc:
        missing = exc
    found = {f"{cname}:{spec}": c for cname, ep in sorted(registered().items())
             for c in catalogue_classes(ep) if spec in (getattr(c, "name", None), c.__name__)}
    if len(found) == 1:
        return next(iter(found.values()))
    if found:
        raise SpecError(f"several registered catalogues have a problem {spec!r}: name one, "
                        f"{' or '.join(found)}.")
    raise SpecError(str(missing.args[0] if missing.args else missing)
                    + " Your own problem: give its file, path.py[:Class], or module:Class.")


def canonical(spec: str) -> str:
    """``spec`` as another process resolves it the same way: a file path made absolute.

    >>> canonical("simple_pendulum")
    'simple_pendulum'
    """
    as_file = _split_file(spec.strip()) if isinstance(spec, str) else None
    if as_file is None:
        return spec
    path, wanted = as_file
    absolute = str(Path(path).expanduser().resolve())
    return absolute + (f":{wanted}" if wanted else "")
