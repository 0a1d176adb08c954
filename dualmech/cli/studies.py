"""The ``chart``, ``atlas`` and ``fidelity`` subcommands of ``dualmech``.

::

    dualmech chart NAME [NAME...] | --all [--out DIR] [--quick]   work-precision diagrams
    dualmech atlas NAME [--out DIR] [--section S ...]              where methods fail
    dualmech fidelity NAME [--out DIR]                             the fidelity ladder
    ... --json                                                     JSON instead of text

NAME is anything :func:`dualmech.problems.get` takes: a catalogue name, ``path.py[:Class]``,
``module:Class`` or a registered catalogue's problem; ``chart`` also takes a registered
catalogue's name for all its problems, and ``chart --all`` is every problem ``dualmech list``
lists (:mod:`dualmech.cli.names`).  The problem object itself goes to the study, which says
"not applicable" with the declaration that would make it applicable.

:func:`register` adds them to an :mod:`argparse` sub-parser set; each handler returns an exit
status (:mod:`dualmech.cli.errors`) -- 0 done, 2 a usage error (an unknown problem, an
unwritable directory, a section that does not exist, a study that does not apply), an error
in a problem file (shown at its file and line), a model that cannot be built or a problem
that could not be charted (the others are) -- and prints errors on stderr, never a
traceback.  ``chart`` of several problems (``--all``) does not fail for a problem that is not
applicable (said on stderr with the reason) as long as one problem was charted
(:data:`CHART_EXIT_STATUS`).  A problem that declares contact phases (``Problem.phases``)
also gets ``DIR/NAME_phases.png``: its motion across every phase, the switches marked (the
work-precision diagrams compare integrators on its first model, up to the first switch).  Progress goes to stderr (a bar on a terminal, one line per problem otherwise).

Example
-------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="dualmech")
>>> register(parser.add_subparsers(dest="command"))
>>> args = parser.parse_args(["atlas", "nonexistent_problem"])
>>> args.func(args)
2
"""
from __future__ import annotations

import contextlib
import os
import sys
from pathlib import Path

from dualmech.cli import names as _names
from dualmech.cli.errors import (OK, USAGE_OR_MODEL_ERROR, UsageError, about, columns,
                                 describe, fit, guarded, say, worst)
from dualmech.cli.options import positive_number, whole_number

__all__ = ["register", "CHART_EXIT_STATUS"]


def register(subparsers) -> None:
    """Add ``chart``, ``atlas`` and ``fidelity`` to ``subparsers`` (from ``add_subparsers``)."""
    p = subparsers.add_parser(
        "chart", help="work-precision diagrams: error against CPU time",
        description="Integrate every formulation of each problem with every integrator over "
                    "a sweep of tolerances and chart the error against a high-accuracy "
                    "reference versus CPU time; write DIR/NAME_workprecision.{csv,json,png,svg}.")
    p.add_argument("names", nargs="*", metavar="NAME",
                   help="problems to chart: catalogue names, path.py[:Class], module:Class, "
                        "a registered catalogue's problem or the catalogue's name")
    p.add_argument("--all", action="store_true",
                   help="chart every problem: the catalogue's and the registered catalogues'")
    _out(p)
    p.add_argument("--duration", metavar="T", type=positive_number, default=5.0,
                   help="simulated seconds, cut to fit the scene (default: %(default)s)")
    p.add_argument("--quick", action="store_true",
                   help="three tolerances and two step counts instead of the full sweep")
    p.add_argument("--repeats", metavar="K", type=whole_number(1, 50), default=None,
                   help="runs per point; its CPU time is their median (default: 5, "
                        "with --quick 1)")
    p.add_argument("--budget", metavar="S", type=positive_number, default=None,
                   help="CPU seconds one point may spend before it is a 'did not finish' "
                        "point (default: 20, with --quick 1)")
    p.add_argument("--jobs", metavar="J", type=whole_number(1, 64), default=None,
                   help="problems charted at once, one process each (default: the cores "
                        "this process may use)")
    p.epilog = CHART_EXIT_STATUS
    p.set_defaults(func=guarded(_chart))

    p = subparsers.add_parser(
        "atlas", help="where methods fail: singularities, drift, stiffness, ...",
        description="Find and report where the problem's formulations and integrators fail: "
                    "coordinate singularities, DAE drift, stiffness, linearisation, chaos; "
                    "write DIR/NAME_atlas.{json,txt} and a chart per section.")
    p.add_argument("name", metavar="NAME", help="the problem")
    _out(p)
    p.add_argument("--section", action="append", metavar="S", dest="sections",
                   help="run only this section (repeatable): singularities, dae_drift, "
                        "stiffness, linearisation, floquet, chaos")
    p.set_defaults(func=guarded(_atlas))

    p = subparsers.add_parser(
        "fidelity", help="the fidelity ladder: what each simplification costs",
        description="Print each rung's derivation time, right-hand-side cost and error "
                    "against the richest model along a standard trajectory; write "
                    "DIR/NAME_fidelity.{json,png,svg}.")
    p.add_argument("name", metavar="NAME", help="the problem")
    _out(p)
    p.set_defaults(func=guarded(_fidelity))


