"""Fidelity ladder of a driven scene (``Problem.fidelity_inputs``): a teacher's pendulum on a
cart pushed by ``F(t) = F0 sin(w t)``, written outside the catalogue (its file below).

Hand derivation (independent of dualmech).  Cart of mass M on a smooth rail (x), a point bob
m on a massless rod of length l (theta from the downward vertical), the push F on the cart::

    T = (M + m) x'^2 / 2 + m l x' theta' cos(theta) + m l^2 theta'^2 / 2,
    V = -m g l cos(theta)
    (M + m) x'' + m l (theta'' cos(theta) - theta'^2 sin(theta)) = F
    x'' cos(theta) + l theta'' + g sin(theta) = 0

Linearised about the equilibrium without input (x, theta) = (0, 0) -- x is neutral:
(M + m) x'' + m l theta'' = F and x'' + l theta'' + g theta = 0, so

    theta'' + W^2 theta = -F / (M l),   W^2 = (M + m) g / (M l),
    x'' = (m g theta + F) / M.

From rest at (0, theta0), with F = F0 sin(w t) and a = -F0 / (M l (W^2 - w^2)):

    theta(t) = theta0 cos(W t) + a (sin(w t) - (w / W) sin(W t))

and x integrated twice from rest (the double integral of sin(k t) is t/k - sin(k t)/k^2, of
cos(W t) is (1 - cos(W t)) / W^2):

    x(t) = (m g / M) [theta0 (1 - cos W t) / W^2 + a (t/w - sin(w t)/w^2)
                      - a (w/W) (t/W - sin(W t)/W^2)] + (F0 / M) (t/w - sin(w t)/w^2).

The ladder's linearised rung must miss the nonlinear motion by exactly what this closed form
misses the hand nonlinear equations (integrated here by scipy), coordinate by coordinate.
"""
from __future__ import annotations

import textwrap

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from dualmech import problems
from dualmech.numeric.studies.fidelity import has_ladder, ladder, not_applicable

RTOL = 1e-10            # the ladder's default
M, m, l, g, F0, w = 2.0, 0.5, 0.5, 9.81, 1.0, 2.0
THETA0 = 0.1
X_RANGE, THETA_RANGE = 10.0, 2.0        # widths of the declared ranges (-5, 5), (-1, 1)

