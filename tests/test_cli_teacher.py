"""A teacher's own problem is first class: every command takes it by file, ``module:Class``
and through a course package's entry point, as it takes a catalogue name.

The teacher's file is written as the README shows one, with the front door's one import
line: a pendulum (mass ``m`` on a rod of length ``l``, angle ``theta`` from the downward
vertical, the rod's pull ``T`` as the reaction).  By hand: ``theta'' = -g sin(theta) / l``
and, from the radial balance, ``T = m (g cos(theta) + l theta'^2)``.  Its inverted twin (the
potential's and gravity's signs flipped) has no stable equilibrium in its declared range,
so a fidelity ladder does not apply to it.
"""
from __future__ import annotations

import json
import sys
import textwrap
from pathlib import Path

import pytest
import sympy as sp

from dualmech import problems
from dualmech.cli.main import main

TEACHER_FILE = textwrap.dedent('''
    """My pendulum, as in my notes."""
    import sympy as sp
    from dualmech import (Frame, Lagrangian, NewtonEuler, Particle, Point, Problem, Parameter,
                          Coordinate, Reaction, coordinate, rot_z, MASS, LENGTH, ACCELERATION,
                          ANGLE, FORCE)

    m, l, g = sp.symbols("m l g", positive=True)
    th = coordinate("theta")
    O = Frame.ground("O")
    arm = O.child("arm", rot_z(th))
    bob = Particle("bob", m, Point.origin(O).locate("P", -l * arm.y))
    SIGN = 1


    class Pendulum(Problem):
        name, title, source = "my_pendulum", "Simple pendulum", "my notes: example 1"
        parameters = (Parameter(m, MASS, 1, (0.1, 10)), Parameter(l, LENGTH, 1, (0.1, 2)),
                      Parameter(g, ACCELERATION, 9.81, (1, 20)))
        coordinates = (Coordinate(th, ANGLE, (-1, 1)),)
        reactions = (Reaction("T", FORCE, "rod on bob, towards the pivot"),)

        def newton_euler(self):
            ne = NewtonEuler(coordinates=[th], ground=O)
            ne.gravity(-SIGN * g * O.y)
            ne.reaction("T", bob, arm.y)
            ne.linear_momentum(bob, arm.x)
            ne.linear_momentum(bob, arm.y)
            return ne.equations()

        def lagrange(self):
            lg = Lagrangian(coordinates=[th])
            lg.kinetic_of(bob, O)
            lg.potential("gravity", -SIGN * m * g * l * sp.cos(th))
            return lg.equations()
''')


def run(capsys, *argv):
    status = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return status, out, err


@pytest.fixture
def teacher(tmp_path):
    path = tmp_path / "my_pendulum.py"
    path.write_text(TEACHER_FILE)
    (tmp_path / "my_inverted.py").write_text(
        TEACHER_FILE.replace("SIGN = 1", "SIGN = -1").replace('"my_pendulum"', '"my_inverted"'))
    return path


def _symbols(path):
    module = sys.modules[type(problems.load(str(path))).__module__]
    return module.m, module.l, module.g, module.th


def test_check_by_file_recovers_the_hand_reaction(capsys, teacher):
    status, out, err = run(capsys, "check", teacher, "--json")
    assert status == 0, err
    d = json.loads(out)
    assert d["name"] == "my_pendulum" and d["equivalent"] is True
    from dualmech import compare, rate
    m, l, g, th = _symbols(teacher)
    c = compare(problems.load(str(teacher)))
    assert sp.simplify(c.reactions["T"] - m * (g * sp.cos(th) + l * rate(th)**2)) == 0
    (acc,) = c.accelerations.values()
    assert sp.simplify(acc + g * sp.sin(th) / l) == 0


