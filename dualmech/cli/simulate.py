"""The ``simulate`` subcommand of ``dualmech``: integrate a problem's equations of motion.

::

    dualmech simulate NAME [--duration T] [--rtol R] [--atol A] [--method M]
                           [--param NAME=VALUE ...] [--input NAME=HISTORY ...]
                           [--samples K] [--n N] [--phases PNG | --single-phase] [--json]

NAME is anything :func:`dualmech.problems.load` takes: a catalogue name, ``path.py[:Class]``
or ``module:Class``.  The reference model is integrated from the problem's initial state
(:func:`~dualmech.numeric.simulation.default_initial_state`) with its default parameter values
(``--param`` overrides them, inside their declared ranges) by
:func:`dualmech.numeric.cvode.integrate`: SUNDIALS CVODE driving the generated C right-hand
side by default (``--method auto``), with no Python per step.  Where that route cannot run (no
C compiler, no SUNDIALS libraries) the command says so in one line on stderr and falls back to
scipy's DOP853 on the generated right-hand side.  The run stops with an error where the motion
reaches the problem's declared singular set (:attr:`Problem.singular
<dualmech.model.problem.Problem.singular>`: CVODE's root finding, scipy's terminal events).

The text (or ``--json``) gives the parameters, the state order (coordinates, then their
rates), the initial and final states, the method that ran and ``cpu_seconds``: the CPU time of
the integration alone (deriving, generating and compiling the code come before the clock
starts).  A run that leaves the scene the problem declares -- a coordinate's ``domain``, a
length's range, a rate's declared direction (a rate range that excludes zero, as a sliding
phase's friction needs) -- is warned about on stderr, and ``left_declared`` in the JSON says
where (:func:`~dualmech.numeric.contacts.left_declared`).  So is a one-sided reaction the
problem declares changing sign on the way (:func:`~dualmech.numeric.contacts.watch`, on the
same route: CVODE with the reactions as event functions in C by default): ``contact`` in the
JSON gives the reaction, the time, the method that located it and its ``cpu_seconds``.

A problem that declares its contact phases (:attr:`Problem.phases
<dualmech.model.problem.Problem>`: what follows when a one-sided reaction lets go) is
simulated across them by default (:func:`phased_summary`,
:func:`~dualmech.numeric.phases.simulate_phases`): where a one-sided reaction would change
sign the run continues with the declared next phase, the state mapped across, each phase on
CVODE with its one-sided reactions and declared bounds as event functions compiled to C
(scipy where that cannot run, said on stderr).  It ends at ``--duration``, or earlier where a
phase leaves its declared domain or a reaction with no next phase lets go (said on stderr,
exit status 1).  The JSON says which phases ran (``phases``: each its problem, coordinates,
start and end time, initial and final state) and when it switched (``switches``); with
``--samples`` the samples cover every phase (``samples``: ``t``, ``phase`` -- the index of
the phase whose coordinates a row is in -- and ``states``).  ``--single-phase`` runs the
first phase alone, as for a problem without phases: a reaction changing sign is then only
warned about (``contact``).  A problem driven by given inputs drives every phase with the
same histories (``--input``, else the declared defaults), time running on across each switch;
a next phase whose problem does not declare them is refused (exit 2).  ``--phases PNG`` runs
the phases too and draws them (:func:`~dualmech.numeric.phase_chart.phase_chart`): it prints
the switches, ``method`` (the integrator that ran) and ``cpu_seconds`` (its integrations
alone), by default at rtol 1e-10 and atol 1e-12 (``--rtol``/``--atol`` override them; the
JSON's ``rtol`` and ``atol`` say which ran).  Exit status (:mod:`dualmech.cli.errors`): 0 done, 1 the integration stopped early
(a singular mass matrix, the declared singular set, too much work), 2 a usage error or a
problem that cannot be built.

Example
-------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="dualmech")
>>> register(parser.add_subparsers(dest="command"))
>>> args = parser.parse_args(["simulate", "nonexistent_problem"])
>>> args.func(args)
2
"""
from __future__ import annotations