TEACHER_FILE = textwrap.dedent('''
    """A pendulum on a cart pushed by F(t), as in my notes."""
    import sympy as sp
    from dualmech import (Frame, Input, Lagrangian, NewtonEuler, Particle, Point, Problem,
                          Parameter, Coordinate, Reaction, FidelityRung, coordinate, rate, t,
                          MASS, LENGTH, ACCELERATION, ANGLE, FORCE, FREQUENCY)

    M, m, l, g = sp.symbols("M m l g", positive=True)
    F0, w = sp.symbols("F0 w", positive=True)
    F = sp.Symbol("F", real=True)
    x, theta = coordinate("x"), coordinate("theta")


    class PushedCart(Problem):
        name, title, source = "pushed_cart", "Pendulum on a pushed cart", "my notes: ex. 4"
        parameters = (Parameter(M, MASS, 2, (0.5, 10)), Parameter(m, MASS, 0.5, (0.1, 5)),
                      Parameter(l, LENGTH, 0.5, (0.1, 2)),
                      Parameter(g, ACCELERATION, 9.81, (1, 20)),
                      Parameter(F0, FORCE, 1, (0.1, 10), "amplitude of the push"),
                      Parameter(w, FREQUENCY, 2, (0.1, 10), "frequency of the push"))
        coordinates = (Coordinate(x, LENGTH, (-5, 5)), Coordinate(theta, ANGLE, (-1, 1)))
        reactions = (Reaction("N", FORCE, "rail on cart, up"),
                     Reaction("S", FORCE, "rod on bob, towards the cart"))
        inputs = (Input(F, FORCE, "push on the cart"),)
        FIDELITY
        initial_state = {x: 0.0, theta: 0.1}

        def newton_euler(self):
            O = Frame.ground("O")
            P = Point.origin(O).locate("P", x * O.x)
            along = sp.sin(theta) * O.x - sp.cos(theta) * O.y      # cart to bob
            cart = Particle("cart", M, P)
            bob = Particle("bob", m, P.locate("B", l * along))
            ne = NewtonEuler(coordinates=[x, theta], ground=O)
            ne.gravity(-g * O.y)
            ne.force("push", cart, F * O.x)
            ne.reaction("N", cart, O.y)
            ne.reaction("S", bob, -along, against=cart)
            ne.linear_momentum(cart, O.x)
            ne.linear_momentum(cart, O.y)
            ne.linear_momentum(bob, O.x)
            ne.linear_momentum(bob, O.y)
            return ne.equations()

        def lagrange(self):
            lg = Lagrangian(coordinates=[x, theta])
            xd, td = rate(x), rate(theta)
            lg.kinetic("T", (M + m) * xd**2 / 2 + m * l * xd * td * sp.cos(theta)
                       + m * l**2 * td**2 / 2)
            lg.potential("V", -m * g * l * sp.cos(theta))
            lg.generalized_force("push", [F, 0])
            return lg.equations()


    class LightBob(PushedCart):
        name = "pushed_cart_light_bob"
        parameters = tuple(Parameter(m, MASS, 1e-9, (1e-12, 5)) if p.symbol == m else p
                           for p in PushedCart.parameters)


    class PushedCartLadder(PushedCart):
        name = "pushed_cart_ladder"
        fidelity_ladder = (FidelityRung("light bob", LightBob, "the bob's pull on the cart"),
                           FidelityRung("cart pendulum", lambda: PushedCartLadder()))
''')
DRIVE = 'fidelity_inputs = {"F": F0 * sp.sin(w * t)}'


def _write(tmp_path_factory, drive: str):
    path = tmp_path_factory.mktemp("teacher") / "pushed_cart.py"
    path.write_text(TEACHER_FILE.replace("FIDELITY", drive))
    return path


@pytest.fixture(scope="module")
def teacher(tmp_path_factory):
    return _write(tmp_path_factory, DRIVE)


@pytest.fixture(scope="module")
def lad(teacher):
    return ladder(problems.load(f"{teacher}:PushedCart"))


def linear_closed_form(t):
    """The hand linear forced response (module docstring), ``(x, theta)``."""
    W = np.sqrt((M + m) * g / (M * l))
    a = -F0 / (M * l * (W**2 - w**2))
    theta = THETA0 * np.cos(W * t) + a * (np.sin(w * t) - w / W * np.sin(W * t))
    dbl_sin = lambda k: t / k - np.sin(k * t) / k**2          # noqa: E731
    x = (m * g / M * (THETA0 * (1 - np.cos(W * t)) / W**2 + a * dbl_sin(w)
                      - a * w / W * dbl_sin(W)) + F0 / M * dbl_sin(w))
    return x, theta


def hand_nonlinear(t, bob=m):
    """The hand nonlinear equations (module docstring) with a bob of mass ``bob``, by scipy
    at rtol 1e-12."""
    def f(time, y):
        _, th, xd, thd = y
        c, s = np.cos(th), np.sin(th)
        A = np.array([[M + bob, bob * l * c], [c, l]])
        b = np.array([F0 * np.sin(w * time) + bob * l * thd**2 * s, -g * s])
        return [xd, thd, *np.linalg.solve(A, b)]
    return solve_ivp(f, (t[0], t[-1]), [0.0, THETA0, 0.0, 0.0], "DOP853", t_eval=t,
                     rtol=1e-12, atol=1e-14).y