def test_show_by_file_and_by_module_colon_class(capsys, teacher, monkeypatch):
    status, out, _ = run(capsys, "show", teacher)
    assert status == 0
    assert out.index("newton_euler") < out.index("lagrange") < out.index("reactions")
    monkeypatch.chdir(teacher.parent)
    status, out, _ = run(capsys, "show", "my_pendulum:Pendulum", "--model", "lagrange")
    assert status == 0 and "lagrange" in out and "newton_euler" not in out


def test_report_of_a_file_reports_that_problem_alone(capsys, teacher, tmp_path):
    out_dir = tmp_path / "report"
    status, out, err = run(capsys, "report", teacher, "--out", out_dir, "--duration", "0.3",
                           "--points", "3", "--json")
    assert status == 0, err
    d = json.loads(out)
    assert [(p["problem"], p["equivalent"]) for p in d["problems"]] == [("my_pendulum", True)]
    assert (out_dir / "report.html").exists() and (out_dir / "my_pendulum.json").exists()
    status, _, err = run(capsys, "report", teacher, "--all", "--out", out_dir)
    assert status == 2 and "not both" in err


def test_every_message_is_wrapped_to_the_terminal(capsys, teacher, monkeypatch):
    # an unknown command lists every command (a 200-column line unwrapped); a bad --at names
    # the coordinates; the declaration error of a problem file lists what to fix
    status, _, err = run(capsys, "chek", teacher)
    assert status == 2 and "invalid choice: 'chek'" in " ".join(err.split())
    assert len(err.splitlines()) > 2 and max(map(len, err.splitlines())) <= 100
    teacher.write_text(teacher.read_text().replace('ne.reaction("T"', 'ne.reaction("Tension"'))
    status, _, err = run(capsys, "check", teacher)
    flat = " ".join(err.split())
    assert status == 2 and "reaction `Tension` is not declared in `reactions`" in flat
    assert max(map(len, err.splitlines())) <= 100
    import dualmech.cli.errors as errors
    monkeypatch.setattr(errors, "columns", lambda stream=None: 60)
    status, _, err = run(capsys, "check", teacher)
    assert status == 2 and " ".join(err.split()) == flat
    # a line longer than 60 is one word (the file's path) or the quoted line of the file
    assert all(len(line) <= 60 or " " not in line.strip() or line.endswith("# <- error")
               for line in err.splitlines())
    assert "    reactions = (" in err and len(err.splitlines()) > len(flat) // 60


def test_mutate_by_file_catches_a_flipped_reaction_with_the_referee(capsys, teacher):
    # T is derived by the direct form alone; the Kane referee, derived from its unbroken
    # declarations, derives T again, so flipping T (or doubling m in the direct form only,
    # which changes T and not the motion) is caught as `check` would catch it
    status, out, _ = run(capsys, "mutate", teacher, "--json")
    d = json.loads(out)
    assert status == 0 and d["survived"] == [] and d["uncatchable"] == []
    killed = {k["mutant"]: k["named"] for k in d["killed"]}
    assert "reaction T" in killed["newton_euler: flip the sign of unknown `T`"]
    assert "reaction T" in killed["newton_euler: double `m`"]


def test_mutate_says_a_reaction_no_second_derivation_gives_is_uncatchable(capsys, teacher):
    # without a referee (declared away) T is derived once: its flip is no gap in the checks
    # but a mistake these derivations cannot catch -- said, not counted, exit 0
    text = teacher.read_text().replace("    reactions = (", "    referee = False\n"
                                       "    reactions = (")
    teacher.write_text(text.replace('"my_pendulum"', '"my_unrefereed"'))
    status, out, _ = run(capsys, "mutate", teacher, "--json")
    d = json.loads(out)
    assert status == 0 and d["survived"] == []
    assert {u["mutant"] for u in d["uncatchable"]} == {
        "newton_euler: flip the sign of unknown `T`", "newton_euler: double `m`"}
    assert all("no second derivation" in u["why"] for u in d["uncatchable"])
    status, out, _ = run(capsys, "mutate", teacher)
    assert status == 0 and "UNCATCHABLE: newton_euler: flip the sign of unknown `T`" in out


