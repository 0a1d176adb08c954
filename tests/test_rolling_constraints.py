"""Constraints declared in the direct form (holonomic, velocity level, rolling), sampled on the
motion's manifold by the verdict, and sympy's own rolling disk with dependent speeds.

The rolling disk (``problems/rolling_disk.py``, derived by hand there) declares its rolling
condition with ``NewtonEuler.rolling``; the variants below write it as hand rows at velocity
level, or wrongly at the geometric contact point.  Reference values: the catalogue's Lagrange
and multiplier models (hand ``T`` and ``V``, rolling by multipliers), decided by the exact
verdict, and the hand rolling rows ``x' - r phi' cos(psi)``, ``y' - r phi' sin(psi)`` of the
problem's docstring."""
from __future__ import annotations

import pytest
import sympy as sp
import sympy.physics.mechanics as me

from dualmech import (EquationSet, Frame, Lagrangian, NewtonEuler, Particle, Point, coordinate,
                      linearize_about, rate, compare)
from dualmech.model.equations import ModelError, is_zero_expression
from dualmech.problems import get
from dualmech.problems.rolling_disk import (COORDS, RollingDisk, _rolling_rows,
                                            lean_eigenvalue_squared, scene, g, r, v, phi, psi,
                                            x, y)
from dualmech.verify import sampling
from dualmech.verify.interop import check_mechanics, from_mechanics


def direct(name: str = "newton_euler", how: str = "rolling"):
    """The disk's free-body diagram; the rolling condition declared as ``how`` says."""
    s = scene()
    ne = NewtonEuler(name, coordinates=COORDS, ground=s.O)
    ne.gravity(-g * s.O.z)
    ne.reaction_vector("F", s.disk, s.O, at=s.P)
    for axis in (s.O.x, s.O.y, s.O.z):
        ne.linear_momentum(s.disk, axis)
    for axis in (s.B.x, s.B.y, s.B.z):
        ne.angular_momentum(s.disk, axis)
    if how == "rolling":                       # the helper: the material point
        ne.rolling("rolling", s.disk, s.P, [s.O.x, s.O.y])
    elif how == "velocity rows":               # hand rows at velocity level, no declaration
        for label, row in zip(("O.x", "O.y"), _rolling_rows(s)):
            ne.equation(f"rolling {label} (velocity level)", {"rolling": row})
    elif how == "geometric":                   # the classic mistake: the contact point itself
        for label, d in (("O.x", s.O.x), ("O.y", s.O.y)):
            ne.velocity_constraint(f"slip {label}", s.P.vel(s.O).dot(d))
    return ne.equations()


class DeclaredDisk(RollingDisk):
    """The catalogue's disk with one more direct model, rolling declared."""

    extra_models = ("multiplier", "declared")

    def declared(self):
        return direct("declared")


class VelocityRowsDisk(RollingDisk):
    def newton_euler(self):
        return direct(how="velocity rows")


class GeometricDisk(RollingDisk):
    def newton_euler(self):
        return direct(how="geometric")


def test_declared_rolling_gives_the_same_motion_and_contact_forces():
    c = compare(DeclaredDisk())
    assert c.equivalent, str(c)
    assert c.judgement.method == "exact"
    # every contact force of the declared model is compared with the hand direct model's
    by_reaction = {}
    for pair in c.pairs:
        if pair.kind == "reactions":
            for name in pair.reactions:
                by_reaction.setdefault(name, []).append(pair)
    for name in ("F_x", "F_y", "F_z"):
        pairs = [p for p in by_reaction[name] if "declared" in (p.reference, p.candidate)
                 or "declared" in p.candidate]
        assert pairs and all(p.equivalent and p.decided for p in pairs), name


