"""The catalogue's doctests run (problems/ is in testpaths) without a second copy of it.

conftest.py at the repository root imports each catalogue module as
``dualmech.problems.<module>`` for its doctests; a plain collection would import them again as
``problems.<module>``, so that name must never appear in the process that collected them.
"""
import sys


def test_catalogue_is_imported_once_under_its_real_name():
    assert "dualmech.problems" in sys.modules
    doubles = [n for n in sys.modules if n == "problems" or n.startswith("problems.")]
    assert doubles == []
