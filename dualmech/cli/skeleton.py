'''A new problem's skeleton: ``dualmech new NAME`` writes ``NAME.py`` and ``test_NAME.py``.

The skeleton is a working problem -- a pendulum of length ``l`` with the tension of its rod,
written by Newton-Euler and by Lagrange -- so ``dualmech check NAME.py`` passes as written;
its ``TODO`` comments say what to replace with the teacher's own system.

Example
-------
>>> import tempfile, pathlib
>>> out = pathlib.Path(tempfile.mkdtemp())
>>> [p.name for p in write_skeleton("driven_pendulum", out)]
['driven_pendulum.py', 'test_driven_pendulum.py']
'''
from __future__ import annotations

import keyword
import re
from pathlib import Path

__all__ = ["write_skeleton", "class_name", "SkeletonError"]


class SkeletonError(ValueError):
    """A name that cannot be a problem's, or a file that already exists."""


_PROBLEM = '''r"""{title} -- TODO: one line saying what the system is and where it comes from.

Sign sketch (TODO: draw yours; say which way each coordinate and force is positive)::

              O  pivot
              |\\                j (up), i (right), k = i x j out of the page
              | \\               gravity -g j
              |  \\  l           arm frame: arm.y points from the bob to the pivot,
              |th \\                        arm.x = e_theta (direction of increasing theta)
                   o  bob m      r_bob = -l arm.y = l (sin th, -cos th)

``theta`` from the downward vertical, counterclockwise about ``k``.

Newton-Euler on the bob (``a_bob = l theta'' arm.x + l theta'^2 arm.y``)::

        arm.x:  m l theta''  = -m g sin theta
        arm.y:  m l theta'^2 = T - m g cos theta

Lagrange: ``T = m (l theta')^2 / 2``, ``V = -m g l cos theta``.

Check it with ``dualmech check {filename}``; see it with ``dualmech show {filename}``.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Reaction, coordinate, rate, rot_z, ACCELERATION, ANGLE,
                      FORCE, LENGTH, MASS)

__all__ = ["{cls}", "PROBLEMS"]

# TODO: your parameters (with their assumptions) and coordinates (functions of time)
m, l, g = sp.symbols("m l g", positive=True)
theta = coordinate("theta")


class {cls}(Problem):
    """TODO: one sentence; the sign sketch is in the module docstring."""

    name = "{name}"
    title = "{title}"
    source = "TODO: your course notes, section or problem number"
    # TODO: every parameter: symbol, dimension, default value, admissible range, meaning
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 10.0), "mass of the bob"),
        Parameter(l, LENGTH, 0.5, (0.1, 3.0), "length of the rod"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    # TODO: every coordinate: function, dimension, range of q, range of q'
    coordinates = (
        Coordinate(theta, ANGLE, (-2.5, 2.5), (-4.0, 4.0), "angle from the downward vertical"),
    )
    # TODO: the reactions the Newton-Euler model solves for (or none)
    reactions = (Reaction("T", FORCE, "rod on bob, along arm.y (towards the pivot)"),)

    def newton_euler(self) -> EquationSet:
        """TODO: frames, points, bodies; then the momentum balances with every force."""
        O = Frame.ground("O")
        arm = O.child("arm", rot_z(theta))
        bob = Particle("bob", m, Point.origin(O, "pivot").locate("bob", -l * arm.y))
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=O,
                         description="sum F = m a on the bob, along e_theta and the rod")
        ne.gravity(-g * O.y)
        ne.reaction("T", bob, arm.y)
        ne.linear_momentum(bob, arm.x)
        ne.linear_momentum(bob, arm.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """TODO: the kinetic and potential energies, written independently of newton_euler."""
        lg = Lagrangian("lagrange", coordinates=[theta], description="T and V by hand")
        lg.kinetic("T of bob", m * (l * rate(theta))**2 / 2)
        lg.potential("gravity", -m * g * l * sp.cos(theta))
        return lg.equations()


PROBLEMS = ({cls},)
'''

_TEST = '''"""{name}: both derivations agree exactly, and the tension is the hand result."""
from pathlib import Path

import sympy as sp

from dualmech import compare, load, rate

PROBLEM = load(str(Path(__file__).with_name("{name}.py")))


def test_the_derivations_agree():
    result = compare(PROBLEM)
    assert result.equivalent, str(result)


def test_the_tension_is_the_hand_result():
    # TODO: your reaction, solved by hand from the free-body diagram
    from importlib import import_module
    mod = import_module(type(PROBLEM).__module__)
    theta, m, l, g = mod.theta, mod.m, mod.l, mod.g
    hand = m * (g * sp.cos(theta) + l * rate(theta)**2)
    (tension,) = compare(PROBLEM).reactions.values()
    assert sp.simplify(tension - hand) == 0
'''


def class_name(name: str) -> str:
    """``driven_pendulum`` -> ``DrivenPendulum``."""
    return "".join(part[:1].upper() + part[1:] for part in name.split("_") if part) or "Problem"


def write_skeleton(name: str, out: Path | str = ".", force: bool = False) -> list[Path]:
    """Write ``out/NAME.py`` (the problem) and ``out/test_NAME.py`` (its test); return both paths.

    Raises :class:`SkeletonError` for a name that is not a Python identifier and for files that
    exist already (unless ``force``).
    """
    if not (isinstance(name, str) and re.fullmatch(r"[a-z][a-z0-9_]{0,63}", name)) \
            or keyword.iskeyword(name):
        raise SkeletonError(f"a problem's name is lower-case letters, digits and _, starting "
                            f"with a letter (it names the file and the module), got {name!r:.80}.")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    files = {out / f"{name}.py": _PROBLEM, out / f"test_{name}.py": _TEST}
    existing = [str(p) for p in files if p.exists()]
    if existing and not force:
        raise SkeletonError(f"{', '.join(existing)} already exist(s); choose another name or "
                            "directory, or pass --force to overwrite.")
    title = name.replace("_", " ").capitalize()
    for path, template in files.items():
        path.write_text(template.format(name=name, cls=class_name(name), title=title,
                                        filename=f"{name}.py"), encoding="utf-8")
    return list(files)
