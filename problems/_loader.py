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

import functools
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
           "problem_classes", "catalogue_specs", "problem_files", "user_line", "user_error", "GROUP"]

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
    :class:`~dualmech.model.problem.Problem` subclasses defined in it (not imported into it).

    A ``PROBLEMS`` entry that is not a Problem subclass is refused (:class:`SpecError`, at
    the line of ``PROBLEMS``), and so is a module that offers no problem: the message names
    what it has instead -- a class that does not derive from Problem, problem classes it
    imports but does not list."""
    listed = getattr(module, "PROBLEMS", None)
    if listed is not None:
        entries = list(listed) if isinstance(listed, (list, tuple)) else [listed]
        for i, c in enumerate(entries):
            if not _is_problem_class(c):
                what = f"{c!r:.60} (a {type(c).__name__})" if not inspect.isclass(c) else \
                    f"the class {c.__name__}, which does not derive from Problem"
                raise SpecError(f"{_at(module, 'PROBLEMS')}`PROBLEMS[{i}]` is {what}; list the "
                                "problem classes themselves, e.g. PROBLEMS = (Pendulum, Cart).")
        found = entries
    else:
        found = [obj for obj in vars(module).values()
                 if _is_problem_class(obj) and obj.__module__ == module.__name__]
    if not found:
        raise SpecError(_none_offered(module))
    return found


def _lines(module) -> dict:
    """``{name: line}`` of the top-level classes, assignments and imports of ``module``'s
    source (empty when it has none to read)."""
    import ast
    try:
        tree = ast.parse(inspect.getsource(module))
    except (OSError, TypeError, SyntaxError):
        return {}
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out.setdefault(node.name, node.lineno)
        elif isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    out.setdefault(target.id, node.lineno)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                out.setdefault((alias.asname or alias.name).split(".")[0], node.lineno)
    return out


def _at(module, name: str) -> str:
    """``"path, line N: "`` where ``module`` defines ``name`` (or ``"path: "``)."""
    path = getattr(module, "__file__", None) or module.__name__
    line = _lines(module).get(name)
    return f"{path}, line {line}: " if line else f"{path}: "


def _none_offered(module) -> str:
    """Why ``module`` offers no problem, at the line to change."""
    mine = [o for o in vars(module).values()
            if inspect.isclass(o) and o.__module__ == module.__name__]
    imported = [n for n, o in vars(module).items()
                if _is_problem_class(o) and o.__module__ != module.__name__]
    if mine:
        c = mine[0]
        return (f"{_at(module, c.__name__)}class {c.__name__} does not derive from Problem, and "
                f"the file defines no class that does; write `class {c.__name__}(Problem):` "
                "(with `from dualmech import Problem`).")
    if imported:
        listed = ", ".join(imported)
        return (f"{_at(module, imported[0])}the file imports the problem {listed} but defines "
                f"none and has no PROBLEMS list; say what it offers: PROBLEMS = ({listed},).")
    path = getattr(module, "__file__", None) or module.__name__
    return (f"{path} defines no Problem subclass (a class deriving from dualmech's Problem, "
            "`from dualmech import Problem`); write one, or name the file that does.")


def _pick(classes: list, wanted: str | None, where: str):
    """The class of ``classes`` called ``wanted`` (class name or problem name), or the only one."""
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
    located = user_error(exc, {str(path)})
    if located is None:
        return f"importing {path} failed: {type(exc).__name__}: {exc}"
    first = located.split(",", 1)[0]
    return located if first == str(path) else f"{located}\n  (while importing {path})"


# -- the user's own file and line ------------------------------------------------------
#: files :func:`_import_file` imported: users' own problem files
_USER_FILES: set = set()
_CATALOGUE = str(Path(__file__).resolve().parent)


@functools.lru_cache(maxsize=1)
def _library_roots() -> tuple:
    """Folders of Python itself and of installed packages: nobody's own problem file."""
    import sysconfig
    roots = {sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix}
    roots |= {sysconfig.get_paths().get(k, "") for k in ("stdlib", "purelib", "platlib")}
    return tuple(os.path.realpath(r) for r in roots if r)