import argparse
import json
import sys

from dualmech.cli.errors import DISAGREE, OK, UsageError, about, guarded
from dualmech.cli.options import positive_number, whole_number

__all__ = ["register", "summary", "phased_summary"]

#: the integration stopped early (the same status as a disagreement: the job was not done)
STOPPED = DISAGREE

#: the default ``(rtol, atol)``: of a run, and of ``--phases PNG`` (a chart's switch times)
TOLERANCES = ((1e-8, 1e-10), (1e-10, 1e-12))


def register(subparsers) -> None:
    """Add ``simulate`` to ``subparsers`` (from ``add_subparsers``; nothing heavy is imported
    before the command runs)."""
    p = subparsers.add_parser(
        "simulate", help="integrate a problem's equations of motion (CVODE + generated C)",
        description="Integrate the reference model from the problem's initial state and print "
                    "the final state and the CPU time of the integration alone.  Default "
                    "method: SUNDIALS CVODE (Adams) driving the generated C right-hand side; "
                    "where it cannot run, scipy's DOP853 (said on stderr).")
    p.add_argument("name", metavar="NAME",
                   help="the problem: a catalogue name, path.py[:Class] or module:Class")
    p.add_argument("--duration", metavar="T", type=positive_number, default=10.0,
                   help="simulated seconds (default: %(default)s)")
    p.add_argument("--rtol", metavar="R", type=_rtol, default=None,
                   help=f"relative tolerance (default: {TOLERANCES[0][0]:g}; with --phases "
                        f"{TOLERANCES[1][0]:g})")
    p.add_argument("--atol", metavar="A", type=positive_number, default=None,
                   help=f"absolute tolerance (default: {TOLERANCES[0][1]:g}; with --phases "
                        f"{TOLERANCES[1][1]:g})")
    p.add_argument("--method", metavar="M", default="auto",
                   help="auto (default: CVODE-Adams, else DOP853), CVODE-Adams, CVODE-BDF, "
                        "or scipy's DOP853, RK45, Radau, BDF, LSODA on the generated "
                        "right-hand side")
    p.add_argument("--param", metavar="NAME=VALUE", action="append", default=[],
                   help="a parameter value instead of the problem's default (repeatable)")
    p.add_argument("--input", metavar="NAME=HISTORY", action="append", default=[],
                   help="a given input's history (a problem declaring inputs needs one each): "
                        "an expression of t, e.g. 'F=2*sin(3*t)', or a CSV table of time, "
                        "value rows, e.g. F=push.csv (repeatable)")
    p.add_argument("--phases", metavar="PNG", default=None,
                   help="chain the contact phases the problem declares (Problem.phases): "
                        "print each switch, the method that ran and its CPU time, and write "
                        "a chart of every phase to PNG (JSON: phases, switches, ended, chart, "
                        "method, cpu_seconds, fallback)")
    p.add_argument("--single-phase", action="store_true",
                   help="do not follow the contact phases the problem declares: run its "
                        "first model alone and only warn where a one-sided reaction changes "
                        "sign (the default follows them: JSON phases, switches)")
    p.add_argument("--samples", metavar="K", type=whole_number(2, 100_000), default=None,
                   help="also give the state at K evenly spaced times (2 to 100000; across "
                        "contact phases, shared among them, each row in its phase's "
                        "coordinates)")
    p.add_argument("--n", metavar="N", type=int, default=None,
                   help="size of a parametric problem (one that declares `parametric`), e.g. --n 3")
    p.add_argument("--json", action="store_true",
                   help="print JSON: name, parameters, coordinates, initial_state, "
                        "final_state, t_final, method, cpu_seconds, steps, rhs_evaluations, "
                        "rtol, atol, success, message, fallback, left_declared, contact "
                        "(and samples); across declared contact phases also phases, "
                        "switches, ended, final_coordinates")
    p.set_defaults(func=guarded(_simulate))


def _rtol(text: str) -> float:
    value = positive_number(text)
    if not 1e-14 <= value < 1:
        raise argparse.ArgumentTypeError(f"expected a relative tolerance in [1e-14, 1), got "
                                         f"{text!r}")
    return value


