"""``python -m dualmech``: the same as the ``dualmech`` command (see :mod:`dualmech.cli.main`)."""
from dualmech.cli.main import command

if __name__ == "__main__":
    raise SystemExit(command())