@functools.lru_cache(maxsize=1)
def _engine_root() -> str:
    import dualmech
    return str(Path(dualmech.__file__).resolve().parent)


def problem_files(problem) -> frozenset:
    """The files that define ``problem`` (an instance or a class) and the classes it derives
    from, dualmech's own modules excepted: where a mistake in it is the user's."""
    cls = problem if inspect.isclass(problem) else type(problem)
    engine = _engine_root() + os.sep
    out = set()
    for c in cls.__mro__:
        try:
            path = os.path.realpath(inspect.getsourcefile(c) or "")
        except TypeError:   # a built-in class
            continue
        if path and (path.startswith(_CATALOGUE + os.sep) or not path.startswith(engine)):
            out.add(path)
    return frozenset(out)


def _is_users(filename: str, files: frozenset) -> bool:
    """Whether ``filename`` is one of ``files``, a file the loader imported, a catalogue
    module, or any file outside dualmech and outside Python's and the packages' folders."""
    if not filename or filename.startswith("<"):
        return False
    path = os.path.realpath(filename)
    if path in files or path in _USER_FILES:
        return True
    if path.startswith(_CATALOGUE + os.sep):   # a catalogue module, not the loader itself
        return not os.path.basename(path).startswith("_")
    if path.startswith(_engine_root() + os.sep):
        return False
    return not any(path.startswith(root + os.sep) for root in _library_roots())


def _chain(exc: BaseException):
    """``exc``, then the exceptions it was raised from or while handling."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        seen.add(id(exc))
        yield exc
        exc = exc.__cause__ or (None if exc.__suppress_context__ else exc.__context__)


def user_line(exc: BaseException, files=()):
    """``(path, line number, frame or None)`` of the innermost line of the user's own code
    that ``exc`` (or an exception it was raised from) passed through; None when none did.
    ``files`` are the problem's own files (:func:`problem_files`)."""
    files = frozenset(os.path.realpath(f) for f in files)
    for e in _chain(exc):
        if isinstance(e, SyntaxError) and e.filename and _is_users(e.filename, files) \
                and e.lineno:
            return e.filename, e.lineno, None
        found = None
        for frame, lineno in traceback.walk_tb(e.__traceback__):
            if _is_users(frame.f_code.co_filename, files):
                found = (frame.f_code.co_filename, lineno, frame)
        if found is not None:
            return found
    return None


#: what marks the quoted line of the user's file in :func:`user_error`
_MARK = "# <- error"


def user_error(exc: BaseException, files=()) -> str | None:
    """``exc`` as the user's error at the innermost line of their own file (see
    :func:`user_line`): the file and line, the error, the source line, the function it is in
    and what to fix; None when the error did not pass through the user's code.

    >>> try:
    ...     exec(compile("x = 1\\ny = 1 / (x - 1)", "/home/teacher/my_problem.py", "exec"), {})
    ... except ZeroDivisionError as exc:
    ...     print(user_error(exc).splitlines()[0])
    /home/teacher/my_problem.py, line 2: ZeroDivisionError: division by zero
    """
    where = user_line(exc, files)
    if where is None:
        return None
    path, lineno, frame = where
    import linecache
    if isinstance(exc, SyntaxError) and frame is None:
        source = (exc.text or linecache.getline(path, lineno)).rstrip("\n")
        message = exc.msg
    else:
        source = linecache.getline(path, lineno, frame.f_globals if frame else None)
        source = source.rstrip("\n")
        message = str(exc)
    lines = [f"{path}, line {lineno}: {type(exc).__name__}: {message}"]
    if source.strip():
        indent = len(source) - len(source.lstrip())
        marked = source.strip()   # marked: the command line keeps it whole when it wraps
        lines.append("    " + (marked if marked.endswith(_MARK) else f"{marked}  {_MARK}"))
        offset = getattr(exc, "offset", None) if frame is None else None
        if offset and offset - 1 >= indent:
            lines.append("    " + " " * (offset - 1 - indent) + "^")
    if frame is not None and frame.f_code.co_name != "<module>":
        name = getattr(frame.f_code, "co_qualname", frame.f_code.co_name)
        function = frame.f_code.co_flags & inspect.CO_OPTIMIZED   # else a class body
        lines.append(f"  in {name}()" if function else f"  in class {name}")
    fix = _what_to_fix(exc, frame)
    if fix:
        lines.append(f"  to fix: {fix}")
    return "\n".join(lines)