def test_the_rolling_helper_records_the_hand_rows_at_velocity_level():
    eqs = direct()
    assert [c.level for c in eqs.constraints] == ["velocity", "velocity"]
    hand = [rate(x) - r * rate(phi) * sp.cos(psi), rate(y) - r * rate(phi) * sp.sin(psi)]
    for c, h in zip(eqs.constraints, hand):
        assert is_zero_expression(sp.expand(c.expression - h)), c
        assert c.label in eqs.labels          # its acceleration-level row is in the equations
    # the catalogue's multiplier model, mapped to the reference coordinates (h = 0), keeps
    # its rolling constraints and loses h = 0, which the mapping satisfies by construction
    disk = get("rolling_disk")
    mapped = disk.in_reference_coordinates(disk.model("multiplier"))
    assert [(k.name, k.level) for k in disk.model("multiplier").constraints] == \
        [("F_x", "velocity"), ("F_y", "velocity"), ("F_z", "position")]
    assert [(k.name, k.level) for k in mapped.constraints] == \
        [("F_x", "velocity"), ("F_y", "velocity")]
    # the acceleration-level rows hold no reaction: linearisation reads them as constraints
    lin = linearize_about(eqs, RollingDisk.steady_motion.about, parameter=v)
    assert [kind for _, kind in lin.constraints] == ["velocity", "velocity"]
    lam = sp.Symbol("lambda")
    coeffs = sp.Poly(lin.symbolic.charpoly(lam).as_expr(), lam).all_coeffs()
    spin = {v: r * sp.Symbol("W")}
    assert sp.cancel((-coeffs[2] / coeffs[0] - lean_eigenvalue_squared()).subs(spin)) == 0


def test_velocity_level_rows_are_not_blamed_when_another_model_declares_the_manifold():
    c = compare(VelocityRowsDisk())
    assert c.equivalent, str(c)


@pytest.mark.slow
def test_without_the_manifold_the_velocity_rows_would_be_blamed(monkeypatch):
    """The point of sampling on the manifold: drawn freely, the correct velocity rows fail."""
    monkeypatch.setattr(sampling, "_declared_manifold", lambda systems, ctx: [])
    from dualmech.verify import verdicts
    monkeypatch.setattr(verdicts, "shared_manifold", lambda *a: [])
    c = compare(VelocityRowsDisk())
    assert not c.equivalent
    assert "newton_euler" in c.to_dict()["odd"]
    assert "[rolling O.x (velocity level)]" in str(c)


@pytest.mark.slow
def test_the_geometric_contact_point_is_caught_and_named():
    c = compare(GeometricDisk())
    assert not c.equivalent
    # the referee is derived from the direct model's declarations, the wrong constraint
    # included (the catalogue's disk declares its rolling, so it has one): it shares the
    # mistake and is outvoted with the model, by the two multiplier models
    assert c.to_dict()["odd"] == ["newton_euler", "referee"]
    text = str(c)
    assert "[constraint slip O.x (acceleration level)]" in text
    assert "material point" in text and "geometric contact point" in text


def test_the_referee_derives_the_catalogue_disk_with_its_declared_rolling():
    """Kane's method from the declarations (bodies, loads, the contact force and the rolling
    constraint) gives the motion and all three contact forces a third time."""
    c = compare(get("rolling_disk"))
    assert c.equivalent, str(c)
    assert "no referee" not in str(c) and "not cross-checked" not in str(c)
    assert "referee vs lagrange: equivalent" in str(c)
    assert "reactions F_x, F_y, F_z of referee vs newton_euler: the same" in str(c)


def test_the_rolling_helper_warns_about_the_geometric_contact_point():
    doc = " ".join(NewtonEuler.rolling.__doc__.split())
    assert "material point" in doc and "geometric* contact point" in doc


