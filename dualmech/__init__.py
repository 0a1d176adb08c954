"""dualmech: every mechanics problem written twice -- Newton--Euler and Lagrange -- and proved equal.

The public API is this one list; every name is a function or a class (no module), so a problem
file needs one import line::

    from dualmech import (Frame, Lagrangian, NewtonEuler, Particle, Point, Problem, Parameter,
                          Coordinate, Reaction, Published, EquationSet, coordinate, rate, rot_z,
                          t, MASS, LENGTH, ACCELERATION, ANGLE, FORCE)

Names are imported when first used, so ``import dualmech`` is quick and the ``dualmech``
command never loads sympy for work that does not need it (``dualmech list`` reads
declarations only).  The stages behind it, arrows pointing one way: ``cli`` -> ``web``,
``grade``, ``report`` -> ``numeric`` -> ``verify`` -> ``exact`` -> ``model``.

Example
-------
>>> from dualmech import compare, get
>>> result = compare(get("simple_pendulum"))
>>> result.equivalent, result.method
(True, 'exact rational-point test')
"""
from dualmech._lazy import exports

_HOME = {
    # building a model: frames, points, bodies, the two forms, the equations they end in
    "model.kinematics": ("t", "coordinate", "rate", "Frame", "Point", "Vector", "RelativeMotion",
                         "rot_x", "rot_y", "rot_z", "rot_axis", "skew"),
    "model.bodies": ("Particle", "RigidBody", "MassProperties", "composite", "parallel_axis",
                     "point_mass", "thin_rod", "thin_disk", "solid_cylinder", "solid_sphere",
                     "cuboid"),
    "model.direct": ("NewtonEuler",),
    "model.lagrange": ("Lagrangian",),
    "model.equations": ("EquationSet", "ModelError"),
    "model.stability": ("linearize_about",),
    # declaring a problem: its parameters, coordinates, reactions and printed answers, and
    # the facts its equations do not carry (probe runs, a stiff scene, a fidelity ladder)
    "model.problem": ("Problem", "Parameter", "Coordinate", "Reaction", "Published",
                      "ProblemError"),
    "model.facts": ("Probe", "StiffScene", "FidelityRung", "SteadyMotion"),
    "model.inputs": ("Input",),
    "model.phases": ("Phase",),
    "model.drawing": ("Drawing", "ChartScene"),
    "model.dimensions": ("Dimension", "DIMENSIONLESS", "MASS", "LENGTH", "TIME", "ANGLE",
                         "FORCE", "TORQUE", "ENERGY", "VELOCITY", "ACCELERATION", "STIFFNESS",
                         "DAMPING", "TORSIONAL_STIFFNESS", "TORSIONAL_DAMPING", "INERTIA",
                         "FREQUENCY"),
    # finding problems: a catalogue name, a file, module:Class or a course package's entry
    "problems": ("get", "load"),
    # checking: the verdict, the reactions, a model made in sympy.physics.mechanics
    "verify.check": ("compare", "compare_models", "recover_reactions", "Comparison"),
    "verify.interop": ("check_mechanics", "from_mechanics"),
    "verify.mutation": ("mutation_report",),
    # numbers, grading, reports
    "numeric.simulation": ("simulate", "Trajectory"),
    "grade.api": ("grade", "Grader"),
    "report": ("write_report",),
    "report.animation": ("animate", "Animation"),
}

__all__ = [name for names in _HOME.values() for name in names]
__version__ = "0.2.0"

__getattr__, __dir__ = exports(__name__, _HOME, globals())
