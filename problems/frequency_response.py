r"""A second-order system identified from its frequency response (MIT 2.003J, spring 2011, final
exam, problem 2).

The source applies ``F(t) = F0 cos(omega t)`` (``F0 = 9 N``) to an unknown system at 21
frequencies from 0 to 10 rad/s, plots the steady-state amplitude, assumes the system is
``m x'' + c x' + k x = F(t)`` and reads ``m, c, k`` off the plot.  This module is that
model, written both ways; the plot itself is not in the text (only the two readings the
solution uses, ``X(0) = 3 m`` and ``X(4 rad/s) = 4 m``).

Sign convention::

      wall                               the block slides on a frictionless guide;
      |/|        k                       x = 0 where the spring is unstretched
      |/|---/\/\/\/\/\---+-------+
      |/|                |   m   |----> F(t) = F0 cos(omega t)
      |/|------[ c ------+-------+
                             +--> x,  I

Frames and bodies: one inertial frame ``O`` (``I`` along the guide); the block is a particle
``m`` at ``x I``.

Free-body diagram (along ``I``; weight and guide act across it)::

      spring -k x I,    dashpot -c x' I,    drive F(t) I          m x'' = -k x - c x' + F(t)

Lagrangian (written independently)::

      T = m x'^2/2,   V = k x^2/2,   R = c x'^2/2,   Q = F(t)

Frequency response (hand derivation): the steady state is ``x_p = Re(X e^{i omega t})`` with
``X = F0 / (k - m omega^2 + i c omega)``, amplitude
``|X| = F0 / sqrt((k - m omega^2)^2 + (c omega)^2)``; ``|X(0)| = F0/k``.

The source's identification (part (a)): ``k = F0/X(0) = 3 N/m``; reading the peak of the plot
as ``omega_n = sqrt(k/m) ~ 4 rad/s`` gives ``m ~ 3/16 kg``; then ``X(4) = 4 m`` with
``k - m omega^2 = 0`` at ``omega = 4`` gives ``c = F0/(4 X(4)) ~ 9/16 kg/s``.  These values
reproduce both readings exactly (tested).  Note: with them the damping ratio is
``zeta = c/(2 sqrt(k m)) = 3/8``, and the amplitude peaks at
``omega_n sqrt(1 - 2 zeta^2) ~ 3.39 rad/s`` with ``~4.31 m``, not at 4 rad/s -- taking the
peak for ``omega_n`` is an approximation; without the figure it cannot be judged further.

Part (b) (the unforced response from ``x(0) = 1``, ``x'(0) = 0``) has no printed answer in the
text; by hand, with ``omega_d = omega_n sqrt(1 - zeta^2)``::

      x(t) = exp(-zeta omega_n t) (cos(omega_d t) + zeta omega_n / omega_d sin(omega_d t))

The tests integrate the model and compare.  No errata found.

Example
-------
>>> p = FrequencyResponse(); p.validate()
>>> p.model("lagrange").equations[0]
-F0*cos(omega*t) + c*Derivative(x(t), t) + k*x(t) + m*Derivative(x(t), (t, 2))
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, coordinate, rate, t, DAMPING, FORCE, FREQUENCY,
                      LENGTH, MASS, STIFFNESS)

__all__ = ["FrequencyResponse", "PROBLEMS", "amplitude", "m", "c", "k", "F0", "omega", "x"]

m, c, k, F0, omega = sp.symbols("m c k F0 omega", positive=True)
x = coordinate("x")
drive = F0 * sp.cos(omega * t)


def amplitude(eqs: EquationSet, w) -> sp.Expr:
    """Steady-state amplitude of ``eqs`` under its drive at frequency ``w``, from its matrices.

    ``M, C, K`` come from :meth:`EquationSet.linearize` of the unforced model (``F0 = 0``);
    the drive's amplitude is the coefficient of ``cos(omega t)`` in the generalised force,
    ``F0``.  ``|X| = F0 / |K - M w^2 + i C w|`` (single coordinate).
    """
    M0, C0, K0 = eqs.substitute({F0: 0}).linearize()
    z = K0[0] - M0[0] * w**2 + sp.I * C0[0] * w
    return F0 / sp.sqrt(sp.expand(z * sp.conjugate(z)))


class FrequencyResponse(Problem):
    """``m x'' + c x' + k x = F0 cos(omega t)``: the model behind the frequency-response data."""

    name = "frequency_response"
    title = "Second-order system behind a frequency response"
    source = "001_9d08622cf8d659c2.txt: 2.003J spring 2011, final exam, problem 2"
    summary = ("The model m x'' + c x' + k x = F written both ways; the identified m, c, k "
               "reproduce the two readings the source uses.")
    parameters = (
        Parameter(m, MASS, 0.1875, (0.01, 5.0), "mass (source: ~3/16 kg)"),
        Parameter(c, DAMPING, 0.5625, (0.01, 20.0), "damping (source: ~9/16 kg/s)"),
        Parameter(k, STIFFNESS, 3.0, (0.1, 100.0), "stiffness (source: 3 N/m)"),
        Parameter(F0, FORCE, 9.0, (0.1, 50.0), "amplitude of the drive (source: 9 N)"),
        Parameter(omega, FREQUENCY, 4.0, (0.05, 10.0), "frequency of the drive"),
    )
    coordinates = (
        Coordinate(x, LENGTH, (-5.0, 5.0), (-20.0, 20.0), "position, x = 0 unstretched"),
    )

    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` along ``I``."""
        O = Frame.ground("O")
        block = Particle("block", m, Point.origin(O).locate("P", x * O.x))
        ne = NewtonEuler(coordinates=[x], ground=O, description="sum F = m a along I")
        ne.linear_spring("spring", block, k, x, O.x)
        ne.linear_damper("dashpot", block, c, rate(x), O.x)
        ne.force("drive", block, drive * O.x)
        ne.linear_momentum(block, O.x)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T``, ``V``, ``R`` and the drive's generalised force."""
        lg = Lagrangian(coordinates=[x], description="T, V, R, Q")
        lg.kinetic("T of block", m * rate(x)**2 / 2)
        lg.spring("spring", k, x)
        lg.damper("dashpot", c, rate(x))
        lg.generalized_force("drive", [drive])
        return lg.equations()

    def published(self) -> list[Published]:
        lag = self.model("lagrange")
        (w_n,) = lag.substitute({F0: 0}).natural_frequencies()
        where = "final exam, problem 2 (a)"
        return [
            Published("(a) model", "motion", (m * rate(x, 2) + c * rate(x) + k * x - drive,),
                      where="final exam, problem 2: m x'' + c x' + k x = F(t)"),
            Published("(a) X(0) = F0/k", "expression", (F0 / k,), (amplitude(lag, 0),),
                      where=where),
            Published("(a) omega_n = sqrt(k/m)", "expression", (sp.sqrt(k / m),), (w_n,),
                      where=where),
            Published("(a) X(omega)", "expression",
                      (F0 / sp.sqrt((k - m * omega**2)**2 + (c * omega)**2),),
                      (amplitude(lag, omega),), where=where),
        ]


PROBLEMS = (FrequencyResponse,)
