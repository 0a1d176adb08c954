"""sympy.physics.mechanics interop: Kane, Lagrange and System models checked against the
catalogue's own derivations, a wrong one named, and the export used by simulation users.

The toy car (MIT 2.003J quiz 1, ``problems/toy_car.py``) is built here a third way, with
sympy's KanesMethod: track frame ``A`` tilted by ``phi`` about ``N.x``, car frame ``B`` turned
by ``theta`` about ``A.y``, car at ``-R B.z``, weight ``-m g N.z``; speeds ``u = (theta',
phi')``.  Its mass matrix is ``diag(m R^2, m R^2 cos^2 theta)`` (the source's Lagrangian)."""
from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me

from dualmech.model.equations import ModelError
from dualmech.verify.interop import (check_mechanics, from_mechanics, lagranges_method,
                                    to_mechanics, with_derivation)
from dualmech.problems import get

TOY_CAR = get("toy_car")
PENDULUM = get("simple_pendulum")


def kane_toy_car(gravity_sign: int = 1, *, formed: bool = True):
    theta, phi = me.dynamicsymbols("theta phi")
    u1, u2 = me.dynamicsymbols("u1 u2")
    m, R, g = sp.symbols("m R g")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (phi, N.x))
    B = A.orientnew("B", "Axis", (theta, A.y))
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", -R * B.z)
    A.set_ang_vel(N, u2 * N.x)
    B.set_ang_vel(A, u1 * A.y)
    P.v2pt_theory(O, N, B)
    car = me.Particle("car", P, m)
    km = me.KanesMethod(N, q_ind=[theta, phi], u_ind=[u1, u2],
                        kd_eqs=[theta.diff() - u1, phi.diff() - u2])
    if formed:
        km.kanes_equations([car], [(P, -gravity_sign * m * g * N.z)])
    return km, car, P, N


def test_a_kane_toy_car_agrees_with_every_hand_derivation():
    km, *_ = kane_toy_car()
    c = check_mechanics(TOY_CAR, km, name="kane")
    assert c.equivalent, str(c)
    assert "kane" in c.to_dict()["models"]
    eqs = from_mechanics(km, TOY_CAR, name="kane")
    m, R = sp.Symbol("m", positive=True), sp.Symbol("R", positive=True)
    theta = TOY_CAR.coordinate_functions[0]
    # the source's mass matrix diag(m R^2, m R^2 cos^2 theta)
    assert sp.simplify(eqs.mass_matrix() - sp.diag(m * R**2, m * R**2 * sp.cos(theta)**2)) \
        == sp.zeros(2, 2)
    assert eqs.coordinates == TOY_CAR.model("lagrange").coordinates


def test_a_wrong_kane_model_is_named_as_the_odd_one():
    km, *_ = kane_toy_car(gravity_sign=-1)          # gravity pointing up: a sign slip
    c = check_mechanics(TOY_CAR, km, name="kane")
    assert not c.equivalent
    assert c.to_dict()["odd"] == ["kane"]            # the four hand derivations outvote it


def test_a_system_is_formed_and_checked():
    km, car, P, N = kane_toy_car(formed=False)
    theta, phi = km.q
    u1, u2 = km.u
    m, g = sp.symbols("m g")
    system = me.System(N, me.Point("O"))
    system.q_ind = [theta, phi]
    system.u_ind = [u1, u2]
    system.kdes = [theta.diff() - u1, phi.diff() - u2]
    system.add_bodies(car)
    system.add_loads(me.Force(P, -m * g * N.z))
    assert check_mechanics(TOY_CAR, system, name="system").equivalent


def test_a_lagranges_method_with_a_multiplier_recovers_the_tension():
    """The pendulum freed from its string (coordinates theta, r; constraint a - r = 0):
    sympy's multiplier is the tension, M (g cos theta + a theta'^2) by hand."""
    th, r = me.dynamicsymbols("theta r")
    M, a, g = sp.symbols("M a g")
    L = M * (r.diff()**2 + r**2 * th.diff()**2) / 2 + M * g * r * sp.cos(th)
    lm = me.LagrangesMethod(L, [th, r], hol_coneqs=[a - r])
    lm.form_lagranges_equations()
    eqs = from_mechanics(lm, PENDULUM, name="sympy_multiplier", reactions={"lam1": "T"})
    assert [str(u) for u in eqs.unknowns] == ["T"]
    problem = with_derivation(PENDULUM, eqs,
                              coordinate_map=PENDULUM.coordinate_maps()["multiplier"])
    from dualmech.verify.check import compare
    c = compare(problem)
    assert c.equivalent, str(c)
    theta = PENDULUM.coordinate_functions[0]
    Mp, ap, gp = PENDULUM.parameter_symbols
    hand = Mp * (gp * sp.cos(theta) + ap * theta.diff()**2)
    assert sp.simplify(c.reactions["T"] - hand) == 0


