"""The referee (Kane's method with auxiliary speeds, from a direct model's declarations).

(a) On the catalogue it agrees with every direct model it can be derived from, motion and
reactions; (b) on a teacher's problem outside the catalogue (tests/_atwood_source.py, written
to a temporary folder) injected mistakes get the right verdict, name and exit code; (c) its
reactions equal sympy's KanesMethod (simple pendulum) and a hand derivation (Atwood machine).
"""
from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp

from dualmech import rate
from dualmech.cli.main import main
from dualmech.model.direct import declarations_of
from dualmech.model.equations import ModelError
from dualmech.model.kane import kane_equations
from dualmech.problems import all_problems, get
from dualmech.verify.check import claims_of
from dualmech.verify.referee import INDEPENDENCE, referees
from dualmech.verify.sampling import Context
from dualmech.verify.verdicts import judge

from _catalogue_expected import SLOW, catalogue_params

#: problems with a direct model (a slow one is not derived to find out: it has one)
DIRECT = sorted(p.name for p in all_problems() if p.name in SLOW
                or any(declarations_of(m) is not None for m in p.models().values()))

#: direct models that get no referee, and why (asserted, so a change is noticed)
NO_REFEREE = {"copying_machine": "moves no declared body",       # small-rotation bar in O
              "mobile_robot_simplified": "lumps the arm"}         # referee = False
#: reactions a referee leaves open: statically indeterminate without the closure equation
OPEN = {("wheel_on_pivot", "referee"): {"F_x", "F_z", "R_x", "R_z"},
        ("wheel_on_pivot", "referee (angular_momentum)"): {"F_x", "F_z"}}


@pytest.mark.parametrize("name", catalogue_params(DIRECT))
def test_referee_agrees_with_every_direct_model(name):
    p = get(name)
    refs = referees(p)
    if name in NO_REFEREE:
        assert not refs.models and NO_REFEREE[name] in " ".join(refs.notes)
        return
    assert refs.models, refs.notes
    ctx = Context(p.model(p.reference).coordinates, p.parameter_symbols, p)
    claims = claims_of(p)
    for rname, kane in refs.models.items():
        direct = refs.of[rname]
        models = {direct: p.in_reference_coordinates(p.model(direct)), rname: kane}
        cl = {n: claims[direct] for n in models if direct in claims}
        j = judge(models, context=ctx, claims=cl, referees={rname: direct})
        assert j.equivalent, j.summary()
        assert not j.withdrawn
        assert j.undetermined.get(rname, set()) == OPEN.get((name, rname), set())
        # every reaction the referee determines was compared (same values at every point)
        assert {str(u) for u in kane.unknowns} == {str(u) for u in models[direct].unknowns}


def _teacher(tmp_path: Path, mistake: str) -> str:
    text = (Path(__file__).parent / "_atwood_source.py").read_text()
    path = tmp_path / "atwood.py"
    path.write_text(text.replace('MISTAKE = ""', f"MISTAKE = {mistake!r}"))
    return str(path)


def _check(capsys, tmp_path, mistake):
    status = main(["check", _teacher(tmp_path, mistake)])
    return status, _unwrapped(capsys.readouterr().out)


def _unwrapped(out: str) -> str:
    """The report with each line's continuation lines (wrapped to 100 columns, indented 4
    deeper) joined back to it."""
    lines: list = []
    for x in out.splitlines():
        deep = len(x) - len(x.lstrip(" "))
        if lines and x.strip() and deep >= len(lines[-1]) - len(lines[-1].lstrip(" ")) + 4:
            lines[-1] += " " + x.strip()
        else:
            lines.append(x)
    return "\n".join(lines)


def test_teacher_problem_without_mistake_cross_checks_every_reaction(capsys, tmp_path):
    status, out = _check(capsys, tmp_path, "")
    assert status == 0
    assert INDEPENDENCE in out
    for r in ("T₁", "T₂", "R ="):
        line = next(x for x in out.splitlines() if x.strip().startswith(r))
        assert "(cross-checked: newton_euler, referee agree)" in line


def test_wrong_load_sign_in_lagrange_names_lagrange(capsys, tmp_path):
    status, out = _check(capsys, tmp_path, "load sign")
    assert status == 1
    assert "`lagrange` disagrees with `newton_euler` and `referee`" in out


def test_dropped_term_in_direct_projection_names_the_direct_model(capsys, tmp_path):
    status, out = _check(capsys, tmp_path, "dropped term")
    assert status == 1
    assert "`newton_euler` disagrees with `lagrange` and `referee`" in out
    assert "do not follow from its own declarations" in out


