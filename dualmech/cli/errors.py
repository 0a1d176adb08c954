"""The exit statuses of ``dualmech``, its usage error, and the one handler that turns an
exception into a message and a status.

Exit status (every command)::

    0    OK                    done; every checked pair of derivations agrees (grade: the
                               answer is right; mutate: every mutant is caught)
    1    DISAGREE              the models disagree -- a wrong model (mutate: a mutant survived
                               or the derivations already disagree; grade: the answer is wrong)
    2    USAGE_OR_MODEL_ERROR  a usage error (an unknown problem, a bad option, an unwritable
                               directory); a problem file with an error, shown at its file and
                               line; a declaration error (ProblemError, ModelError) or any
                               model that cannot be built; an internal error, which says so
    130  INTERRUPTED           stopped by Ctrl-C

Several problems at once: the worst status of them (2 before 1 before 0).

Every message is wrapped to the terminal's width (100 columns when stderr is no terminal),
its continuation lines indented under it; a quoted line of the user's file (marked
``# <- error``) stays whole, as it is in the file (:func:`fit`, :func:`say`).

No Python traceback reaches the terminal.  An error raised in the user's own code -- a
problem file, or a module of a course package -- is shown at the innermost line of it that
the error passed through, with the source line and what to fix
(:func:`dualmech.problems.user_error`).  An error inside dualmech that no user line explains
is called an internal error, with how to report it (``DUALMECH_TRACEBACK=1`` prints the
traceback).

Example
-------
>>> @guarded
... def handler(args):
...     raise UsageError("name a problem.")
>>> import argparse
>>> handler(argparse.Namespace(command="check"))
2
"""
from __future__ import annotations

import contextlib
import functools
import os
import shutil
import sys
import textwrap
import traceback
from dataclasses import dataclass

__all__ = ["OK", "DISAGREE", "USAGE_OR_MODEL_ERROR", "INTERRUPTED", "EXIT_STATUS",
           "UsageError", "Failure", "about", "describe", "report", "guarded", "worst",
           "columns", "fit", "say"]

OK = 0
DISAGREE = 1
USAGE_OR_MODEL_ERROR = 2
INTERRUPTED = 130

#: the exit statuses, as the end of every command's ``--help`` says them
EXIT_STATUS = ("Exit status: 0 done, every checked pair of derivations agrees; 1 the models "
               "disagree (a wrong model); 2 a usage error, an error in a problem file (shown "
               "at its file and line), a declaration error or a model that cannot be built, "
               "or an internal error (it says so); 130 interrupted.  Several problems: the "
               "worst of their statuses.")

#: set (to anything but 0) to see the traceback of an internal error
TRACEBACK_VARIABLE = "DUALMECH_TRACEBACK"


class UsageError(Exception):
    """A command-line mistake; the message says what to do instead."""


@dataclass(frozen=True)
class Failure:
    """What a command says about an exception: its exit status, its message (one line or a
    few) and its kind -- ``"usage"`` (a command-line mistake, an unknown problem, a file that
    cannot be written), ``"user"`` (raised in the user's own code, shown at its line),
    ``"model"`` (a declaration or model error dualmech found), ``"refused"`` (dualmech
    refusing an input, with the reason), ``"internal"`` (dualmech's own bug) or
    ``"interrupted"``."""

    status: int
    message: str
    kind: str = "usage"

    @property
    def internal(self) -> bool:
        return self.kind == "internal"


@contextlib.contextmanager
def about(problem):
    """Exceptions raised inside are about ``problem``: :func:`describe` looks for the user's
    line in the files that define it (a catalogue module, an installed course package)."""
    try:
        yield
    except Exception as exc:
        if getattr(exc, "_dualmech_problem", None) is None:
            with contextlib.suppress(AttributeError, TypeError):
                exc._dualmech_problem = problem
        raise


def worst(statuses) -> int:
    """The status of several results: interrupted, then 2, then 1, then 0.

    >>> worst([0, 1, 2, 1]), worst([]), worst([0, 130, 2])
    (2, 0, 130)
    """
    order = (OK, DISAGREE, USAGE_OR_MODEL_ERROR, INTERRUPTED)
    return max(statuses, key=lambda s: order.index(s) if s in order else 2, default=OK)