def test_unmatched_names_are_refused_with_what_to_pass():
    th = me.dynamicsymbols("q1")
    M, l, g = sp.symbols("M l g")
    lm = me.LagrangesMethod(M * l**2 * th.diff()**2 / 2 + M * g * l * sp.cos(th), [th])
    with pytest.raises(ModelError, match=r"coordinate `q1`.*coordinates=\{'q1'"):
        from_mechanics(lm, PENDULUM)
    with pytest.raises(ModelError, match=r"symbol\(s\) l .*symbols=\{'l'") as info:
        from_mechanics(lm, PENDULUM, coordinates={"q1": PENDULUM.coordinate_functions[0]})
    assert "symbols={'l': ...} naming" in str(info.value) and "}}" not in str(info.value)
    theta = PENDULUM.coordinate_functions[0]
    a = PENDULUM.parameter_symbols[1]
    assert check_mechanics(PENDULUM, lm, coordinates={"q1": theta}, symbols={"l": a}).equivalent
    with pytest.raises(TypeError, match="KanesMethod, a LagrangesMethod or a System"):
        from_mechanics("not a model", PENDULUM)


def test_export_round_trip_and_state_space_form():
    """to_mechanics' state-space form integrates like the problem's own right-hand side, and
    lagranges_method of the source's Lagrangian comes back equivalent."""
    form = to_mechanics(TOY_CAR)
    assert [str(q) for q in form.q] == ["theta(t)", "phi(t)"]
    values = {s: v for s, v in form.constants.items()}
    theta, phi = form.q
    ut, up = form.u
    state = {theta: 0.3, phi: -0.7, ut: 0.5, up: 1.1}
    rhs = form.rhs().subs(values).subs(state)
    m, R, g = 0.2, 0.5, 9.81
    # by hand from T, V of the source: theta'' = -phi'^2 sin cos - g/R sin(theta) cos(phi);
    # phi'' = 2 phi' theta' tan(theta) - g sin(phi) / (R cos(theta))
    th, ph, wt, wp = 0.3, -0.7, 0.5, 1.1
    expected = [wt, wp, -wp**2 * np.sin(th) * np.cos(th) - g / R * np.sin(th) * np.cos(ph),
                2 * wp * wt * np.tan(th) - g * np.sin(ph) / (R * np.cos(th))]
    assert np.allclose([float(x) for x in rhs], expected, rtol=1e-12, atol=0)
    assert m == values[TOY_CAR.parameter_symbols[0]]
    th_d, ph_d = TOY_CAR.coordinate_functions
    ms, Rs, gs = TOY_CAR.parameter_symbols
    L = ms * Rs**2 * (th_d.diff()**2 + ph_d.diff()**2 * sp.cos(th_d)**2) / 2 \
        + ms * gs * Rs * sp.cos(th_d) * sp.cos(ph_d)
    lm = lagranges_method(TOY_CAR, L)
    assert check_mechanics(TOY_CAR, lm, name="exported").equivalent
    with pytest.raises(ModelError, match="unknown reactions"):
        to_mechanics(TOY_CAR, "newton_euler")


def test_a_lagrangian_given_as_text_is_refused_not_evaluated():
    with pytest.raises(TypeError, match="not text"):
        lagranges_method(TOY_CAR, "__import__('os').getcwd()")


# -- what the bridge cannot take, refused with what to do ------------------------------------
def test_a_kanes_method_without_kinematic_equations_is_refused():
    q, u = me.dynamicsymbols("x u")
    N = me.ReferenceFrame("N")
    km = me.KanesMethod(N, q_ind=[q], u_ind=[u])          # no kd_eqs
    with pytest.raises(ModelError, match=r"no kinematic differential equations.*kd_eqs"):
        from_mechanics(km)


def test_auxiliary_speeds_are_refused():
    q, u, ua = me.dynamicsymbols("x u ua")
    m, F = sp.symbols("m F")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    P = O.locatenew("P", q * N.x)
    P.set_vel(N, u * N.x + ua * N.y)
    km = me.KanesMethod(N, q_ind=[q], u_ind=[u], kd_eqs=[q.diff() - u], u_auxiliary=[ua])
    km.kanes_equations([me.Particle("p", P, m)], [(P, -m * N.x + F * N.y)])
    with pytest.raises(ModelError, match=r"auxiliary speeds \(ua\).*without u_auxiliary"):
        from_mechanics(km)


def test_objects_that_are_not_mechanics_models_are_refused():
    for thing in (sp.Matrix([1, 2]), None, me.ReferenceFrame("N")):
        with pytest.raises(TypeError, match="KanesMethod, a LagrangesMethod or a System"):
            from_mechanics(thing)


