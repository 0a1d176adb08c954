"""``dualmech mutate``: every mutant of a problem's models judged, survivors explained, the
exit status 1 when one survives.

The figures asserted are the comparator's own (``dualmech.verify.mutation``): a catalogue problem
catches every judged mutant (the mutation tests require it), and the skeleton that
``dualmech new`` writes derives its string tension ``T`` in one model only: flipping ``T`` --
or doubling the mass in the direct form, which only changes ``T`` -- is caught by the Kane
referee, which derives ``T`` again from the direct form's unbroken declarations, as ``check``
cross-checks it.
"""
from __future__ import annotations

import json

from dualmech.cli.main import main


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_a_catalogue_problem_catches_every_mutant(capsys):
    status, out, _ = run(capsys, "mutate", "simple_pendulum", "--json")
    data = json.loads(out)
    assert status == 0
    assert data["problem"] == "simple_pendulum" and data["survived"] == []
    assert data["judged"] == data["caught"] == len(data["killed"]) > 20
    assert data["kill_rate"] == 1.0
    # each kill names the broken derivation (or the reaction it changes)
    assert all(k["named"] and k["mutant"].split(":")[0] in k["named"][0] or
               k["named"][0].startswith("reaction ") for k in data["killed"])


def test_a_reaction_derived_once_is_cross_checked_by_the_referee(capsys, tmp_path):
    assert main(["new", "my_pend", "--out", str(tmp_path)]) == 0
    capsys.readouterr()
    status, out, _ = run(capsys, "mutate", str(tmp_path / "my_pend.py"), "--json")
    data = json.loads(out)
    assert status == 0 and data["survived"] == [] and data["uncatchable"] == []
    killed = {k["mutant"]: k["named"] for k in data["killed"]}
    assert "reaction T" in killed["newton_euler: flip the sign of unknown `T`"]
    assert "reaction T" in killed["newton_euler: double `m`"]


def test_several_problems_end_with_a_table(capsys):
    status, out, err = run(capsys, "mutate", "simple_pendulum", "spring_mass_damper")
    assert status == 0
    assert "mutants caught over 2 problems" in out
    lines = [ln for ln in out.splitlines() if ln.startswith(("simple_pendulum ",
                                                              "spring_mass_damper "))]
    assert len(lines) == 2 and all(" 0 " in ln for ln in lines)   # nothing survived


def test_usage_errors_say_what_to_do(capsys):
    status, _, err = run(capsys, "mutate")
    assert status == 2 and "name at least one problem, or use --all" in err
    status, _, err = run(capsys, "mutate", "toy_carr")
    assert status == 2 and "Did you mean 'toy_car'?" in err
    status, _, err = run(capsys, "mutate", "simple_pendulum", "--all")
    assert status == 2 and "not both" in err


def test_derivations_that_already_disagree_are_not_scored(capsys, tmp_path):
    # with the potential's sign flipped, flipping gravity in the direct form would make the
    # two wrong models agree: that mutant would pass for a gap in the checks
    assert main(["new", "my_pend", "--out", str(tmp_path)]) == 0
    capsys.readouterr()
    path = tmp_path / "my_pend.py"
    text = path.read_text()
    wrong = text.replace('lg.potential("gravity", -m * g * l * sp.cos(theta))',
                         'lg.potential("gravity", m * g * l * sp.cos(theta))')
    assert wrong != text
    path.write_text(wrong)
    status, out, _ = run(capsys, "mutate", str(path))
    assert status == 1 and "SURVIVED" not in out
    assert "derivations disagree before any mutant is made" in out
    assert f"dualmech check my_pend" in out