def test_the_linear_rung_misses_what_the_hand_closed_form_misses(lad):
    linear, nonlinear = lad.rungs
    assert linear.model == "linearised" and "forced by F(t)" in linear.label
    assert nonlinear.error_path == 0 and lad.span == (0.0, 5.0)
    t = np.linspace(*lad.span, 201)
    x_lin, th_lin = linear_closed_form(t)
    x_nl, th_nl = hand_nonlinear(t)[:2]
    hand_theta = np.abs(th_lin - th_nl).max() / THETA_RANGE
    hand_x = np.abs(x_lin - x_nl).max() / X_RANGE
    # a real difference, far above the integrations' error ...
    assert hand_theta > 1e-4 and hand_x > 1e-5
    # ... matched to the runs' tolerance (rtol 1e-10, atol 1e-10 x each range), a few times
    assert linear.by_coordinate["theta"] == pytest.approx(hand_theta, abs=10 * RTOL)
    assert linear.by_coordinate["x"] == pytest.approx(hand_x, abs=10 * RTOL)


def test_the_push_is_in_every_rung_and_stated(lad):
    # the push drives the cart away: x(5) = 1.3 m by the closed form, 0.13 of x's range; an
    # unforced linear rung would stay near x = 0 and miss that much at the end
    x_lin, _ = linear_closed_form(np.array([5.0]))
    assert x_lin[0] / X_RANGE > 0.1 > 1e-2 > lad.rungs[0].error_final
    assert lad.inputs == {"F": "F0*sin(t*w)"}
    assert "driven by F(t) = F0*sin(t*w)" in str(lad)
    assert "$F$(t) = F0*sin(t*w)" in lad.conditions     # under the chart


def test_the_reaction_of_the_rail_is_taken_at_each_time(teacher):
    """The reactions along a driven run are the direct model's at each sample's own time
    (the push enters them): by hand, the bob's radial balance gives the rod's pull
    S = m (g cos(theta) + l theta'^2 - x'' sin(theta)) and the cart's vertical balance
    N = M g + S cos(theta), with x'' from the 2 x 2 system of the module docstring."""
    from dualmech.numeric.studies.fidelity import _driven, _drive, _reactions
    p = problems.load(f"{teacher}:PushedCart")
    scene = _driven(p, _drive(p))
    t = np.linspace(0.0, 2.0, 41)
    x, th, xd, thd = hand_nonlinear(t)
    forces = _reactions(scene, np.array([x, th, xd, thd]), t)
    c, s = np.cos(th), np.sin(th)
    F = F0 * np.sin(w * t)
    xdd = (F + m * l * thd**2 * s + m * g * s * c) / (M + m * s**2)   # the 2 x 2 solved
    S = m * (g * c + l * thd**2 - xdd * s)
    assert np.abs(forces["S"] - S).max() < 1e-9 * m * g
    assert np.abs(forces["N"] - (M * g + S * c)).max() < 1e-9 * M * g


def test_without_the_declaration_it_says_which_one_to_make(tmp_path_factory, capsys):
    bare = _write(tmp_path_factory, "")
    p = problems.load(f"{bare}:PushedCart")
    why = not_applicable(p)
    assert not has_ladder(p)
    assert "it is driven by given inputs (F) and declares no history of them" in why
    assert '`fidelity_inputs = {"F": F0 * sp.sin(w * t)}`' in why
    from dualmech.cli.main import main
    assert main(["fidelity", f"{bare}:PushedCart", "--out", str(tmp_path_factory.mktemp("o"))]) == 2
    err = " ".join(capsys.readouterr().err.split())
    assert "has no fidelity ladder (not applicable)" in err and "fidelity_inputs = {" in err


def test_an_inputs_default_history_drives_the_study_as_fidelity_inputs_does(
        tmp_path_factory, lad):
    """``Input(..., history=...)`` is what simulations and charts drive the scene with, and
    the study takes it too when no ``fidelity_inputs`` is declared: the same ladder."""
    text = TEACHER_FILE.replace("FIDELITY", "").replace(
        'Input(F, FORCE, "push on the cart")',
        'Input(F, FORCE, "push on the cart", history=F0 * sp.sin(w * t))')
    path = tmp_path_factory.mktemp("teacher") / "pushed_cart_history.py"
    path.write_text(text)
    p = problems.load(f"{path}:PushedCart")
    assert has_ladder(p) and not_applicable(p) is None
    other = ladder(p)
    assert other.inputs == lad.inputs == {"F": "F0*sin(t*w)"}
    assert other.rungs[0].error_final == pytest.approx(lad.rungs[0].error_final, rel=1e-6)