def _load(args):
    from dualmech import problems
    try:
        return problems.load(args.name, **({"n": args.n} if args.n is not None else {}))
    except KeyError as exc:   # SpecError: what to fix, with close matches
        raise UsageError(exc.args[0] if exc.args else str(exc)) from None
    except ValueError as exc:  # options a fixed-size problem does not take
        raise UsageError(str(exc)) from None


def _params(pairs) -> dict:
    out = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        if not sep or not name.strip():
            raise UsageError(f"`--param` takes NAME=VALUE, got {pair!r}.")
        try:
            out[name.strip()] = float(value)
        except ValueError:
            raise UsageError(f"`--param` {name.strip()}: {value.strip()!r} is not a number.") \
                from None
    return out


def _phases(problem, args) -> int:
    """``--phases PNG``: the run across the declared contact phases, its switches, a chart."""
    from dualmech.numeric.inputs import describe
    from dualmech.numeric.phases import phase_chart, simulate_phases
    rtol, atol = _tolerances(args, TOLERANCES[1])
    with _usage():
        params = _params(args.param)
        inputs = _inputs(problem, params, args.input)
        run = simulate_phases(problem, (0.0, args.duration), params=params,
                              samples=args.samples or 400, method=args.method, rtol=rtol,
                              atol=atol, inputs=inputs)
    try:
        path = phase_chart(run, args.phases)
    except OSError as exc:
        raise UsageError(f"`--phases`: cannot write {args.phases!r} ({exc.strerror}).") \
            from None
    doc = {"name": problem.name, "phases": [ph.problem for ph in run.phases],
           "switches": [vars(s) for s in run.switches], "ended": run.ended, "chart": path,
           "method": run.method or None, "cpu_seconds": run.cpu if run.method else None,
           "fallback": run.fallback or None, "rtol": rtol, "atol": atol,
           "inputs": describe(problem, inputs)}
    if run.fallback:
        print(f"dualmech simulate: CVODE cannot run here ({run.fallback}); fell back to "
              "scipy on the generated right-hand side.", file=sys.stderr)
    if args.json:
        print(json.dumps(doc, indent=1))
    else:
        print(" -> ".join(doc["phases"]) or "no phase ran")
        if run.method:
            print(f"{run.method}, rtol {rtol:g}, atol {atol:g}, {run.cpu:.4g} s CPU")
        print("\n".join(str(s) for s in run.switches))
        print(run.ended or f"reached t = {args.duration:g} s")
        print(f"chart: {path}")
    return OK if not run.ended else STOPPED