def test_chart_by_file_with_the_quick_sweep(capsys, teacher, tmp_path):
    status, out, err = run(capsys, "chart", teacher, "--quick", "--duration", "0.3",
                           "--repeats", "1", "--json", "--out", tmp_path / "o")
    assert status == 0, err
    d = json.loads(out)
    assert d["problem"] == "my_pendulum" and d["runs"]
    assert all((tmp_path / "o").joinpath(p).exists() for p in d["files"])


def test_atlas_by_file_says_what_does_not_apply(capsys, teacher, tmp_path):
    status, out, err = run(capsys, "atlas", teacher, "--section", "floquet", "--section",
                           "chaos", "--out", tmp_path / "o")
    assert status == 0, err
    assert "[floquet] not applicable:" in out and "[chaos] not applicable:" in out


def test_fidelity_by_file_and_its_not_applicable_message(capsys, teacher, tmp_path):
    status, out, err = run(capsys, "fidelity", teacher, "--json", "--out", tmp_path / "o")
    assert status == 0, err
    assert json.loads(out)["rungs"][0]["model"] == "linearised"
    status, _, err = run(capsys, "fidelity", teacher.parent / "my_inverted.py",
                         "--out", tmp_path / "o")
    assert status == 2
    err = " ".join(err.split())   # the message as words: it is wrapped to the terminal
    assert "not applicable" in err and "declare" in err and "stable equilibrium" in err


def test_grade_by_file(capsys, teacher):
    status, out, _ = run(capsys, "grade", teacher, "--answer", "l*theta'' + g*sin(theta) = 0")
    assert status == 0 and out.startswith("RIGHT")
    status, out, _ = run(capsys, "grade", teacher, "--answer", "l*theta'' - g*sin(theta) = 0")
    assert status == 1 and out.startswith("WRONG")


def test_serve_takes_a_file_and_hands_the_server_an_absolute_spec(capsys, teacher,
                                                                  monkeypatch):
    pytest.importorskip("starlette")
    import dualmech.web.server as server
    from dualmech.web.app import served_problems
    seen = {}
    monkeypatch.setattr(server, "serve", lambda host, port, specs, **kw: seen.update(specs=specs))
    monkeypatch.chdir(teacher.parent)
    assert main(["serve", "--problems", "my_pendulum.py", "toy_car"]) == 0
    assert seen["specs"] == [str(teacher.resolve()), "toy_car"]
    assert served_problems(seen["specs"]) == {"my_pendulum": str(teacher.resolve()),
                                             "toy_car": "toy_car"}


# -- a course package's catalogue ----------------------------------------------------------------
@pytest.fixture
def course(teacher, monkeypatch):
    """A course package registering ``mech101 = my_course`` in the group dualmech.problems
    (a dist-info folder on sys.path, as pip installs one); ``my_course`` lists the teacher's
    pendulum and its inverted twin."""
    folder = teacher.parent
    (folder / "my_course.py").write_text(
        "from my_pendulum import Pendulum\nfrom my_inverted import Pendulum as Inverted\n"
        "PROBLEMS = (Pendulum, Inverted)\n")
    info = folder / "mech101-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: mech101\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[dualmech.problems]\nmech101 = my_course\n")
    monkeypatch.syspath_prepend(str(folder))
    assert "mech101" in problems.registered()
    return "mech101"


def test_report_takes_a_course_catalogue_as_a_whole(capsys, course, tmp_path):
    status, out, err = run(capsys, "report", course, "--out", tmp_path / "r", "--duration",
                           "0.3", "--points", "3", "--json")
    assert status == 0, err
    assert [p["problem"] for p in json.loads(out)["problems"]] == ["my_pendulum",
                                                                   "my_inverted"]