def _close(word: str, candidates) -> str:
    import difflib
    close = difflib.get_close_matches(word, sorted({c for c in candidates
                                                    if not c.startswith("_")}), n=3)
    return f" Did you mean {', '.join(f'`{c}`' for c in close)}?" if close else ""


def _what_to_fix(exc: BaseException, frame) -> str:
    """One sentence on what to change at the user's line, by the kind of error."""
    if any(c.__name__ in ("ModelError", "SpecError") for c in type(exc).__mro__):
        return ""   # dualmech's own messages say what to fix
    if isinstance(exc, SyntaxError):
        return ("Python cannot read this line: fix the syntax where the caret points (a "
                "missing bracket, comma or colon is often on the line before).")
    if isinstance(exc, NameError):
        name = getattr(exc, "name", None) or ""
        known = set(frame.f_globals) | set(frame.f_locals) if frame is not None else set()
        return (f"`{name}` is not defined where this line runs: a typo, a name defined later "
                f"or inside another method, or a missing import (a problem file needs "
                f"`from dualmech import ...` and `import sympy as sp`).{_close(name, known)}")
    if isinstance(exc, AttributeError):
        name, obj = getattr(exc, "name", None), getattr(exc, "obj", None)
        hint = _close(name, dir(obj)) if name and obj is not None else ""
        return ("this object has no such attribute: check the spelling and what the object "
                f"is (help() on it lists what it has).{hint}")
    if isinstance(exc, ZeroDivisionError):
        return ("a division by zero on this line: a divisor that is zero for the values "
                "given (a parameter's default, or a factor that vanishes).")
    if isinstance(exc, TypeError):
        return ("a value of the wrong kind on this line: check the call's arguments -- how "
                "many, in which order, and that each is what the function takes (a sympy "
                "symbol, an expression, a vector of a frame, a number).")
    if isinstance(exc, ImportError):
        return ("a module or name that cannot be imported: check its spelling; a problem "
                "file needs only `from dualmech import (...)` and `import sympy as sp`.")
    if isinstance(exc, (IndexError, KeyError)):
        return "an index or key that does not exist on this line: check its value."
    return "the error above is raised by this line of your file."


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
    _USER_FILES.add(os.path.realpath(path))
    folder = str(path.parent)
    sys.path.insert(0, folder)
    try:
        spec.loader.exec_module(module)
    except Exception as exc:  # noqa: BLE001 - the user's own error, shown at its line
        sys.modules.pop(modname, None)
        raise SpecError(_user_error(exc, path)) from None
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


def catalogue_specs(name: str) -> list:
    """``["name:problem", ...]``: a spec for each problem of the registered catalogue ``name``
    (:class:`SpecError` when no installed package registers it or it does not load)."""
    eps = registered()
    if name not in eps:
        raise SpecError(f"no course package registers a catalogue {name!r} (entry-point group "
                        f"{GROUP}); installed catalogues: {', '.join(sorted(eps)) or 'none'}.")
    return [f"{name}:{getattr(c, 'name', '') or c.__name__}"
            for c in catalogue_classes(eps[name])]


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
    if spec in registered():
        names = catalogue_specs(spec)
        raise SpecError(f"{spec!r} is a course package's catalogue of {len(names)} problem(s) "
                        f"({', '.join(names)}); name one of them here (check, report, mutate, "
                        "chart and serve --problems take the whole catalogue).")
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
