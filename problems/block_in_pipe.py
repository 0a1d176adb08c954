r"""Block in a pivoting pipe, held by a spring (free length ``y0``) and a damper.

Source: ``sources/003_d6818267b4d96a20.txt``, lecture 18, "Block in a pipe I/II" (old exam,
"Oppgave 3, Kloss i rør").  A block of mass ``m`` slides without friction inside a pipe that
swings about a fixed pivot O.  All mass but the block's is negligible.  A spring ``k``
(force-free at ``y = y0``) and a damper ``d`` act along the pipe between O and the block.

Sign convention (the figure is not in the text; this one matches the printed Lagrangian)::

            O (pivot) ------> i
           /|                       e_r  = -P.y = ( sin th, -cos th)   along the pipe, outward
          / |th                     e_th =  P.x = ( cos th,  sin th)
     pipe/  |                       r_block = y e_r
        /   v  -j                   spring -k (y - y0) e_r and damper -d y' e_r on the block
     [m]  block, y from O           N e_th: the pipe's normal force on the block
                                    gravity -m g j

Frames.  ``O`` inertial (``i`` right, ``j`` up); ``P = O.child(rot_z(theta))`` turns with the
pipe.  Bodies: the block, a particle ``m`` at ``y e_r`` (the source's ``T`` has no spin term);
the pipe, a massless rigid body in ``P``.

Free-body diagrams::

    block:  -m g j,  -k (y - y0) e_r,  -d y' e_r,  N e_th
    pipe:   -N e_th at the block,  +k (y - y0) e_r and +d y' e_r at O,  pivot force at O

Direct form, with ``a = (y'' - y th'^2) e_r + (y th'' + 2 y' th') e_th``::

    block . e_r :   m (y'' - y th'^2)     = m g cos th - k (y - y0) - d y'
    block . e_th:   m (y th'' + 2 y' th') = -m g sin th + N
    pipe, moments about O:  0 = -y N                      (massless pipe)

So ``N = 0``: a massless pipe can only guide the block, never push it (the spring and damper
act along the pipe, through O, and have no moment).  The block moves as a free particle under
gravity and a central spring-damper.

Lagrangian, written independently (the source's)::

    L = m (y'^2 + y^2 th'^2)/2 + m g y cos th - k (y - y0)^2/2,     Q = (0, -d y')
    th:  m y^2 th'' + 2 m y y' th' + m g y sin th = 0
    y :  m y'' - m y th'^2 - m g cos th + k (y - y0) + d y' = 0

The normal force once more, independently (``multiplier``, :func:`multiplier_model`): free
the block from the pipe's axis with an offset ``w`` along ``e_th`` (``r = y e_r + w e_th``),
held by ``w = 0`` with multiplier ``N``: the pair ``N e_th`` on the block and ``-N e_th`` on
the pipe at the block does virtual work ``N dw``::

    r' = (y' - w th') e_r + (y th' + w') e_th
    w :  m (w'' - w th'^2 + 2 y' th' + y th'') + m g sin th = N     (on w = 0: the block's e_th
                                                                     equation above)

so ``N`` is derived twice, and both derivations give ``N = 0``.  A reaction that vanishes
identically cannot be told from its negative or its double: the mutants "flip/double the
constraint ``N``" of this model give the same motion and the same ``N`` as the model itself,
and the mutation score reports them apart as *equivalent* (:mod:`dualmech.verify.mutation`).  A
wrong term that makes either derivation's ``N`` non-zero is caught (pinned in the tests).

Equilibrium (derived by the library in the tests): ``th = 0``, ``y = y0 + m g/k``; small
oscillations ``omega^2 = k/m`` (along the pipe) and ``g/(y0 + m g/k)`` (swing).

Errata: none.  Garbled: the slide "Block in a pipe I" lists the generalised forces as
"theta and -d.y"; read, with its own ``Q = -d q'``, as ``(0, -d y')``.

Example
-------
>>> p = BlockInPipe(); p.validate()
>>> p.model("newton_euler").reactions_solved()
{N: 0}
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, RigidBody, coordinate, rate, rot_z,
                      ACCELERATION, ANGLE, DAMPING, FORCE, LENGTH, MASS, STIFFNESS)

__all__ = ["BlockInPipe", "PROBLEMS", "frames", "multiplier_model", "m", "k", "d", "y0", "g",
           "theta", "y", "w"]

m, k, d, y0, g = sp.symbols("m k d y0 g", positive=True)
theta, y = coordinate("theta"), coordinate("y")
w = coordinate("w")


def frames() -> SimpleNamespace:
    """Frames ``O``, ``P``; points ``o`` (pivot), ``b`` (block); the block and the pipe."""
    O = Frame.ground("O")
    P = O.child("P", rot_z(theta))
    o = Point.origin(O, "O")
    b = o.locate("block", -y * P.y)
    block = Particle("block", m, b)
    pipe = RigidBody("pipe", sp.Integer(0), o, P, sp.zeros(3, 3))
    return SimpleNamespace(O=O, P=P, o=o, b=b, block=block, pipe=pipe, e_r=-P.y, e_th=P.x)


def multiplier_model() -> EquationSet:
    """The block off the pipe's axis by ``w``, held on it by the multiplier ``N`` (module doc).

    In ``(theta, y, w)``; :meth:`BlockInPipe.coordinate_maps` gives the map (``w = 0``).  The
    problem's ``multiplier`` model.
    """
    s, c = sp.sin(theta), sp.cos(theta)
    e_r, e_th = sp.Matrix([s, -c]), sp.Matrix([c, s])
    r = y * e_r + w * e_th
    lg = Lagrangian("multiplier", coordinates=[theta, y, w],
                    description="block freed from the pipe's axis, held by N")
    lg.kinetic("T of block", m * (rate(r).T * rate(r))[0, 0] / 2)
    lg.potential("gravity", m * g * r[1])
    lg.spring("spring", k, y - y0)
    damper = -d * rate(y) * e_r  # on the block; its other end is at the fixed pivot
    lg.generalized_force("damper", [damper.dot(r.diff(q)) for q in (theta, y, w)])
    lg.constraint("N", w)
    return lg.equations()


class BlockInPipe(Problem):
    """Block sliding in a massless pivoting pipe with spring and damper (see module doc)."""

    name = "block_in_pipe"
    title = "Block in a pivoting pipe with spring and damper"
    source = "003_d6818267b4d96a20.txt: lecture 18, Block in a pipe I/II (Oppgave 3)"
    summary = ("Polar coordinates of a block in a massless swinging pipe; the pipe's normal "
               "force vanishes identically, from the free-body diagrams and from a multiplier.")
    parameters = (
        Parameter(m, MASS, 0.5, (0.05, 5.0), "mass of the block"),
        Parameter(k, STIFFNESS, 40.0, (1.0, 500.0), "spring constant"),
        Parameter(d, DAMPING, 0.8, (0.01, 10.0), "damper constant"),
        Parameter(y0, LENGTH, 0.6, (0.1, 2.0), "free length of the spring"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-2.5, 2.5), (-4.0, 4.0), "pipe angle from the downward vertical"),
        Coordinate(y, LENGTH, (0.1, 2.5), (-3.0, 3.0), "distance of the block from O"),
    )
    extra_coordinates = (
        Coordinate(w, LENGTH, (-0.3, 0.3), (-3.0, 3.0), "offset of the block off the pipe's "
                   "axis, along e_th (0: held by N)"),
    )
    reactions = (Reaction("N", FORCE, "pipe on the block, along e_th = P.x"),)
    singular = (y,)
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, y: y, w: 0}}

    def newton_euler(self) -> EquationSet:
        """Block along ``e_r`` and ``e_th``; the massless pipe's moments about O."""
        f = frames()
        ne = NewtonEuler("newton_euler", coordinates=[theta, y], ground=f.O,
                         description="block: sum F = m a; pipe: sum of moments about O = 0")
        ne.gravity(-g * f.O.y, bodies=[f.block])
        ne.linear_spring("spring", f.block, k, y - y0, f.e_r, against=f.pipe, against_at=f.o)
        ne.linear_damper("damper", f.block, d, rate(y), f.e_r, against=f.pipe, against_at=f.o)
        ne.reaction("N", f.block, f.e_th, against=f.pipe, against_at=f.b)
        ne.linear_momentum(f.block, f.e_r)
        ne.linear_momentum(f.block, f.e_th)
        ne.angular_momentum(f.pipe, f.O.z, about=f.o)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """The source's Lagrangian and the damper's generalised force ``(0, -d y')``."""
        lg = Lagrangian("lagrange", coordinates=[theta, y], description="the source's L, Q")
        lg.kinetic("T of block", m * (rate(y)**2 + y**2 * rate(theta)**2) / 2)
        lg.potential("gravity", -m * g * y * sp.cos(theta))
        lg.spring("spring", k, y - y0)
        lg.generalized_force("damper", [0, -d * rate(y)])
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The block freed from the pipe's axis by ``w``; ``N`` its multiplier (module doc)."""
        return multiplier_model()

    def published(self) -> list[Published]:
        f = frames()
        v = f.b.vel(f.O)
        damper = -d * rate(y) * f.e_r
        Q = tuple(damper.dot(v.diff(rate(q), f.O)) for q in (theta, y))
        L = f.block.kinetic_energy(f.O) - (m * g * f.b.pos_from(f.o).dot(f.O.y)
                                           + k * (y - y0)**2 / 2)
        return [
            Published("generalised forces", "expression", (0, -d * rate(y)), Q,
                      where="Block in a pipe I: theta and -d y' (garbled: 'theta and -d.y'); "
                      "reference: the damper force's virtual power"),
            Published("Lagrangian", "expression",
                      (m * (rate(y)**2 + y**2 * rate(theta)**2) / 2 + m * g * y * sp.cos(theta)
                       - k * (y - y0)**2 / 2,), (L,), where="Block in a pipe II"),
        ]


PROBLEMS = (BlockInPipe,)
