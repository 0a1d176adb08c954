"""Integration with no Python per step: CVODE + generated C against CVODE + hand-written C.

For the toy car and the 3-link chain (``n_link_pendulum --n 3``), 10 s from the problem's
initial state at rtol 1e-8, atol 1e-10, time in one run (interleaved rounds, medians):

* ours: :func:`dualmech.numeric.cvode.integrate` -- SUNDIALS CVODE driving the generated C
  right-hand side (``CVODE-Adams``, the default, and ``CVODE-BDF``);
* scipy: ``DOP853`` on the same generated C right-hand side (the route before this one);
* hand: CVODE with the same settings driving hand-written C for the same equations
  (``bench/cvode_hand.c``, compiled here against the same SUNDIALS libraries).

Two times for ours: the integration alone (``Run.cpu``: CPU time of the C call, what
``dualmech simulate`` reports) and the whole ``integrate()`` call (wall clock, its Python set-up
included; the code is compiled and loaded before timing).  The hand baseline is one C call,
timed the same way.  Prints ratios ours / hand (target <= 2) and scipy / ours, and each
route's largest difference from DOP853 at rtol 1e-11 (all three must agree to within their
tolerance, or the timing compares different work).

A script, not a test: ``python bench/simulate_cvode.py`` (``--rounds N``, default 200).
"""
from __future__ import annotations

import argparse
import ctypes
import statistics
import time
from pathlib import Path

import numpy as np
import sympy as sp

from dualmech.numeric import NumericModel, cbackend, cvode_driver
from dualmech.numeric._cache import private_dir
from dualmech.numeric.cvode import MAX_STEPS, integrate
from dualmech.numeric.simulation import default_initial_state, problem_parameters
from dualmech.problems import load

SPAN, RTOL, ATOL = (0.0, 10.0), 1e-8, 1e-10
LMM = {"CVODE-Adams": 1, "CVODE-BDF": 2}


def hand_library():
    """``hand_cvode`` from bench/cvode_hand.c, built against the driver's SUNDIALS."""
    libs = cvode_driver.sundials_libraries()
    index = cvode_driver._probe(libs)
    head = ("#include <stdint.h>\n#include <stdio.h>\n#include <stdlib.h>\n"
            f"#include <string.h>\n#define DM_INDEX {index}\n")
    source = head + cvode_driver._DECLARATIONS + (Path(__file__).parent / "cvode_hand.c") \
        .read_text()
    flags = [str(libs[n]) for n in reversed(cvode_driver._LIBS)] + \
        [f"-Wl,-rpath,{libs['cvode'].parent}"]
    folder = private_dir()
    built = cbackend.compile_library(source, folder, folder / "bench_cvode_hand.so", flags)
    if built is None:
        raise SystemExit("bench/cvode_hand.c did not compile")
    fn = ctypes.CDLL(str(built)).hand_cvode
    fn.restype = ctypes.c_int
    P = ctypes.c_void_p
    fn.argtypes = [ctypes.c_int, P, ctypes.c_int, ctypes.c_double, P, ctypes.c_long, P, P,
                   ctypes.c_double, ctypes.c_double, ctypes.c_long, P]
    return fn


def scenes():
    """(label, model, y0, which, hand parameters) for the toy car and the 3-link chain."""
    out = []
    car = load("toy_car")
    values = problem_parameters(car)
    by_name = {s.name: v for s, v in values.items()}
    out.append(("toy_car", car, values, 0, np.array([by_name["g"] / by_name["R"]])))
    chain = load("n_link_pendulum", n=3)
    values = problem_parameters(chain)
    m = np.array([float(values[s]) for s in chain.m])
    lengths = np.array([float(values[s]) for s in chain.l])
    g = float(values[sp.Symbol("g", positive=True)])
    tail = np.cumsum(m[::-1])[::-1]
    mu = tail[np.maximum.outer(np.arange(3), np.arange(3))]
    W = mu * np.outer(lengths, lengths)
    out.append(("3-link chain", chain, values, 1, np.concatenate([W.ravel(), g * tail * lengths])))
    result = []
    for label, p, values, which, par in out:
        model = NumericModel(p.model(p.reference), values)
        q0, qd0 = default_initial_state(p)
        result.append((label, model, np.array(q0 + qd0, dtype=float), which, par))
    return result


def run_hand(fn, which, par, lmm, y0):
    tout = np.array([SPAN[1]])
    yout = np.zeros((1, y0.size))
    steps = ctypes.c_long()
    wall, cpu = time.perf_counter(), time.process_time()
    flag = fn(which, par.ctypes.data, lmm, SPAN[0], y0.ctypes.data, 1, tout.ctypes.data,
              yout.ctypes.data, RTOL, ATOL, MAX_STEPS, ctypes.byref(steps))
    cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    assert flag == 0, flag
    return yout[0], cpu, wall, steps.value


def run_ours(model, y0, method):
    wall = time.perf_counter()
    run = integrate(model, SPAN, y0, rtol=RTOL, atol=ATOL, method=method)
    wall = time.perf_counter() - wall
    assert run.success and run.method == method, run.message
    return run.y[:, -1], run.cpu, wall, run.steps


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=200, help="timed rounds (default 200)")
    args = parser.parse_args()
    fn = hand_library()
    print(f"10 s, rtol {RTOL:g}, atol {ATOL:g}; medians of {args.rounds} interleaved rounds "
          f"(scipy: of {max(args.rounds // 20, 3)}); ms\n")
    header = (f"{'scene':13} {'method':12} {'ours cpu':>9} {'ours call':>9} {'hand':>8} "
              f"{'scipy':>8} {'ours/hand':>9} {'call/hand':>9} {'scipy/ours':>10} "
              f"{'steps o/h':>10}  max |y - ref| ours, hand, scipy")
    print(header)
    print("-" * len(header))
    for label, model, y0, which, par in scenes():
        ref = integrate(model, SPAN, y0, rtol=1e-11, atol=1e-13, method="DOP853").y[:, -1]
        y_sc, *_ = run_ours(model, y0, "DOP853")  # warm: compiled and loaded
        scipy_cpu = [run_ours(model, y0, "DOP853")[1]
                     for _ in range(max(args.rounds // 20, 3))]
        for method, lmm in LMM.items():
            y_o, *_ = run_ours(model, y0, method)
            y_h, *_ = run_hand(fn, which, par, lmm, y0)
            ours_cpu, ours_wall, hand_cpu = [], [], []
            for _ in range(args.rounds):
                _, c, w, so = run_ours(model, y0, method)
                ours_cpu.append(c)
                ours_wall.append(w)
                _, c, _, sh = run_hand(fn, which, par, lmm, y0)
                hand_cpu.append(c)
            oc, ow, hc = (1e3 * statistics.median(x) for x in (ours_cpu, ours_wall, hand_cpu))
            sc = 1e3 * statistics.median(scipy_cpu)
            errs = [np.abs(y - ref).max() for y in (y_o, y_h, y_sc)]
            print(f"{label:13} {method:12} {oc:9.3f} {ow:9.3f} {hc:8.3f} {sc:8.3f} "
                  f"{oc / hc:9.2f} {ow / hc:9.2f} {sc / oc:10.1f} {f'{so}/{sh}':>10}  "
                  + ", ".join(f"{e:.1e}" for e in errs))
    print("\nours cpu: the C call alone (Run.cpu, what `dualmech simulate` reports); "
          "ours call: the whole integrate() call, wall clock; hand and scipy: CPU time.")


if __name__ == "__main__":
    main()
