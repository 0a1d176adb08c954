"""A reaction that one derivation alone gives is marked "not cross-checked" everywhere it is
shown: the check's text, its JSON, the CLI summary and the report's summary table.

Every reaction of the catalogue is derived twice, so the lonely reactions here are made on
purpose: the restrained pendulum with its multiplier model left out and no referee, so that
its pivot forces ``H`` and ``V`` rest on the free-body diagram alone."""
import pytest

from dualmech.cli.main import main
from dualmech.verify.check import compare
from dualmech.problems import get, load
from dualmech.report.pages import summary_rows

ONE_DIAGRAM = '''
from dualmech.problems.restrained_pendulum import RestrainedPendulum


class OneDiagram(RestrainedPendulum):
    """The restrained pendulum without its multiplier model: H, V from one diagram."""

    name = "restrained_pendulum_one_diagram"
    extra_models = ()
    extra_coordinates = ()
    referee = False   # else dualmech's own referee cross-checks H and V
'''


@pytest.fixture(scope="module")
def spec(tmp_path_factory):
    path = tmp_path_factory.mktemp("lonely") / "one_diagram.py"
    path.write_text(ONE_DIAGRAM)
    return f"{path}:OneDiagram"


@pytest.fixture(scope="module")
def lonely(spec):
    return compare(load(spec))


def test_lonely_reaction_is_named_in_text_and_json(lonely):
    assert lonely.equivalent, str(lonely)
    assert lonely.reaction_derivations == {"H": ["newton_euler"], "V": ["newton_euler"]}
    assert lonely.not_cross_checked == ["H", "V"]
    text = str(lonely)
    assert "not cross-checked (one derivation only): H (newton_euler), V (newton_euler)" in text
    assert text.count("(NOT CROSS-CHECKED)") == 2
    d = lonely.to_dict()
    assert d["reactions_not_cross_checked"] == ["H", "V"]
    assert d["reaction_derivations"] == {"H": ["newton_euler"], "V": ["newton_euler"]}


def test_summaries_count_them(spec, lonely, capsys):
    main(["check", spec, "simple_pendulum"])
    table = capsys.readouterr().out.split("problem ", 1)[1]
    assert "2 (2 not cross-checked)" in table
    assert "2 reaction(s) not cross-checked" in table
    (row,) = summary_rows([lonely])
    assert "2 (2 not cross-checked)" in row


def test_a_reaction_derived_twice_is_not_flagged():
    c = compare(get("restrained_pendulum"))
    assert c.reaction_derivations == {"H": ["newton_euler", "multiplier"],
                                      "V": ["newton_euler", "multiplier"]}
    assert c.referee_derivations == {"H": ["referee"], "V": ["referee"]}
    assert c.not_cross_checked == [] and "NOT CROSS-CHECKED" not in str(c)
    assert c.reaction_count_text() == "2"