def test_fidelity_command_runs_the_driven_ladder(teacher, tmp_path, capsys):
    import json
    from dualmech.cli.main import main
    assert main(["fidelity", f"{teacher}:PushedCart", "--out", str(tmp_path), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["inputs"] == {"F": "F0*sin(t*w)"} and len(doc["rungs"]) == 2
    assert (tmp_path / "pushed_cart_fidelity.png").stat().st_size > 0


@pytest.mark.parametrize("drive, message", [
    ('fidelity_inputs = {"G": sp.sin(t)}', "`G` is not a declared input (declared: F)"),
    ('fidelity_inputs = {"F": sp.sin(sp.Symbol("k") * t)}', "names k, which are neither t"),
    ('fidelity_inputs = {"F": "sin(t)"}', "must be a sympy expression of t"),
], ids=["unknown-input", "stray-symbol", "text"])
def test_declaration_mistakes_are_named(tmp_path_factory, drive, message):
    from dualmech.model.problem import ProblemError
    p = problems.load(f"{_write(tmp_path_factory, drive)}:PushedCart")
    with pytest.raises(ProblemError, match=message.replace("(", r"\(").replace(")", r"\)")):
        p.validate()


def test_a_declared_rung_takes_the_push_by_name(teacher):
    """The teacher's own ladder: a bob of 1e-9 kg (its pull on the cart neglected: the cart
    moves as M x'' = F) below the full model, both pushed by the declared F(t).  The rung's
    error is what the hand equations give with m = 1e-9 against m = 0.5."""
    lad = ladder(problems.load(f"{teacher}:PushedCartLadder"))
    assert [r.label for r in lad.rungs][1:] == ["light bob", "cart pendulum"]
    assert [r.problem for r in lad.rungs][1:] == ["pushed_cart_light_bob", "pushed_cart_ladder"]
    light = lad.rungs[1]
    t = np.linspace(*lad.span, 201)
    rung, full = hand_nonlinear(t, bob=1e-9), hand_nonlinear(t)
    hand_x = np.abs(rung[0] - full[0]).max() / X_RANGE
    hand_theta = np.abs(rung[1] - full[1]).max() / THETA_RANGE
    assert hand_x > 1e-3 and hand_theta > 1e-3          # the bob's pull matters
    assert light.by_coordinate["x"] == pytest.approx(hand_x, abs=10 * RTOL)
    assert light.by_coordinate["theta"] == pytest.approx(hand_theta, abs=10 * RTOL)


def test_the_input_matrix_at_the_equilibrium_is_the_hand_one(teacher):
    """At theta = 0, at rest, the linear equations give x'' = F / M and theta'' = -F / (M l):
    the forced linear rung's B is [0, 0, 1/M, -1/(M l)] (module docstring)."""
    from dualmech.numeric.formulations import formulations
    from dualmech.numeric.studies.fidelity import _drive, _driven, _forcing, _free
    p = problems.load(f"{teacher}:PushedCart")
    drive = _drive(p)
    ref, free = (formulations(q, models=["lagrange"], stabilisations=())[0][0]
                 for q in (_driven(p, drive), _free(p)))
    y_eq = np.zeros(4)
    B, u = _forcing(ref, free.rhs(0.0, y_eq), y_eq, drive, (0.0, 5.0))
    assert B[:, 0] == pytest.approx([0, 0, 1 / M, -1 / (M * l)], abs=1e-12)
    assert u(0.3)[0] == pytest.approx(F0 * np.sin(w * 0.3), rel=1e-15)