def test_a_holonomic_declaration_matches_a_multiplier_model():
    """A bead on a horizontal rail at height -l, written in (X, Y): the direct form declares
    Y + l = 0 (position level) with the rail's normal force N; Lagrange holds the same
    constraint by the multiplier N.  By hand: X'' = 0, N = m g."""
    X, Y = coordinate("X"), coordinate("Y")
    m, l, gg = sp.symbols("m l g", positive=True)
    O = Frame.ground("O")
    bob = Particle("bob", m, Point.origin(O).locate("bob", X * O.x + Y * O.y))
    ne = NewtonEuler(coordinates=[X, Y], ground=O)
    ne.gravity(-gg * O.y)
    N = ne.reaction("N", bob, O.y)
    ne.linear_momentum(bob, O.x)
    ne.linear_momentum(bob, O.y)
    ne.constraint("rail", Y + l)
    eqs = ne.equations()
    assert [(c.level, c.expression) for c in eqs.constraints] == [("position", Y + l)]
    assert eqs.labels[-1] == "constraint rail (acceleration level)"
    sol = eqs.solve()
    assert (sol[rate(X, 2)], sol[rate(Y, 2)], sol[N]) == (0, 0, m * gg)
    lg = Lagrangian(coordinates=[X, Y])
    lg.kinetic("T", m * (rate(X)**2 + rate(Y)**2) / 2)
    lg.potential("V", m * gg * Y)
    lg.constraint("N", Y + l)
    from dualmech.verify.verdicts import judge
    j = judge({"direct": eqs, "lagrange": lg.equations()})
    assert not j.faults and len(j.groups) == 1 and j.points == 8, j
    wrong = Lagrangian(coordinates=[X, Y])
    wrong.kinetic("T", m * (rate(X)**2 + rate(Y)**2) / 2)
    wrong.potential("V", m * gg * Y + m * gg * X)      # a stray slope along the rail
    wrong.constraint("N", Y + l)
    j = judge({"direct": eqs, "lagrange": lg.equations(), "wrong": wrong.equations()})
    assert j.odd == ["wrong"], j


def test_a_constraint_no_coordinate_solves_is_compared_at_acceleration_level():
    """The pendulum in Cartesian coordinates: Lagrange declares x^2 + y^2 - l^2 = 0 (solved
    for no coordinate without a root, so the manifold cannot be sampled exactly and points are
    drawn freely); the direct form writes the rod's condition by hand at acceleration level,
    x x'' + y y'' + x'^2 + y'^2 = 0, with the rod's tension S along the rod.  By hand the two
    are the same motion at every state; the declared constraint is not "violated" off its
    manifold (its acceleration row is what is compared there).  A wrong tension direction is
    still caught."""
    X, Y = coordinate("X"), coordinate("Y")
    m, l, gg = sp.symbols("m l g", positive=True)
    S = sp.Symbol("S", real=True)
    xd, yd = rate(X), rate(Y)
    lg = Lagrangian(coordinates=[X, Y])
    lg.kinetic("T", m * (xd**2 + yd**2) / 2)
    lg.potential("V", m * gg * Y)
    lg.constraint("lam", X**2 + Y**2 - l**2)
    rows = [m * rate(X, 2) + S * X / l, m * rate(Y, 2) + S * Y / l + m * gg,
            X * rate(X, 2) + Y * rate(Y, 2) + xd**2 + yd**2]
    direct = EquationSet("direct", (X, Y), tuple(rows), (S,))
    from dualmech.verify.verdicts import judge
    j = judge({"lagrange": lg.equations(), "direct": direct})
    assert not j.faults and len(j.groups) == 1 and j.points == 8, j
    bad = EquationSet("bad", (X, Y), (rows[0], m * rate(Y, 2) - S * Y / l + m * gg, rows[2]),
                      (S,))
    j = judge({"lagrange": lg.equations(), "bad": bad})
    assert j.faults, j


