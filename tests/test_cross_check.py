"""A reaction that one derivation alone gives is marked "not cross-checked" everywhere it is
shown: the check's text, its JSON, the CLI summary and the report's summary table.

block_in_pipe keeps its second derivation of N out of the catalogue on purpose (N vanishes
identically; problems/block_in_pipe.py says why), so N is the example of a lonely reaction."""
import pytest

from dualmech.cli import main
from dualmech.compare import compare
from dualmech.problems import get
from dualmech.report.pages import summary_rows


@pytest.fixture(scope="module")
def lonely():
    return compare(get("block_in_pipe"))


def test_lonely_reaction_is_named_in_text_and_json(lonely):
    assert lonely.reaction_derivations == {"N": ["newton_euler"]}
    assert lonely.not_cross_checked == ["N"]
    text = str(lonely)
    assert "not cross-checked (one derivation only): N (newton_euler)" in text
    d = lonely.to_dict()
    assert d["reactions_not_cross_checked"] == ["N"]
    assert d["reaction_derivations"] == {"N": ["newton_euler"]}


def test_summaries_count_them(lonely, capsys):
    main(["check", "block_in_pipe", "simple_pendulum"])
    table = capsys.readouterr().out.split("problem ", 1)[1]
    assert "1 (1 not cross-checked)" in table
    assert "1 reaction(s) not cross-checked" in table
    (row,) = summary_rows([lonely])
    assert "1 (1 not cross-checked)" in row


def test_a_reaction_derived_twice_is_not_flagged():
    c = compare(get("restrained_pendulum"))
    assert c.reaction_derivations == {"H": ["newton_euler", "multiplier"],
                                      "V": ["newton_euler", "multiplier"]}
    assert c.not_cross_checked == [] and "NOT CROSS-CHECKED" not in str(c)
    assert c.reaction_count_text() == "2"