def describe(exc: BaseException, problem=None) -> Failure:
    """The status and message for ``exc``, raised while working on ``problem`` (if known)."""
    if isinstance(exc, KeyboardInterrupt):
        return Failure(INTERRUPTED, "interrupted", "interrupted")
    if isinstance(exc, UsageError):
        return Failure(USAGE_OR_MODEL_ERROR, str(exc))
    from dualmech.problems import SpecError, problem_files, user_error
    if isinstance(exc, SpecError):
        return Failure(USAGE_OR_MODEL_ERROR, str(exc))
    problem = problem if problem is not None else getattr(exc, "_dualmech_problem", None)
    files = problem_files(problem) if problem is not None else ()
    located = user_error(exc, files)
    if located is not None:
        return Failure(USAGE_OR_MODEL_ERROR, located, "user")
    if isinstance(exc, OSError):   # an unwritable --out, an unreadable input: one line
        where = f"{exc.filename}: " if getattr(exc, "filename", None) else ""
        return Failure(USAGE_OR_MODEL_ERROR, f"{where}{exc.strerror or exc}")
    if _is_model_error(exc):
        at = None if _in_study(exc) else _declared_at(problem, exc)
        return Failure(USAGE_OR_MODEL_ERROR, at or _in_problem(problem, files) + str(exc),
                       "model")
    if _deliberate(exc):   # dualmech refusing an input, with a message that says why
        return Failure(USAGE_OR_MODEL_ERROR, f"{type(exc).__name__}: {exc}", "refused")
    jumps = _jumps(problem)
    if jumps is not None:   # e.g. symengine's solver, given sign() in a hand-written model
        return Failure(USAGE_OR_MODEL_ERROR, _in_problem(problem, files) + jumps, "model")
    return Failure(USAGE_OR_MODEL_ERROR, _internal(exc, problem), "internal")


#: width of a message that goes to a file or a pipe, not a terminal
PIPE_COLUMNS = 100
#: what marks a quoted line of the user's file (:func:`dualmech.problems.user_error`)
_QUOTED = "# <- error"


def columns(stream=None) -> int:
    """The width of the terminal ``stream`` (default stderr) writes to, at least 40; 100
    when it is no terminal."""
    stream = sys.stderr if stream is None else stream
    try:
        tty = stream.isatty()
    except (AttributeError, ValueError):   # a closed or a fake stream
        tty = False
    return max(40, shutil.get_terminal_size((PIPE_COLUMNS, 24)).columns) if tty \
        else PIPE_COLUMNS


def fit(text: str, width: int | None = None) -> str:
    r"""Every line of ``text`` wrapped to ``width`` (default :func:`columns`), continuation
    lines indented four spaces under it; words (and paths) are not broken, and a quoted line
    of the user's file stays whole.

    >>> print(fit("dualmech check: error: reaction `N` is declared but no model uses it "
    ...           "(a typo in a name?)\n    ne.reaction('NN', ...)  # <- error", 40))
    dualmech check: error: reaction `N` is
        declared but no model uses it (a
        typo in a name?)
        ne.reaction('NN', ...)  # <- error
    """
    width = width or columns()
    out = []
    for line in text.split("\n"):
        lead = line[:len(line) - len(line.lstrip(" "))]
        if len(line) <= width or line.rstrip().endswith(_QUOTED):
            out.append(line)
            continue
        out.append(textwrap.fill(line.strip(" "), width, initial_indent=lead,
                                 subsequent_indent=lead + "    ", break_long_words=False,
                                 break_on_hyphens=False))
    return "\n".join(out)


def say(command: str, message: str, what: str = "error", stream=None) -> None:
    """``dualmech COMMAND: WHAT: MESSAGE`` on ``stream`` (default stderr), wrapped to its
    width (:func:`fit`); ``what=""`` leaves the word out."""
    stream = sys.stderr if stream is None else stream
    head = f"dualmech {command}: " + (f"{what}: " if what else "")
    print(fit(head + message, columns(stream)), file=stream, flush=True)


def report(command: str, exc: BaseException, problem=None) -> int:
    """Print what :func:`describe` says about ``exc`` on stderr; return the exit status."""
    failure = describe(exc, problem)
    if failure.status == INTERRUPTED:
        print(f"dualmech {command}: interrupted", file=sys.stderr)
        return INTERRUPTED
    say(command, failure.message)
    if failure.internal and os.environ.get(TRACEBACK_VARIABLE, "0") not in ("", "0"):
        traceback.print_exception(exc, file=sys.stderr)
    return failure.status


def guarded(handler):
    """``handler(args) -> status`` that never raises: an exception becomes a message on
    stderr (:func:`report`) and its exit status."""
    @functools.wraps(handler)
    def run(args) -> int:
        command = getattr(args, "command", None) or handler.__name__.strip("_")
        try:
            return handler(args)
        except BrokenPipeError:   # nobody reads the output any more: the work is done
            return OK
        except (Exception, KeyboardInterrupt) as exc:  # noqa: BLE001 - no traceback for users
            return report(command, exc)
    return run