@pytest.mark.slow
def test_report_all_includes_the_course_packages_problems(capsys, course, tmp_path,
                                                          monkeypatch):
    monkeypatch.setattr(problems, "all_problems", lambda: [problems.get("simple_pendulum")])
    status, out, err = run(capsys, "report", "--all", "--out", tmp_path / "r", "--duration",
                           "0.3", "--points", "3", "--json")
    assert status == 0, err
    assert [p["problem"] for p in json.loads(out)["problems"]] == [
        "simple_pendulum", "my_pendulum", "my_inverted"]


def test_every_command_takes_a_course_problem_by_entry_point(capsys, course, tmp_path):
    assert run(capsys, "check", "mech101:my_pendulum")[0] == 0
    assert run(capsys, "check", "my_inverted")[0] == 0           # its bare name
    status, out, _ = run(capsys, "check", course)                 # the whole catalogue
    assert status == 0 and "my_pendulum" in out and "my_inverted" in out
    assert run(capsys, "show", "mech101:Pendulum")[0] == 0
    # grading runs in worker processes: the package is installed before the command starts
    import os
    import subprocess
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [str(tmp_path)] + [p for p in [os.environ.get("PYTHONPATH")] if p])}
    done = subprocess.run([sys.executable, "-m", "dualmech", "grade", "mech101:my_pendulum",
                           "--answer", "l*theta'' + g*sin(theta) = 0"], env=env,
                          capture_output=True, text=True, timeout=300, cwd=tmp_path.parent)
    assert done.returncode == 0 and done.stdout.startswith("RIGHT"), done.stdout + done.stderr
    status, _, err = run(capsys, "show", course)                  # one problem is needed
    assert status == 2
    assert "mech101:my_pendulum, mech101:my_inverted" in err and "name one" in err


# -- a teacher's problem with given inputs F(t), graded --------------------------------------
CART = str(Path(__file__).resolve().parent / "corpus" / "teacher_problems"
           / "driven_cart_pendulum.py")
#: the cart's x equation, by hand from the file's free-body diagram (cart + rod along O.x):
#: (M + m) x'' + m L/2 (cos(theta) theta'' - sin(theta) theta'^2) = F + F_x
CART_X = "(M+m)*x'' + m*L/2*cos(theta)*theta'' - m*L/2*sin(theta)*theta'^2 = F + F_x"


def test_grade_takes_a_problem_with_given_inputs_and_their_dimensions(capsys):
    # the inputs F and F_x are forces: drawn at each point as the verdict draws them, with
    # their declared dimension (they were an internal KeyError, then "dimensionless")
    status, out, err = run(capsys, "grade", CART, "--answer", CART_X)
    assert status == 0 and out.startswith("RIGHT"), out + err
    status, out, _ = run(capsys, "grade", CART, "--answer", CART_X.replace("+ F_x", "- F_x"))
    assert status == 1 and out.startswith("WRONG") and "dimension" not in out
    assert "`F_x` has the wrong sign" in " ".join(out.split())


def test_grade_output_is_wrapped_to_the_terminal(capsys):
    status, out, _ = run(capsys, "grade", CART, "--answer", "0 = 0")
    assert status == 1 and "holds for any motion" in " ".join(out.split())
    assert max(map(len, out.splitlines())) <= 100 and len(out.splitlines()) >= 4


def test_fidelity_names_an_equilibrium_on_the_declared_singular_set(capsys, tmp_path):
    # the spherical pendulum hangs at rest at theta = 0, where sin(theta) = 0 (declared
    # singular): an equilibrium these coordinates cannot linearise about -- said, with the
    # declaration that makes the ladder applicable (it said "no stable equilibrium")
    path = CART.replace("driven_cart_pendulum", "spherical_pendulum")
    status, _, err = run(capsys, "fidelity", path, "--out", tmp_path)
    flat = " ".join(err.split())
    assert status == 2 and "not applicable" in flat
    assert "equilibrium at rest, theta = 0, phi = 0, lies on the declared singular set " \
           "(sin(theta) = 0)" in flat
    assert "`fidelity_ladder = (FidelityRung(" in flat and "no stable equilibrium" not in flat