@pytest.mark.parametrize("value, match", [
    ("vector", "is a Vector"),
    ("list", "sequence or matrix"),
    ("stranger", "not coordinates"),
    ("reaction", "holds the reaction"),
    ("acceleration", "acceleration level is derived"),
    ("quadratic", "not linear in the rates"),
    ("no rate", "holds no rate"),
    ("zero", "identically zero"),
])
def test_malformed_velocity_constraints_are_refused(value, match):
    s = scene()
    ne = NewtonEuler(coordinates=COORDS, ground=s.O)
    F = ne.reaction_vector("F", s.disk, s.O, at=s.P)
    bad = {"vector": s.P.vel(s.O), "list": [rate(x), rate(y)],
           "stranger": rate(coordinate("z")), "reaction": rate(x) - F.dot(s.O.x),
           "acceleration": rate(x, 2), "quadratic": rate(x)**2 - rate(y),
           "no rate": x - r, "zero": sp.sin(psi)**2 + sp.cos(psi)**2 - 1}[value]
    with pytest.raises(ModelError, match=match):
        ne.velocity_constraint("c", bad)


def test_malformed_position_constraints_and_rolling_are_refused():
    s = scene()
    ne = NewtonEuler(coordinates=COORDS, ground=s.O)
    with pytest.raises(ModelError, match="position-level constraint holds no rates"):
        ne.constraint("c", rate(x))
    with pytest.raises(TypeError, match="text"):
        ne.constraint("c", "x - 1")
    ne.constraint("c", x - r)
    with pytest.raises(ModelError, match="declared twice"):
        ne.constraint("c", y)
    with pytest.raises(ModelError, match="identically zero"):
        ne.rolling("vertical", s.disk, s.P, [s.O.z])   # built into the coordinates
    with pytest.raises(ModelError, match="rigid body"):
        ne.rolling("r", Particle("p", 1, s.G), s.P, [s.O.x])