def test_doubled_mass_in_shared_declaration_is_not_blamed_on_lagrange_alone(capsys, tmp_path):
    status, out = _check(capsys, tmp_path, "doubled mass")
    assert status == 1
    assert "may lie in a shared declaration of `newton_euler`" in out


def test_non_unit_reaction_direction_is_refused(capsys, tmp_path):
    status = main(["check", _teacher(tmp_path, "non-unit direction")])
    err = " ".join(capsys.readouterr().err.split())   # wrapped to 100 columns: as words
    assert status == 2      # a model that cannot be built (dualmech.cli.errors), on stderr
    assert "the direction of reaction `T1` is not a unit vector (its squared length is 4)" in err


def test_dropped_pulley_weight_only_in_a_reaction_is_caught(capsys, tmp_path):
    status, out = _check(capsys, tmp_path, "dropped pulley weight")
    assert status == 1
    assert "reactions T1, T2, R of referee vs newton_euler: DIFFERENT" in out
    assert "`newton_euler`: its balances and projections do not follow" in out
    assert "reaction R differs" in out


def test_json_lists_the_referee(capsys, tmp_path):
    import json
    main(["check", _teacher(tmp_path, ""), "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert doc["referees"]["referee"]["of"] == "newton_euler"
    assert doc["reaction_derivations"]["R"] == ["newton_euler"]
    assert doc["referee_derivations"]["R"] == ["referee"]
    assert doc["reactions_not_cross_checked"] == []


def test_referee_tension_equals_sympy_kanes_method():
    """Simple pendulum: sympy's KanesMethod with an auxiliary speed along the string."""
    me = pytest.importorskip("sympy.physics.mechanics")
    from problems.simple_pendulum import M, a, g, theta
    q, u, ua = me.dynamicsymbols("q u ua")
    T = sp.Symbol("T", real=True)
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q, N.z])
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", -a * A.y)
    P.set_vel(N, a * u * A.x + ua * A.y)
    km = me.KanesMethod(N, q_ind=[q], u_ind=[u], kd_eqs=[q.diff() - u], u_auxiliary=[ua])
    fr, frstar = km.kanes_equations([me.Particle("bob", P, M)],
                                    [(P, -M * g * N.y + T * A.y)])
    udot = sp.solve((fr + frstar)[0], u.diff())[0]
    aux = km.auxiliary_eqs[0].subs(u.diff(), udot)
    theirs = sp.solve(aux, T)[0].subs({q: theta, u: theta.diff()})
    p = get("simple_pendulum")
    ours = kane_equations(declarations_of(p.model("newton_euler"))).reactions_solved()
    assert sp.simplify(ours[T] - theirs) == 0


def test_referee_reactions_equal_the_hand_derivation_of_the_atwood_machine(tmp_path):
    """Atwood machine with a massive pulley: T1, T2, R by hand (tests/_atwood_source.py)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("atwood_ok", _teacher(tmp_path, ""))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    m1, m2, mp, g, x = mod.m1, mod.m2, mod.mp, mod.g, mod.x
    kane = kane_equations(declarations_of(mod.Atwood().model("newton_euler")))
    sol = kane.solve()
    xdd = (m1 - m2) * g / (m1 + m2 + mp / 2)
    T1, T2 = m1 * (g - xdd), m2 * (g + xdd)
    hand = {"T1": T1, "T2": T2, "R": T1 + T2 + mp * g}
    assert sp.simplify(sol[rate(x, 2)] - xdd) == 0
    for u in kane.unknowns:
        assert sp.simplify(sol[u] - hand[str(u)]) == 0, u


def test_a_coordinate_the_declarations_do_not_move_is_refused():
    p = get("copying_machine")
    with pytest.raises(ModelError, match="moves no declared body"):
        kane_equations(declarations_of(p.model("newton_euler")))


def test_a_reaction_outvoted_only_by_a_model_and_its_referee_leaves_no_majority():
    """The teacher's rolling disk with Lagrange's multiplier taken with the opposite sign
    (tests/corpus/teacher_mistakes/rolling_down_incline_mistakes.py): the motion agrees, the
    friction F differs, and `newton_euler` is backed only by its own referee -- so no side is
    a majority, and the verdict never sets a model against itself."""
    from dualmech import problems
    from dualmech.verify.check import compare
    path = (Path(__file__).resolve().parent / "corpus" / "teacher_mistakes"
            / "rolling_down_incline_mistakes.py")
    c = compare(problems.load(f"{path}:MultiplierSignReversed"))
    j = c.judgement
    assert not j.equivalent and not j.faults and [r.name for r in j.reaction_faults] == ["F"]
    assert j.majority == () and set(j.odd) >= {"newton_euler", "lagrange"}
    summary = j.summary()
    assert "disagree with" not in summary and "share declarations" in summary, summary
