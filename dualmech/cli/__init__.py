"""The ``dualmech`` command: every subcommand, one error and exit-code convention."""