def kane_rolling_disk(material: bool = True):
    """sympy's rolling disk (its rolling-disc tutorial's frames Y, L, R) with the contact's
    x, y as coordinates, x' and y' as dependent speeds and the no-slip condition as velocity
    constraints -- on the material point (``material``) or on the geometric contact point."""
    psi_, theta_, phi_, x_, y_ = me.dynamicsymbols("psi theta phi x y")
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    m, rr, gg = sp.symbols("m r g")
    N = me.ReferenceFrame("N")
    Yf = N.orientnew("Y", "Axis", (psi_, N.z))
    L = Yf.orientnew("L", "Axis", (theta_, Yf.x))
    R = L.orientnew("R", "Axis", (phi_, L.y))
    w_qd = R.ang_vel_in(N)
    R.set_ang_vel(N, u1 * L.x + u2 * L.y + u3 * L.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", x_ * N.x + y_ * N.y)
    P.set_vel(N, u4 * N.x + u5 * N.y)
    G = P.locatenew("G", rr * L.z)
    G.set_vel(N, P.vel(N) + me.cross(L.ang_vel_in(N), rr * L.z))
    contact = G.vel(N) + me.cross(R.ang_vel_in(N), -rr * L.z) if material else P.vel(N)
    kd = [me.dot(w_qd - R.ang_vel_in(N), e) for e in (L.x, L.y, L.z)] + \
         [x_.diff() - u4, y_.diff() - u5]
    inertia = me.inertia(L, m * rr**2 / 4, m * rr**2 / 2, m * rr**2 / 4)
    disk = me.RigidBody("disk", G, R, m, (inertia, G))
    km = me.KanesMethod(N, q_ind=[psi_, theta_, phi_, x_, y_], u_ind=[u1, u2, u3],
                        u_dependent=[u4, u5], kd_eqs=kd,
                        velocity_constraints=[me.dot(contact, N.x), me.dot(contact, N.y)])
    km.kanes_equations([disk], [(G, -m * gg * N.z)])
    return km


def test_sympys_rolling_disk_with_dependent_speeds_is_the_same_motion():
    disk = get("rolling_disk")
    eqs = from_mechanics(kane_rolling_disk(), disk, name="kane")
    assert eqs.labels[3:] == ("constraint u4 (acceleration level)",
                              "constraint u5 (acceleration level)")
    assert [c.level for c in eqs.constraints] == ["velocity", "velocity"]
    c = check_mechanics(disk, kane_rolling_disk(), name="kane")
    assert c.equivalent, str(c)
    assert c.judgement.method == "exact"
    assert "kane vs lagrange: equivalent" in str(c)


def test_sympys_rolling_disk_on_the_geometric_contact_point_is_named():
    c = check_mechanics(get("rolling_disk"), kane_rolling_disk(material=False), name="kane")
    assert not c.equivalent
    assert c.to_dict()["odd"] == ["kane"]


def test_a_kane_model_with_dependent_coordinates_keeps_its_configuration_constraint():
    """A particle (unit mass, unit weight along -y) on the line y = x, written with q2 dependent:
    the configuration constraint is kept at position level on the row of the velocity
    constraint it replaces, and the motion is the incline's: each acceleration is
    -sin(45 deg) cos(45 deg) = -1/2 by hand."""
    q1, q2 = me.dynamicsymbols("q1 q2")
    u1, u2 = me.dynamicsymbols("u1 u2")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", q1 * N.x + q2 * N.y)
    P.set_vel(N, u1 * N.x + u2 * N.y)
    km = me.KanesMethod(N, q_ind=[q1], u_ind=[u1], q_dependent=[q2], u_dependent=[u2],
                        configuration_constraints=[q2 - q1],
                        velocity_constraints=[u2 - u1],
                        kd_eqs=[q1.diff() - u1, q2.diff() - u2])
    km.kanes_equations([me.Particle("p", P, 1)], [(P, -N.y)])
    eqs = from_mechanics(km)
    x1, x2 = eqs.coordinates
    (con,) = eqs.constraints
    assert (con.name, con.level, con.label) == ("configuration q2", "position",
                                                "constraint u2 (acceleration level)")
    assert sp.expand(con.expression - (x2 - x1)) == 0
    solved = eqs.solve()
    assert solved[x1.diff(x1.args[0], 2)] == sp.Rational(-1, 2)
    assert solved[x2.diff(x2.args[0], 2)] == sp.Rational(-1, 2)


def test_sympys_lagrange_rolling_disk_with_nonholonomic_constraints():
    """sympy's LagrangesMethod with the rolling rows as ``nonhol_coneqs`` (the problem
    docstring's T and V, written again in dynamicsymbols): its mass_matrix holds the dynamic
    rows only; the bridge adds the constraints' acceleration rows and keeps them at velocity
    level.  Its multipliers are the contact forces F_x, F_y (the hand derivation's)."""
    psi_, theta_, phi_, x_, y_ = me.dynamicsymbols("psi theta phi x y")
    m, rr, gg = sp.symbols("m r g")
    s, c = sp.sin, sp.cos
    G = sp.Matrix([x_ + rr * s(theta_) * s(psi_), y_ - rr * s(theta_) * c(psi_),
                   rr * c(theta_)])
    vG = G.diff(me.dynamicsymbols._t)
    A, C = m * rr**2 / 4, m * rr**2 / 2
    d = sp.Function.diff
    T = m * (vG.T * vG)[0, 0] / 2 + (A * d(theta_)**2 + C * (d(phi_) + d(psi_) * s(theta_))**2
                                     + A * d(psi_)**2 * c(theta_)**2) / 2
    lm = me.LagrangesMethod(T - m * gg * rr * c(theta_), [psi_, theta_, phi_, x_, y_],
                            nonhol_coneqs=[d(x_) - rr * d(phi_) * c(psi_),
                                           d(y_) - rr * d(phi_) * s(psi_)])
    lm.form_lagranges_equations()
    match = {"name": "sympy_lagrange", "reactions": {"lam1": "F_x", "lam2": "F_y"}}
    eqs = from_mechanics(lm, get("rolling_disk"), **match)
    assert len(eqs.equations) == 7 and [k.level for k in eqs.constraints] == ["velocity"] * 2
    out = check_mechanics(get("rolling_disk"), lm, **match)
    assert out.equivalent, str(out)
    assert "reactions F_x, F_y of lagrange, multiplier, sympy_lagrange vs newton_euler: the " \
        "same" in str(out)