#: ``chart``'s exit statuses, as its ``--help`` ends
CHART_EXIT_STATUS = (
    "Exit status: 0 every problem charted, or not applicable (the reason and the declaration "
    "that would make it applicable printed on stderr: a problem with no model that "
    "integrates in its reference coordinates has no chart to draw, which is not an error); "
    "2 any problem that could not be charted for another reason (a model that cannot be "
    "built, an error in a problem file, a failed reference run, an internal error), a usage "
    "error, or nothing charted at all (every problem named not applicable); 130 "
    "interrupted.")


def _out(p) -> None:
    p.add_argument("--out", metavar="DIR", type=Path, default=Path("out"),
                   help="output directory (default: %(default)s)")
    p.add_argument("--json", action="store_true",
                   help="print JSON (the results and the files written) instead of text")


def _print_json(obj) -> None:
    import json
    print(json.dumps(obj, indent=1, default=str))


def _problem(name: str):
    """The problem ``name`` names (any NAME form; :func:`dualmech.cli.names.get`)."""
    return _names.get(name)


def _writable(out: Path) -> Path:
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UsageError(f"cannot create the output directory {out}: {exc.strerror or exc}") \
            from None
    return out


def _chart(args) -> int:
    from dualmech.progress import progress
    if not args.all and not args.names:
        raise UsageError("name at least one problem, or use --all.")
    chosen = _names.selected(args.names, args.all)
    out = _writable(args.out)
    jobs = min(args.jobs or len(os.sched_getaffinity(0)), len(chosen)) or 1
    _CHART_JOB.clear()
    _CHART_JOB.update(problems=chosen, args=args, out=out, bars=jobs == 1)
    results = []
    with contextlib.ExitStack() as stack:
        if jobs == 1:
            each = map(_chart_one, progress(range(len(chosen)), "charting"))
        else:
            import multiprocessing
            pool = stack.enter_context(multiprocessing.get_context("fork").Pool(jobs))
            each = pool.imap(_chart_one, range(len(chosen)))
        for r in each:
            results.append(r)
            if jobs > 1:
                print(f"charting: {len(results)}/{len(chosen)} ({r[0]})", file=sys.stderr,
                      flush=True)
            if r[1] is None and not args.json:
                print(fit(r[3], columns(sys.stdout)), flush=True)
    return _chart_status(results, args)


def _chart_status(results: list, args) -> int:
    """Print the JSON and the problems not charted; the exit status of
    :data:`CHART_EXIT_STATUS` (``results``: :func:`_chart_one`'s tuples)."""
    done = [r[2] for r in results if r[1] is None]
    failed = [(r[0], r[1]) for r in results if r[1] is not None and not r[4]]
    inapplicable = [(r[0], r[1]) for r in results if r[1] is not None and r[4]]
    if args.json:
        _print_json(done[0] if len(done) == 1 and not args.all and not failed
                    and not inapplicable else done)
    for name, failure in inapplicable:
        say("chart", f"{name}: {failure.message}", "")
    for name, failure in failed:
        say("chart", f"no chart for {name}: {failure.message}", "")
    status = worst([OK] + [failure.status for _, failure in failed])
    if not done and inapplicable:
        status = worst([status, USAGE_OR_MODEL_ERROR])
    return status


#: What the chart workers read (set before they fork): the problems, the arguments.
_CHART_JOB: dict = {}


