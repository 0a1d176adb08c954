"""The Kane referee on rolling: the disk's and the bicycle's declared rolling let it derive
every reaction a second time, so a sign slip in a direct form's balances is caught.

The mutants below keep the direct model's declarations (bodies, loads, the reactions with
their declared directions, the rolling constraints) and change its balances only: one
reaction enters every row with the opposite sign, as when a projection is written by hand
with the direction reversed.  Such a model is the original with the unknown renamed, so its
motion is unchanged; only the reaction differs (mutation testing, ``dualmech.verify.mutation``,
says the same).  With the rolling written as rows of the model (the catalogue before issue
26) the bicycle's joint reactions had one derivation only and ``check`` said "not
cross-checked" and exited 0; with the rolling declared the referee derives them from the
declarations and ``check`` exits 1, naming the reaction.
"""
from __future__ import annotations

import re
import textwrap

import pytest

from dualmech.cli.main import main

MUTANT = '''
from dualmech.model.declared import builder_of, note
from dualmech.problems.{module} import {cls}


class Flipped({cls}):
    """The catalogue's problem with `{reaction}` entering the direct form's balances with
    the sign opposite to its declared direction."""

    name = "{module}_flipped"

    def newton_euler(self):
        eqs = super().newton_euler()
        u = next(u for u in eqs.unknowns if u.name == "{reaction}")
        out = eqs.substitute({{u: -u}})
        note(builder_of(eqs), out)       # the declarations stay the builder's own
        return out


PROBLEMS = (Flipped,)
'''


def _mutant(tmp_path, module: str, cls: str, reaction: str) -> str:
    path = tmp_path / f"{module}_flipped.py"
    path.write_text(textwrap.dedent(MUTANT.format(module=module, cls=cls, reaction=reaction)))
    return str(path)


def _unwrapped(out: str) -> str:
    """The report with its wrapped continuation lines joined back."""
    return re.sub(r"\n {4,}(?=\S)", " ", out)


def test_check_of_the_disk_cross_checks_every_contact_force_with_the_referee(capsys):
    status = main(["check", "rolling_disk"])
    out = _unwrapped(capsys.readouterr().out)
    assert status == 0
    assert "reactions F_x, F_y, F_z of referee vs newton_euler: the same" in out
    assert "no referee" not in out and "not cross-checked" not in out


def test_a_flipped_contact_force_of_the_disk_is_blamed_by_the_referee(capsys, tmp_path):
    """``F_x`` with the wrong sign in every balance of the direct form: the motion is the
    same, the referee (and the Lagrange model's multiplier) give ``F_x`` with the declared
    sign, so ``check`` exits 1 naming the reaction."""
    status = main(["check", _mutant(tmp_path, "rolling_disk", "RollingDisk", "F_x")])
    out = _unwrapped(capsys.readouterr().out)
    assert status == 1
    assert "newton_euler vs lagrange: equivalent" in out      # the motion is unchanged
    assert "referee vs lagrange: equivalent" in out
    assert re.search(r"reactions [^:]*F_x[^:]* of referee vs newton_euler: DIFFERENT", out), out


@pytest.mark.slow
def test_a_flipped_hub_reaction_of_the_bicycle_is_blamed_by_the_referee(capsys, tmp_path):
    """The rear hub's force along ``B.x`` (``R_R_x``, carried by the direct form alone) with
    the wrong sign in every balance: before the rolling was declared, ``check`` said "not
    cross-checked" and exited 0; now the referee derives ``R_R_x`` and ``check`` exits 1."""
    status = main(["check", _mutant(tmp_path, "whipple_bicycle", "WhippleBicycle", "R_R_x")])
    out = _unwrapped(capsys.readouterr().out)
    assert status == 1
    assert "newton_euler vs lagrange: equivalent" in out
    assert "not cross-checked" not in out
    assert re.search(r"reactions [^:]*R_R_x[^:]* of referee vs newton_euler: DIFFERENT", out), \
        out
