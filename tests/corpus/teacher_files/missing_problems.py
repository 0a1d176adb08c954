"""A course file that imports its problem from pendulum_parts.py and does not list it: no
problem class of its own and no PROBLEMS."""
from pendulum_parts import Pendulum  # <- error

COURSE = "Dynamics 101"