def phased_summary(problem, duration: float = 10.0, rtol: float = 1e-8, atol: float = 1e-10,
                   method: str = "auto", params: dict | None = None,
                   samples: int | None = None, inputs: dict | None = None) -> dict:
    """Integrate ``problem`` across the contact phases it declares over ``[0, duration]``
    (:func:`~dualmech.numeric.phases.simulate_phases`): what plain ``dualmech simulate
    --json`` prints for such a problem -- :func:`summary`'s keys (``coordinates`` and
    ``initial_state`` of the first phase, ``final_state`` of the last, in its
    ``final_coordinates``; ``None`` when the run ended early, ``message`` saying why) and
    :meth:`PhasedRun.to_dict <dualmech.numeric.phases.PhasedRun.to_dict>`'s ``phases``,
    ``switches``, ``ended`` (and ``samples``).  ``inputs``: the given inputs' histories by
    name (else their declared defaults), driving every phase (``inputs`` in the result says
    which, in words).

    Example
    -------
    >>> from dualmech.problems import load
    >>> s = phased_summary(load("simple_pendulum"), duration=1.0, method="DOP853")
    >>> [ph["problem"] for ph in s["phases"]], s["switches"], s["t_final"]
    (['simple_pendulum'], [], 1.0)
    """
    from dualmech.numeric import SingularityError
    from dualmech.numeric.inputs import describe
    from dualmech.numeric.phases import simulate_phases
    from dualmech.numeric.simulation import default_initial_state, problem_parameters
    values = problem_parameters(problem, params)
    q0, qd0 = default_initial_state(problem)
    names = [q.func.__name__ for q in problem.model(problem.reference).coordinates]
    out = {"name": problem.name,
           "parameters": {s.name: float(v) for s, v in values.items()},
           "coordinates": names + [f"{n}'" for n in names],
           "initial_state": [float(v) for v in q0 + qd0], "final_state": None,
           "final_coordinates": None, "t_final": None, "duration": duration,
           "method": method, "cpu_seconds": None, "steps": None, "rhs_evaluations": None,
           "rtol": rtol, "atol": atol, "success": False, "message": "", "fallback": None,
           "inputs": describe(problem, inputs), "inputs_in_python": None,
           "left_declared": [], "contact": None, "phases": [], "switches": [], "ended": ""}
    try:
        run = simulate_phases(problem, (0.0, duration), params=params, samples=samples or 2,
                              rtol=rtol, atol=atol, method=method, inputs=inputs)
    except SingularityError as exc:
        out["message"] = str(exc)
        return out
    out.update(run.to_dict(samples=bool(samples)))
    last = out["phases"][-1] if out["phases"] else None
    out.update({"final_state": last["final_state"] if last and not run.ended else None,
                "final_coordinates": last["coordinates"] if last else None,
                "t_final": last["t_end"] if last else 0.0, "method": run.method or method,
                "cpu_seconds": run.cpu if run.method else None, "success": not run.ended,
                "message": run.ended, "fallback": run.fallback or None})
    brk = run.open_contact
    if brk is not None:
        out["contact"] = {"reaction": brk.reaction, "time": brk.time,
                          "at_start": brk.at_start, "message": str(brk),
                          "method": run.method or None, "cpu_seconds": None}
    return out


def _phased(problem, args) -> int:
    """Plain ``simulate`` of a problem that declares contact phases: across them."""
    rtol, atol = _tolerances(args, TOLERANCES[0])
    with _usage():
        params = _params(args.param)
        result = phased_summary(problem, args.duration, rtol, atol, args.method, params,
                                args.samples, _inputs(problem, params, args.input))
    if result["fallback"]:
        print(f"dualmech simulate: CVODE cannot run here ({result['fallback']}); fell back to "
              "scipy on the generated right-hand side.", file=sys.stderr)
    status = OK if result["success"] else STOPPED
    if status != OK:
        print(f"dualmech simulate: stopped early: {result['message']}", file=sys.stderr)
    if args.json:
        print(json.dumps(result, indent=1))
        return status
    if result["cpu_seconds"] is None:   # nothing integrated: the line above says why
        return status
    print(f"{' -> '.join(ph['problem'] for ph in result['phases'])}: {result['method']}, "
          f"t = 0 .. {result['t_final']:.6g} s, rtol {rtol:g}, atol {atol:g}: "
          f"{result['cpu_seconds']:.4g} s CPU")
    print("parameters: " + ", ".join(f"{k} = {v:g}" for k, v in result["parameters"].items()))
    if result["inputs"]:
        print("inputs: " + ", ".join(f"{k} = {v}" for k, v in result["inputs"].items()))
    for i, ph in enumerate(result["phases"]):
        if i:
            print("switch: " + str(_switch(result["switches"][i - 1])))
        print(f"phase {i + 1}, {ph['problem']}, t = {ph['t_start']:.6g} .. "
              f"{ph['t_end']:.6g} s")
        width = max(len(c) for c in ph["coordinates"])
        print(f"  {'state'.ljust(width)}  {'initial':>22}  {'final':>22}")
        for c, a, b in zip(ph["coordinates"], ph["initial_state"], ph["final_state"]):
            print(f"  {c.ljust(width)}  {a:22.15g}  {b:22.15g}")
    return status


def _tolerances(args, default: tuple) -> tuple[float, float]:
    """``(rtol, atol)`` of the run: those given, else ``default``."""
    return (args.rtol if args.rtol is not None else default[0],
            args.atol if args.atol is not None else default[1])