def test_a_prescribed_coordinate_declared_is_no_mistake(capsys, tmp_path):
    # the tube's angle phi is turned by a motor (lg.prescribe(phi, Omega t)): declaring it
    # among the coordinates (with its range) is no "coordinate declared but no model uses
    # it"; it is no degree of freedom either
    text = Path(CART.replace("driven_cart_pendulum", "rod_in_rotating_tube")).read_text()
    old = '"rod centre from the pivot"),)'
    assert old in text
    path = tmp_path / "tube.py"
    path.write_text(text.replace(old, '"rod centre from the pivot"),\n                   '
                                 'Coordinate(phi, ANGLE, (-3.2, 3.2), (-10.0, 10.0), '
                                 '"tube angle, turned by the motor"))'))
    status, out, err = run(capsys, "check", path)
    assert status == 0 and "no model uses it" not in out + err, err
    assert "verdict: all derivations agree" in out
    status, out, _ = run(capsys, "list", path, "--json")
    assert status == 0 and json.loads(out)[0]["dof"] == 1
    # a declared coordinate that no model uses nor prescribes is still a mistake
    path = path.with_name("tube_psi.py")   # another file: a loaded file is not re-read
    path.write_text(path.with_name("tube.py").read_text().replace(
                                             '"tube angle, turned by the motor"))',
                                             '"tube angle, turned by the motor"),\n'
                                             '                   Coordinate(coordinate("psi"),'
                                             ' ANGLE, (-1, 1)))'))
    status, _, err = run(capsys, "check", path)
    assert status == 2 and "coordinate `psi` is declared but no model uses it" in \
        " ".join(err.split())
    assert "`phi`" not in err


def test_show_groups_each_row_by_acceleration_in_one_sign_convention(capsys):
    # the cart's x row, by hand: (M + m) x'' + m L/2 (cos(theta) theta'' - sin(theta)
    # theta'^2) = F + F_x; the direct form's cart row F - R_x - M x'' = 0 reads M x'' = F - R_x
    status, out, _ = run(capsys, "show", CART)
    assert status == 0
    lagrange = out[out.index("== lagrange"):out.index("== reactions")]
    x_dd_text = "x\u0308"                                 # x with a combining diaeresis
    assert f"(M + m)\u22c5{x_dd_text} +" in lagrange and "= F + F\u2093" in lagrange
    assert f"M\u22c5{x_dd_text} = F - R\u2093" in \
        out[out.index("== newton_euler"):out.index("== lagrange")]
    status, out, _ = run(capsys, "show", CART, "--json")
    doc = json.loads(out)
    M, m, L, F, Fx = sp.symbols("M m L F F_x")
    x_dd, th, th_d, th_dd = sp.symbols("x_dd theta theta_d theta_dd")
    row = doc["models"]["lagrange"]["equations"][0]["grouped"]
    left, right = sp.sympify(row["left"]), sp.sympify(row["right"])   # our own output
    hand = (M + m) * x_dd + m * L / 2 * (sp.cos(th) * th_dd - sp.sin(th) * th_d**2)
    assert sp.expand(left - hand) == 0 and sp.expand(right - (F + Fx)) == 0
    assert "(M + m)*x_dd" in row["left"]                     # grouped by acceleration
    cart = doc["models"]["newton_euler"]["equations"][0]["grouped"]
    assert sp.sympify(cart["left"]) == M * x_dd        # m a = sum F, as Lagrange's rows


WEDGE = CART.replace("driven_cart_pendulum", "wedge_block")