def test_a_speed_without_a_coordinate_is_named_with_the_way_to_map_it():
    """The toy car with a spinning wheel on it (speed ``w``, its angle left out): ``w`` enters
    no kinematic equation, so the bridge asks for ``ignorable``; given, the wheel's angle is
    the coordinate whose rate ``w`` is."""
    from dualmech import coordinate
    km, car, P, N = kane_toy_car(formed=False)
    theta, phi = km.q
    u1, u2 = km.u
    w = me.dynamicsymbols("w")
    m, Iw = sp.symbols("m Iw")
    wheel_frame = me.ReferenceFrame("Wf")       # a flywheel at the car, spinning about N.y
    wheel_frame.set_ang_vel(N, w * N.y)
    wheel = me.RigidBody("wheel", P, wheel_frame, 0, (me.inertia(N, 0, Iw, 0), P))
    km2 = me.KanesMethod(N, q_ind=[theta, phi], u_ind=[u1, u2, w],
                         kd_eqs=[theta.diff() - u1, phi.diff() - u2])
    km2.kanes_equations([car, wheel], [(P, -m * sp.Symbol("g") * N.z)])
    with pytest.raises(ModelError, match=r"speed\(s\) w enter no kinematic.*ignorable=\{'w'"):
        from_mechanics(km2)
    with pytest.raises(ModelError, match=r"ignorable speed `v` is not a generalised speed"):
        from_mechanics(km2, ignorable={"v": coordinate("beta")})
    beta = coordinate("beta")
    eqs = from_mechanics(km2, ignorable={"w": beta})
    assert [c.func.__name__ for c in eqs.coordinates] == ["theta", "phi", "beta"]
    # the wheel spins freely: Iw beta'' = 0 is its row (Kane's row of w)
    row = eqs.equations[eqs.labels.index("Kane, w")]
    assert sp.expand(row - Iw * beta.diff(beta.args[0], 2)) == 0


def test_a_coordinate_in_the_opposite_sign_convention_and_bad_targets():
    """``coordinates={'theta': -theta}``: the Kane model's pitch read as the problem's pitch
    measured the other way round (its row of theta changes sign through theta''; the toy car is
    symmetric in theta, so the motion is still the toy car's, checked exactly); a target in two
    coordinates, or two targets in one, are refused."""
    km, *_ = kane_toy_car()
    theta, phi = TOY_CAR.coordinate_functions
    eqs = from_mechanics(km, TOY_CAR, name="flipped", coordinates={"theta": -theta})
    assert eqs.coordinates == (theta, phi)
    m, R = TOY_CAR.parameter_symbols[:2]
    # mass matrix row of theta: m R^2 theta'' becomes -m R^2 theta''
    assert sp.expand(eqs.mass_matrix()[0, 0] + m * R**2) == 0
    assert check_mechanics(TOY_CAR, km, name="flipped", coordinates={"theta": -theta}).equivalent
    with pytest.raises(ModelError, match="expression in exactly one"):
        from_mechanics(km, TOY_CAR, coordinates={"theta": theta + phi})
    with pytest.raises(ModelError, match="are mapped to `phi`"):
        from_mechanics(km, TOY_CAR, coordinates={"theta": phi})


def test_a_kane_pendulum_with_a_dependent_coordinate_agrees_and_keeps_its_constraint():
    """The pendulum on coordinates theta and r with r dependent (configuration constraint
    r - a = 0, velocity constraint r' = 0): accepted, the constraint kept at position level on
    the row of the velocity constraint its rate is, and the motion is the pendulum's."""
    th, r = me.dynamicsymbols("theta r")
    u1, u2 = me.dynamicsymbols("u1 u2")
    M, a, g = sp.symbols("M a g")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (th, N.z))
    A.set_ang_vel(N, u1 * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", r * A.x)
    P.set_vel(N, u2 * A.x + r * u1 * A.y)
    km = me.KanesMethod(N, q_ind=[th], u_ind=[u1], kd_eqs=[th.diff() - u1, r.diff() - u2],
                        q_dependent=[r], configuration_constraints=[r - a],
                        u_dependent=[u2], velocity_constraints=[u2])
    km.kanes_equations([me.Particle("bob", P, M)], [(P, M * g * N.x)])
    eqs = from_mechanics(km, PENDULUM, name="kane_r", reactions={})
    (con,) = eqs.constraints
    assert (con.name, con.level, con.label) == ("configuration r", "position",
                                                "constraint u2 (acceleration level)")
    r_t = eqs.coordinates[1]
    assert sp.simplify(con.expression - (r_t - PENDULUM.parameter_symbols[1])) == 0
    problem = with_derivation(PENDULUM, eqs,
                              coordinate_map=PENDULUM.coordinate_maps()["multiplier"])
    from dualmech.verify.check import compare
    assert compare(problem).equivalent