class _usage:
    """Turn a bad ``--param`` or ``--input`` (a ``ValueError`` naming ``params`` or
    ``inputs``, or an input) into a :class:`UsageError` naming the option."""

    def __enter__(self):
        return self

    def __exit__(self, kind, exc, tb):
        if kind is None or not issubclass(kind, ValueError) or isinstance(exc, UsageError):
            return False
        text = str(exc)
        if "`params`" in text:
            raise UsageError(text.replace("`params`", "`--param`")) from None
        if "`inputs`" in text or "input" in text.split(":")[0]:
            raise UsageError(text.replace("`inputs`", "`--input`")) from None
        return False


def _switch(doc: dict):
    from dualmech.numeric.phases import Switch
    return Switch(**doc)


def _inputs(problem, params: dict, texts) -> dict:
    """The ``--input`` histories (expressions may name the parameters, at this run's values)."""
    if not texts:
        return {}
    from dualmech.cli.inputs import parse_inputs
    return parse_inputs(texts, {p.symbol.name: p.symbol for p in problem.parameters})


def summary(problem, duration: float = 10.0, rtol: float = 1e-8, atol: float = 1e-10,
            method: str = "auto", params: dict | None = None,
            samples: int | None = None, inputs: dict | None = None) -> dict:
    """Integrate ``problem``'s reference model over ``[0, duration]``: what ``dualmech
    simulate --json`` prints.

    Example
    -------
    >>> from dualmech.problems import load
    >>> s = summary(load("simple_pendulum"), duration=1.0, method="DOP853")
    >>> s["coordinates"], s["method"], len(s["final_state"])
    (['theta', "theta'"], 'DOP853', 2)
    """
    import numpy as np

    from dualmech.numeric import NumericModel, SingularityError
    from dualmech.numeric.cvode import CVODE_METHODS, integrate
    from dualmech.numeric.simulation import (default_initial_state, problem_parameters,
                                             refuse_static)

    from dualmech.numeric.contacts import left_declared
    from dualmech.numeric.inputs import describe, input_functions
    values = problem_parameters(problem, params)
    drive = input_functions(problem, inputs, (0.0, duration), values)
    ref = problem.model(problem.reference)
    model = NumericModel(ref, values, inputs=drive)
    q0, qd0 = default_initial_state(problem)
    y0 = [float(v) for v in q0 + qd0]
    t_eval = np.linspace(0.0, duration, samples) if samples else None
    names = [q.func.__name__ for q in ref.coordinates]
    out = {"name": problem.name,
           "parameters": {s.name: float(v) for s, v in values.items()},
           "coordinates": names + [f"{n}'" for n in names],
           "initial_state": y0, "final_state": None, "t_final": None, "duration": duration,
           "method": method, "cpu_seconds": None, "steps": None, "rhs_evaluations": None,
           "rtol": rtol, "atol": atol, "success": False, "message": "", "fallback": None,
           "inputs": describe(problem, inputs), "inputs_in_python": model.inputs_in_python,
           "left_declared": [], "contact": None}
    try:
        refuse_static(problem, ref)
        run = integrate(model, (0.0, duration), y0, t_eval=t_eval, rtol=rtol, atol=atol,
                        method=method, singular=problem.singular)
    except SingularityError as exc:  # a singular state, or the declared singular set
        out["message"] = str(exc)
        return out
    reached = run.success and run.t.size and run.t[-1] == duration
    out.update({"final_state": run.y[:, -1].tolist() if reached else None,
                "t_final": float(run.t[-1]) if run.t.size else 0.0, "method": run.method,
                "cpu_seconds": run.cpu, "rhs_evaluations": run.evaluations,
                "steps": run.steps if run.method in CVODE_METHODS else None,  # scipy: uncounted
                "success": bool(run.success), "message": run.message})
    if run.message.startswith("fallback: "):
        out["fallback"] = run.message[len("fallback: "):].split("; used scipy")[0]
    seen = run
    if t_eval is None and run.t.size and run.t[-1] > 0:   # the run again, sampled: where it goes
        seen = integrate(model, (0.0, float(run.t[-1])), y0,
                         t_eval=np.linspace(0.0, float(run.t[-1]), 401), rtol=rtol,
                         atol=atol, method=run.method if run.method in CVODE_METHODS
                         else method, singular=problem.singular)
    if seen.t.size:
        out["left_declared"] = left_declared(problem, ref, seen.t, seen.y)
    if reached and not getattr(problem, "inputs", None):
        out["contact"] = _contact(problem, duration, y0, params, rtol, atol, method)
    if samples:
        out["samples"] = {"t": run.t.tolist(), "states": run.y.T.tolist()}
    return out


