"""Numbers from the canonical equations: generated code, right-hand sides, simulation, reactions.

* :mod:`~dualmech.numeric.codegen` turns expressions into straight-line Python/NumPy code
  (static coefficients hoisted, common subexpressions eliminated), cached on disk across
  processes (:func:`cache_dir`);
* :class:`NumericModel` solves ``A [q''; lambda] = b`` of an
  :class:`~dualmech.model.equations.EquationSet` at one state or many, with a right-hand side
  ``rhs(t, y)`` for :func:`scipy.integrate.solve_ivp` (also vectorised); a singular mass
  matrix stops the work with :class:`SingularityError` naming the state, never a silent
  wrong number;
* :class:`StateFunction` evaluates any expressions of the state (energies, constraints);
* :func:`simulate` integrates a problem's reference model and recovers the direct models'
  reactions along the trajectory.

Example
-------
>>> from dualmech.numeric import simulate
>>> from dualmech.problems import get
>>> traj = simulate(get("toy_car"), t_span=(0, 2))
>>> traj.reactions["F_r"].shape
(200,)
"""
from dualmech._lazy import exports

_HOME = {
    "_cache": ("cache_dir",),
    "model": ("NumericModel", "SingularityError", "StateFunction"),
    "simulation": ("Trajectory", "check_t_span", "default_initial_state", "problem_parameters",
                 "reactions_along", "reactions_at", "right_hand_side", "simulate"),
}

__all__ = ["NumericModel", "SingularityError", "StateFunction", "Trajectory", "cache_dir",
           "check_t_span", "default_initial_state", "problem_parameters", "reactions_along",
           "reactions_at", "right_hand_side", "simulate"]

__getattr__, __dir__ = exports(__name__, _HOME, globals())   # imported when first used
