"""``python -m dualmech``: the same as the ``dualmech`` command (see :mod:`dualmech.cli`)."""
from dualmech.cli import command

if __name__ == "__main__":
    raise SystemExit(command())