def _contact(problem, duration, y0, params, rtol, atol, method) -> dict | None:
    """Where a one-sided reaction the problem declares would change sign along the run
    (:func:`~dualmech.numeric.contacts.watch`, by the route ``method`` asks for), or ``None``
    when none does (or none is declared)."""
    from dualmech.numeric.contacts import unilateral_of, watch
    if not unilateral_of(problem):
        return None
    report = watch(problem, (0.0, duration), y0, params, rtol=rtol, atol=atol, method=method)
    if report.first is None:
        return None
    first = report.first
    return {"reaction": first.reaction, "time": first.time, "at_start": first.at_start,
            "message": str(first), "method": report.method or None,
            "cpu_seconds": report.cpu if report.method else None}


def _simulate(args) -> int:
    from dualmech.numeric.cvode import METHODS
    if args.method not in METHODS:
        raise UsageError(f"`--method` {args.method!r} is not one of {', '.join(METHODS)}.")
    problem = _load(args)
    if args.phases is not None and args.single_phase:
        raise UsageError("`--phases PNG` follows the declared contact phases and "
                         "`--single-phase` does not: give one of them.")
    if args.phases is not None:
        with about(problem):
            return _phases(problem, args)
    if getattr(problem, "phases", None) and not args.single_phase:
        with about(problem):
            return _phased(problem, args)
    rtol, atol = _tolerances(args, TOLERANCES[0])
    with _usage(), about(problem):     # a misspelt or out-of-range --param, a missing --input
        params = _params(args.param)
        inputs = _inputs(problem, params, args.input)
        result = summary(problem, args.duration, rtol, atol, args.method, params,
                         args.samples, inputs)
    if result["fallback"]:
        print(f"dualmech simulate: CVODE cannot run here ({result['fallback']}); fell back to "
              "scipy DOP853 on the generated right-hand side.", file=sys.stderr)
    status = OK if result["final_state"] is not None else STOPPED
    if status != OK:
        print(f"dualmech simulate: stopped early: {result['message']}", file=sys.stderr)
    for what in result["left_declared"]:
        print(f"dualmech simulate: warning: {what}, where the problem's model stops "
              "describing its declared scene", file=sys.stderr)
    if result["contact"]:
        print(f"dualmech simulate: warning: {result['contact']['message']}", file=sys.stderr)
    if args.json:
        print(json.dumps(result, indent=1))
        return status
    if result["cpu_seconds"] is None:  # stopped before any sample: the line above says why
        return status
    print(f"{result['name']}: {result['method']}, t = 0 .. {result['t_final'] or 0:.6g} s, "
          f"rtol {rtol:g}, atol {atol:g}: "
          + (f"{result['steps']} steps, " if result["steps"] is not None else "")
          + f"{result['rhs_evaluations']} right-hand sides, {result['cpu_seconds'] or 0:.4g} s "
          "CPU")
    print("parameters: " + ", ".join(f"{k} = {v:g}" for k, v in result["parameters"].items()))
    width = max(len(c) for c in result["coordinates"])
    final = result["final_state"] or [float("nan")] * len(result["coordinates"])
    print(f"{'state'.ljust(width)}  {'initial':>22}  {'final':>22}")
    for c, a, b in zip(result["coordinates"], result["initial_state"], final):
        print(f"{c.ljust(width)}  {a:22.15g}  {b:22.15g}")
    return status
