"""The teacher files of teacher_files/ are broken on purpose: never collected or imported by
pytest (``--doctest-modules`` would import them); tests/test_cli_teacher_errors.py runs the
``dualmech`` command on each."""
collect_ignore_glob = ["teacher_files/*.py"]