def _is_model_error(exc: BaseException) -> bool:
    """A :class:`~dualmech.model.equations.ModelError` (or ProblemError), told without
    importing sympy: when the module is not loaded, no such error can exist."""
    module = sys.modules.get("dualmech.model.equations")
    return module is not None and isinstance(exc, module.ModelError)


#: engine modules whose refusals are about a study of a sound problem (a state that is no
#: steady motion, a driven model), not about a line of the problem's file
_STUDIES = (os.sep + "numeric" + os.sep, os.sep + "model" + os.sep + "stability.py",
            os.sep + "model" + os.sep + "steady.py")


def _in_study(exc: BaseException) -> bool:
    """Whether ``exc`` was raised by a study (stability, steady motion, numerics) rather than
    while the problem's declarations or models were built."""
    return any(any(s in os.path.realpath(f.filename) for s in _STUDIES)
               for f in traceback.extract_tb(exc.__traceback__))


def _deliberate(exc: BaseException) -> bool:
    """Raised by a ``raise`` statement of dualmech itself (a refusal with a message), not by
    a failing operation inside it or inside a library it calls."""
    frames = traceback.extract_tb(exc.__traceback__)
    if not frames or not str(exc):
        return False
    last = frames[-1]
    engine = os.path.dirname(os.path.dirname(os.path.realpath(__file__))) + os.sep
    return os.path.realpath(last.filename).startswith(engine) and \
        (last.line or "").lstrip().startswith("raise ")


#: what a declaration error names -> the class attribute that declares it
_DECLARED = (("reaction `", "reactions"), ("parameter `", "parameters"),
             ("coordinate `", "coordinates"), ("symbol `", "parameters"),
             ("reference model", "reference"), ("`name`", "name"), ("`title`", "title"),
             ("`source`", "source"))


def _declared_at(problem, exc: BaseException) -> str | None:
    """A model or declaration error of ``problem`` that no line of the user's code raised
    (:meth:`Problem.validate` finds it) at the line of the class attribute it is about --
    ``reactions = ...`` for a reaction -- else of the class statement; None when the source
    cannot be read."""
    import ast
    import inspect
    import textwrap
    if problem is None:
        return None
    cls = problem if inspect.isclass(problem) else type(problem)
    try:
        path = inspect.getsourcefile(cls)
        lines, first = inspect.getsourcelines(cls)
        tree = ast.parse(textwrap.dedent("".join(lines)))
    except (OSError, TypeError, SyntaxError):
        return None
    message = str(exc)
    wanted = next((attr for key, attr in _DECLARED if key in message), None)
    line = first
    for node in tree.body[0].body if tree.body else ():
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, ast.AnnAssign) else []
        if wanted in {n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)}:
            line = first + node.lineno - 1
            break
    head, _, rest = message.partition("\n")
    return (f"{path}, line {line}: {type(exc).__name__}: {head}\n"
            f"    {_quoted(lines[line - first])}" + (f"\n{rest}" if rest else ""))


def _quoted(source_line: str) -> str:
    """A line of the user's file as a message quotes it: stripped, marked ``# <- error``."""
    text = source_line.strip()
    return text if text.endswith(_QUOTED) else f"{text}  {_QUOTED}"


def _jumps(problem) -> str | None:
    """Why ``problem``'s models cannot be used, when one of them (an EquationSet written by
    hand) applies a function that jumps -- ``sign``, ``Piecewise``, ... (the model builders
    refuse those where they are written) -- else None."""
    if problem is None or not hasattr(problem, "models"):
        return None
    try:
        from dualmech.model._expr import refuse_jumps
        for name, eqs in problem.models().items():
            rows = eqs.equations
            refuse_jumps(getattr(rows, "se", rows), f"model `{name}`")
    except Exception as exc:  # noqa: BLE001 - a ModelError is the answer; anything else is not
        return str(exc) if _is_model_error(exc) else None
    return None


def _in_problem(problem, files) -> str:
    if problem is None:
        return ""
    name = getattr(problem, "name", "") or type(problem).__name__
    where = f" ({', '.join(sorted(files))})" if files else ""
    return f"problem `{name}`{where}: "


def _internal(exc: BaseException, problem) -> str:
    what = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
    during = f" while working on `{getattr(problem, 'name', '')}`" if problem is not None else ""
    return (f"internal error{during}: {what}\n  This is a bug in dualmech, not in your problem. "
            "Please report it to the dualmech maintainers with the command you ran, the "
            f"output of `dualmech --version`, and the traceback ({TRACEBACK_VARIABLE}=1 "
            "dualmech ... prints it).")
