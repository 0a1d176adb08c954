"""Contact events with no Python per step: CVODE + event functions in C against scipy's route.

Three runs, each timed on both routes in one run (interleaved rounds, medians):

* ``slack``: the simple pendulum thrown from theta0 = 2 rad at 4 rad/s, watched until its
  string goes slack (:func:`dualmech.numeric.contacts.watch`; the one-sided reaction ``T``);
* ``holds``: the toy car from its initial state over 10 s, its track's push ``F_r`` watched
  and never reaching zero (the whole span, an event function evaluated at every step);
* ``phased``: the teacher's ladder (tests/corpus/teacher_problems/sliding_ladder.py) released at
  0.3 rad from the wall, chained across its contact phases over 3 s
  (:func:`dualmech.numeric.phases.simulate_phases`: the wall's push reaching zero, then the
  free ladder's angle reaching its declared domain's end).

Routes: ``CVODE-Adams`` (the default where it can run: SUNDIALS CVODE driving the generated C,
the reactions and bounds as event functions compiled to C) and scipy's ``DOP853`` with Python
event functions (the fallback).  Two times each: the integrations alone (``cpu``, what
``dualmech simulate --phases`` reports) and the whole call (wall clock, its Python set-up and
the reactions' minima included; everything is compiled before timing).  Prints the ratios
scipy / CVODE and the event times from both routes beside an independent one derived by hand
(the pendulum: T = 0 at cos(theta) = (2 g cos(theta0) - a theta0'^2) / (3 g), the time by
quadrature of the energy equation; the ladder: cos(theta) = (2/3) cos(theta0), the time by
quadrature, as tests/test_contact_phases.py derives them).

A script, not a test: ``python bench/simulate_events.py`` (``--rounds N``, default 30).
"""
from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import numpy as np
from scipy.integrate import quad

from dualmech import problems
from dualmech.numeric.contacts import watch
from dualmech.numeric.phases import simulate_phases

ROUTES = ("CVODE-Adams", "DOP853")
LADDER = Path(__file__).resolve().parents[1] / "tests" / "corpus" / "teacher_problems" / \
    "sliding_ladder.py"


def pendulum_slack_time(a=0.8, g=9.81, th0=2.0, w0=4.0) -> float:
    """By hand: theta'^2 = w0^2 + 2 g / a (cos theta - cos th0); the string slackens at
    cos(theta) = (2 g cos th0 - a w0^2) / (3 g); t = integral of d(theta) / theta'."""
    slack = np.arccos((2 * g * np.cos(th0) - a * w0**2) / (3 * g))
    rate = lambda th: np.sqrt(w0**2 + 2 * g / a * (np.cos(th) - np.cos(th0)))  # noqa: E731
    return quad(lambda th: 1 / rate(th), th0, slack, epsabs=1e-14, epsrel=1e-13)[0]


def ladder_switch_time(m=10.0, L=4.0, g=9.81, th0=0.3) -> float:
    """By hand: theta'^2 = (3 g / L)(cos th0 - cos theta); N_w = 0 at cos = (2/3) cos th0."""
    c0, k = np.cos(th0), np.sqrt(3 * g / L)
    return quad(lambda u: 2 / (k * np.sin(np.arccos(c0 - u * u))), 0, np.sqrt(c0 / 3),
                epsabs=1e-13, epsrel=1e-13)[0]


def scenes():
    """``{label: (call(method) -> (event time or None, cpu), hand event time or None)}``."""
    pendulum, car = problems.get("simple_pendulum"), problems.get("toy_car")
    ladder = problems.load(f"{LADDER}:WallLadder")

    def slack(method):
        r = watch(pendulum, (0, 5), y0=[2.0, 4.0], method=method)
        return r.first.time, r.cpu

    def holds(method):
        r = watch(car, (0, 10), method=method)
        assert r.first is None, r.first
        return None, r.cpu

    def phased(method):
        run = simulate_phases(ladder, (0, 3), samples=300, method=method)
        return run.switches[0].time, run.cpu

    return {"slack (pendulum)": (slack, pendulum_slack_time()),
            "holds (toy car, 10 s)": (holds, None),
            "phased (ladder)": (phased, ladder_switch_time())}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=30)
    rounds = parser.parse_args().rounds
    print(f"{'run':24} {'route':12} {'cpu (ms)':>9} {'wall (ms)':>10} {'event time (s)':>20} "
          f"{'rel. to hand':>13}")
    for label, (call, hand) in scenes().items():
        for method in ROUTES:  # warm-up: derive, generate and compile before timing
            call(method)
        cpu = {m: [] for m in ROUTES}
        wall = {m: [] for m in ROUTES}
        event = {}
        for _ in range(rounds):
            for method in ROUTES:
                start = time.perf_counter()
                event[method], c = call(method)
                wall[method].append(time.perf_counter() - start)
                cpu[method].append(c)
        for method in ROUTES:
            e = event[method]
            rel = f"{(e - hand) / hand:13.2e}" if e is not None and hand else f"{'-':>13}"
            shown = f"{e:20.15f}" if e is not None else f"{'none (to the end)':>20}"
            print(f"{label:24} {method:12} {1e3 * statistics.median(cpu[method]):9.3f} "
                  f"{1e3 * statistics.median(wall[method]):10.3f} {shown} {rel}")
        ratio_cpu = statistics.median(cpu["DOP853"]) / statistics.median(cpu["CVODE-Adams"])
        ratio_wall = statistics.median(wall["DOP853"]) / statistics.median(wall["CVODE-Adams"])
        agree = "" if hand is None else \
            f"; event times differ by {abs(event['DOP853'] - event['CVODE-Adams']):.2e} s"
        print(f"{label:24} scipy / CVODE: {ratio_cpu:.1f}x (integration), {ratio_wall:.1f}x "
              f"(whole call){agree}")
    print(f"({rounds} rounds, medians; watch's defaults rtol 1e-9, atol 1e-11; "
          "simulate_phases' rtol 1e-10, atol 1e-12)")


if __name__ == "__main__":
    main()
