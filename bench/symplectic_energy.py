"""Energy error over 1000 periods: symplectic fixed-step methods against error-controlled RK.

Usage: python bench/symplectic_energy.py [--periods N] [--out docs/symplectic_energy]

Panel 1: the pendulum as a particle (pendulum_particle), released at 1 rad -- RATTLE on the
Cartesian index-3 form (40 steps per small-angle period), the implicit midpoint rule on the
angle (same step), RK45 at rtol 1e-6 on the index-1 DAE and on the angle, DOP853 at rtol
1e-8 on the angle.  Panel 2: the compound double pendulum (configuration-dependent mass
matrix) -- midpoint against RK45 and DOP853.  Prints each run's CPU time, its steps and its
largest energy error in the first and the last tenth of the run (bounded: equal; drift: the
last larger by the ratio of the times).
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from dualmech.numeric.charts import panels, save
from dualmech.numeric.formulations import formulations
from dualmech.numeric.integrators import integrate
from dualmech.numeric.simulation import problem_parameters
from dualmech.numeric.symplectic import constraint_functions
from dualmech import get


def _runs(forms, jobs, end, te):
    out = []
    for label, f, method, kw in jobs:
        start = time.process_time()
        run = integrate(f.rhs, (0.0, end), f.y0, method, t_eval=te, atol=kw.get("rtol", 1e-6)
                        * f.scales, hamiltonian=f.energy, **kw)
        cpu = time.process_time() - start
        dE = np.abs(f.energy_change(run.y))
        k = te.size // 10
        print(f"  {label:34s} {cpu:7.2f} s CPU {run.steps:8d} steps  |dE| first tenth "
              f"{dE[1:k].max():.2e} J, last tenth {dE[-k:].max():.2e} J")
        out.append((label, dE))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--periods", type=int, default=1000)
    ap.add_argument("--out", default="docs/symplectic_energy")
    args = ap.parse_args()
    fig, axes = panels(2, f"energy error over {args.periods} periods: symplectic methods stay "
                       "bounded, error-controlled Runge-Kutta drifts", height=3.4,
                       sharex=False)

    p = get("pendulum_particle")
    forms = formulations(p, y0=[1.0, 0.0], stabilisations=("none",))[0]
    lag = next(f for f in forms if f.name == "lagrange")
    cart = next(f for f in forms if f.name.startswith("cartesian"))
    gG = constraint_functions(cart.constrained, problem_parameters(p))
    period = 2 * np.pi * np.sqrt(1.0 / 9.81)
    end = args.periods * period
    te = np.linspace(0.0, end, 4001)
    print(f"pendulum_particle, {args.periods} periods of {period:.4g} s, from 1 rad:")
    h = period / 40
    runs = _runs(forms, [
        ("RATTLE, cartesian, h = T/40", cart, "rattle", {"step": h, "constraint": gG}),
        ("midpoint, angle, h = T/40", lag, "midpoint", {"step": h}),
        ("RK45 rtol 1e-6, cartesian index 1", cart, "RK45", {"rtol": 1e-6}),
        ("RK45 rtol 1e-6, angle", lag, "RK45", {"rtol": 1e-6}),
        ("DOP853 rtol 1e-8, angle", lag, "DOP853", {"rtol": 1e-8}),
    ], end, te)
    _plot(axes[0], te / period, runs, "pendulum_particle (m = 1 kg, l = 1 m), from 1 rad")

    dp = formulations(get("compound_double_pendulum"), models=["lagrange"])[0][0]
    lam = np.linalg.eigvals(_jac(dp))
    slow = 2 * np.pi / np.abs(lam.imag[lam.imag > 0]).min()
    end = args.periods * slow
    te = np.linspace(0.0, end, 4001)
    print(f"compound_double_pendulum, {args.periods} periods of its slow mode ({slow:.4g} s), "
          f"from {dp.y0[:2].tolist()} rad:")
    runs = _runs([dp], [
        ("midpoint, h = T/40", dp, "midpoint", {"step": slow / 40}),
        ("RK45 rtol 1e-6", dp, "RK45", {"rtol": 1e-6}),
        ("DOP853 rtol 1e-8", dp, "DOP853", {"rtol": 1e-8}),
    ], end, te)
    _plot(axes[1], te / slow, runs, "compound_double_pendulum (M depends on the angles)")
    for path in save(fig, Path(args.out)):
        print("wrote", path)


def _jac(f):
    from dualmech.numeric.studies.regimes import jacobian
    n = f.n
    return jacobian(f.rhs, 0.0, np.zeros(2 * n))


def _plot(ax, x, runs, title):
    for label, dE in runs:
        # the running maximum: a bounded error is a flat line, a drift a rising one
        ax.plot(x[1:], np.maximum.accumulate(np.maximum(dE[1:], 1e-17)), label=label,
                linewidth=1.1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title(title, fontsize="small")
    ax.set_xlabel("time [periods]")
    ax.set_ylabel("max |E(s) - E(0)|, s <= t [J]")
    ax.legend(fontsize="x-small", loc="upper left")


if __name__ == "__main__":
    main()
