"""A teacher's own triple pendulum (three beads on light rods), written as a course would:
the tensions couple six unknowns, past the display budget, so ``show`` gives their values at
a state (tests/test_reactions_at_state.py)."""
import sympy as sp
from dualmech import (Frame, Lagrangian, NewtonEuler, Particle, Point, Problem, Parameter,
                      Coordinate, Reaction, coordinate, rate, rot_z, MASS, LENGTH,
                      ACCELERATION, ANGLE, FORCE)

m1, m2, m3, l1, l2, l3, g = sp.symbols("m1 m2 m3 l1 l2 l3 g", positive=True)
a, b, c = (coordinate(n) for n in ("a", "b", "c"))
O = Frame.ground("O")
rods = [O.child(f"rod{i}", rot_z(q)) for i, q in enumerate((a, b, c), 1)]
P1 = Point.origin(O).locate("P1", -l1 * rods[0].y)
P2 = P1.locate("P2", -l2 * rods[1].y)
P3 = P2.locate("P3", -l3 * rods[2].y)
beads = [Particle("bead1", m1, P1), Particle("bead2", m2, P2), Particle("bead3", m3, P3)]


class TriplePendulum(Problem):
    name, title, source = "my_triple_pendulum", "Three beads on light rods", "my notes: ex. 7"
    parameters = (Parameter(m1, MASS, 2, (0.1, 10)), Parameter(m2, MASS, 1, (0.1, 10)),
                  Parameter(m3, MASS, 0.5, (0.1, 10)), Parameter(l1, LENGTH, 1, (0.1, 2)),
                  Parameter(l2, LENGTH, 0.8, (0.1, 2)), Parameter(l3, LENGTH, 0.6, (0.1, 2)),
                  Parameter(g, ACCELERATION, 9.81, (1, 20)))
    coordinates = (Coordinate(a, ANGLE, (-1, 1)), Coordinate(b, ANGLE, (-1, 1)),
                   Coordinate(c, ANGLE, (-1, 1)))
    reactions = tuple(Reaction(f"T{i}", FORCE, f"rod {i} on bead {i}, towards the joint above")
                      for i in (1, 2, 3))

    def newton_euler(self):
        ne = NewtonEuler(coordinates=[a, b, c], ground=O)
        ne.gravity(-g * O.y)
        for i, (bead, rod) in enumerate(zip(beads, rods)):
            ne.reaction(f"T{i + 1}", bead, rod.y, against=beads[i - 1] if i else None)
        for bead in beads:
            ne.linear_momentum(bead, O.x)
            ne.linear_momentum(bead, O.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[a, b, c])
        vx = vy = height = 0
        for i, (q, mass, length) in enumerate(zip((a, b, c), (m1, m2, m3), (l1, l2, l3))):
            vx += length * rate(q) * sp.cos(q)
            vy += length * rate(q) * sp.sin(q)
            height -= length * sp.cos(q)
            lg.kinetic(f"T of bead {i + 1}", mass * (vx**2 + vy**2) / 2)
            lg.potential(f"gravity on bead {i + 1}", mass * g * height)
        return lg.equations()


PROBLEMS = (TriplePendulum,)