def test_fidelity_and_atlas_say_why_not_and_what_to_declare(capsys, tmp_path):
    # the wedge is driven by F(t) and declares its default history, which the study takes;
    # a block sliding on a free wedge has no equilibrium to linearise about, said as such
    # with the declaration that would give a ladder (it was "list index out of range"); its
    # atlas has no DAE formulation, with the declaration that would give one
    status, _, err = run(capsys, "fidelity", WEDGE, "--out", tmp_path)
    flat = " ".join(err.split())
    assert status == 2 and "no stable equilibrium to linearise about" in flat
    assert "fidelity_ladder = (FidelityRung(" in flat
    assert "index out of range" not in flat
    status, out, _ = run(capsys, "atlas", WEDGE, "--section", "dae_drift", "--out", tmp_path)
    flat = " ".join(out.split())
    assert status == 0 and "[dae_drift] not applicable: `wedge_block` has no DAE formulation: " \
        "declare a model whose coordinates are held by constraints closed with multipliers" \
        in flat and "`lg.constraint(name, g)`" in flat
    assert max(map(len, out.splitlines())) <= 100     # the atlas's lines wrapped too


def test_the_line_of_the_file_is_marked_and_kept_whole(capsys, teacher):
    long_call = ("ne.gravity(-SIGN * g * O.y + 0 * g * O.x + 0 * g * O.z + 0 * g * O.x + 0 * g "
                 "* O.z + 0 * g * Oy)")
    teacher.write_text(teacher.read_text().replace("ne.gravity(-SIGN * g * O.y)", long_call)
                       .replace('"my_pendulum"', '"my_long_line"'))
    status, _, err = run(capsys, "check", teacher)
    assert status == 2 and "NameError: name 'Oy' is not defined" in " ".join(err.split())
    assert f"    {long_call}  # <- error" in err.splitlines()     # whole, though > 100


def test_a_reversed_one_sided_reaction_is_said_though_the_models_agree(capsys, tmp_path):
    # the face's push declared along -n instead of n: the direct form and its referee share
    # the declaration, so they agree (N comes out negative); N is one-sided (unilateral), and
    # at the default state, by hand, N = -m M g cos(alpha)/(M + m sin(alpha)^2) < 0
    path = tmp_path / "wedge_reversed.py"
    text = Path(WEDGE).read_text()
    old = 'ne.reaction("N", block, I.y,'
    assert old in text
    path.write_text(text.replace(old, 'ne.reaction("N", block, -I.y,'))
    status, out, _ = run(capsys, "check", path)
    flat = " ".join(out.split())
    assert status == 0 and "verdict: all derivations agree" in flat
    m, M, g, alpha = 1.0, 3.0, 9.81, 0.5           # the file's defaults
    import math
    N = -m * M * g * math.cos(alpha) / (M + m * math.sin(alpha)**2)
    assert f"warning: one-sided reaction N = {N:.6g} < 0 at t = 0 s" in flat
    assert "the direction is probably reversed" in flat
    status, out, _ = run(capsys, "check", path, "--json")
    assert json.loads(out)["one_sided_warnings"][0].startswith(f"one-sided reaction N = {N:.6g}")
    status, out, _ = run(capsys, "check", WEDGE)       # the right declaration: no warning
    assert status == 0 and "warning: one-sided" not in out


def test_the_class_page_lists_a_teachers_file_by_its_title(tmp_path):
    # the served file's own title, source and summary, as a catalogue problem's (it was
    # listed with its name as title and no source)
    pytest.importorskip("starlette")
    from starlette.testclient import TestClient
    from dualmech.web.app import create_app

    class NoGrading:
        workers = 1

        def submit(self, *args, **kwargs):
            raise AssertionError("this test does not grade")

    app = create_app([WEDGE, "toy_car"], data=tmp_path, token="Teacher-token-8-x1Y9q2Z", pool=NoGrading())
    with TestClient(app) as client:
        listed = {p["name"]: p for p in client.get("/api/problems").json()}
    assert listed["wedge_block"]["title"] == "Block sliding on a free wedge pushed by F(t)"
    assert listed["wedge_block"]["source"] == "my notes: ex. 9"
    assert listed["toy_car"]["title"] == "Toy car on rotating track"