def _chart_one(i: int) -> tuple:
    """Chart problem ``i`` of :data:`_CHART_JOB`: ``(name, failure, json, text line,
    not applicable)``."""
    from dualmech.numeric.integrators import WorkBudget
    from dualmech.numeric.studies.workprecision import (BUDGET, QUICK_BUDGET, STEPS,
                                                        TOLERANCES, NotApplicable,
                                                        work_precision)
    p, args, out = _CHART_JOB["problems"][i], _CHART_JOB["args"], _CHART_JOB["out"]
    tolerances = (1e-3, 1e-6, 1e-9) if args.quick else TOLERANCES
    steps = (32, 256) if args.quick else STEPS
    budget = QUICK_BUDGET if args.quick else BUDGET
    if args.budget is not None:
        budget = WorkBudget(args.budget, budget.evaluations)
    repeats = args.repeats or (1 if args.quick else 5)
    try:
        with about(p):
            wp = work_precision(p, duration=args.duration, tolerances=tolerances,
                                steps=steps, repeats=repeats, budget=budget,
                                progress=_CHART_JOB["bars"])
        paths = wp.write(out)
        with about(p):
            phased = _phase_chart(p, args.duration, out)
    except OSError:
        raise
    except NotApplicable as exc:   # no chart to draw: said, not a failure of the run
        return p.name, describe(exc, p), None, "", True
    except Exception as exc:  # noqa: BLE001 - one problem's failure does not stop --all
        return p.name, describe(exc, p), None, "", False
    unfinished = sum(r.did_not_finish for r in wp.runs)
    line = (f"{p.name}: {len(wp.runs)} runs over t in [0, {wp.span[1]:.3g}] s"
            + (f" ({wp.span_note})" if wp.span_note else "")
            + (f"; {unfinished} did not finish within {budget}" if unfinished else "")
            + (f"; {len(wp.skipped)} model(s) or form(s) not run, said why on the chart and "
               "in the JSON's `skipped`" if wp.skipped else "")
            + "; wrote " + ", ".join(str(x) for x in paths))
    doc = {**wp.to_dict(), "files": [str(x) for x in paths]}
    if phased is not None:
        run, path = phased
        line += (f"; the motion across its contact phases ({' -> '.join(_phase_names(run))}, "
                 f"switching at t = {', '.join(f'{s.time:.3g}' for s in run.switches) or '-'}"
                 f" s): {path}")
        doc.update({"phases": _phase_names(run), "switches": [vars(s) for s in run.switches],
                    "phases_chart": path})
        doc["files"].append(path)
    return p.name, None, doc, line, False


def _phase_names(run) -> list:
    """The names of the phases a :class:`~dualmech.numeric.phases.PhasedRun` ran."""
    return [ph.problem for ph in run.phases]


def _phase_chart(problem, duration: float, out: Path):
    """For a problem that declares contact phases (``Problem.phases``) and a default history
    for each given input it has (every phase driven by them): its motion across them over
    ``duration`` drawn to ``out/NAME_phases.png``, ``(run, path)``; else None.  (The
    work-precision diagrams compare integrators on one model, so their scene ends at the
    first switch.)"""
    from dualmech.numeric.inputs import declared_inputs
    if not getattr(problem, "phases", None) or any(
            getattr(x, "history", None) is None for x in declared_inputs(problem).values()):
        return None
    from dualmech.numeric.phases import phase_chart, simulate_phases
    run = simulate_phases(problem, (0.0, duration), samples=400)
    return run, phase_chart(run, out / f"{problem.name}_phases.png")


def _atlas(args) -> int:
    from dualmech.numeric.studies.atlas import SECTIONS, atlas
    bad = [s for s in (args.sections or []) if s not in SECTIONS]
    if bad:
        raise UsageError(f"unknown section(s) {', '.join(bad)}; choose from {', '.join(SECTIONS)}.")
    p = _problem(args.name)
    out = _writable(args.out)
    with about(p):
        result = atlas(p, sections=tuple(args.sections or SECTIONS))
    paths = result.write(out)
    if args.json:
        _print_json({**result.to_dict(), "files": [str(x) for x in paths]})
        return OK
    print(fit(str(result), columns(sys.stdout)))
    print(fit(f"\nwrote {', '.join(str(x) for x in paths)}", columns(sys.stdout)))
    return OK


def _fidelity(args) -> int:
    from dualmech.numeric.studies.fidelity import ladder, not_applicable
    p = _problem(args.name)
    with about(p):
        why = not_applicable(p)
    if why is not None:
        raise UsageError(f"`{p.name}` has no fidelity ladder (not applicable): {why}")
    out = _writable(args.out)
    with about(p):
        result = ladder(p)
    paths = result.write(out)
    if args.json:
        _print_json({**result.to_dict(), "files": [str(x) for x in paths]})
        return OK
    print(result)   # a table: its rows are not wrapped
    print(fit(f"\nwrote {', '.join(str(x) for x in paths)}", columns(sys.stdout)))
    return OK
