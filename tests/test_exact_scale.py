"""The exact verdict through square roots at bicycle scale (dualmech.exact.radicals.proportional).

The front wheel's contact point of a bicycle is the wheel centre plus ``r_F`` times the unit
vector in the wheel plane pointing down: ``(e g - z) / |e g - z|`` for the wheel axis ``g`` and
the ground's normal ``z``, ``e = g . z``.  Its norm is ``sqrt(1 - e^2)``, a trigonometric
polynomial of roll, pitch (plus the head angle) and steer; one derivation writes that radicand,
another the sum of the squares of the two other components (equal by ``|z| = 1``, written
differently), and the two roots' product is a perfect square too large to factor.  Reference:
the identity ``g_x^2 + g_y^2 + g_z^2 = 1`` of a column of a rotation matrix.
"""
import random

import pytest
import sympy as sp

from dualmech.exact import radicals
from dualmech.exact.form import ExactForm, is_zero

phi, delta, theta, lam = sp.symbols("phi delta theta lambda")     # roll, steer, pitch, head
r_f = sp.Symbol("r_F", positive=True)
SYMBOLS = [phi, delta, theta, lam, r_f]


def _front_contact():
    """Ground z in the fork's frame (roll about x, pitch + head about y, steer about x), and
    the two radicands of the contact direction's norm."""
    rot = sp.rot_axis1(phi).T * sp.rot_axis2(theta + lam).T * sp.rot_axis1(delta).T
    z = rot.T * sp.Matrix([0, 0, 1])
    one = 1 - z[1] ** 2                        # 1 - e^2
    two = sp.expand(z[0] ** 2 + z[2] ** 2)     # the other two components, expanded
    down = z[1] * sp.Matrix([0, 1, 0]) - z
    return down, one, two


def _decide(exprs, points=4):
    form = ExactForm.build(exprs, SYMBOLS)
    rng = random.Random(5)
    out = []
    for _ in range(points):
        point = form.sample(rng)
        out.append((form.evaluate(point), form.certain(point)))
    return form, out


def test_front_contact_written_two_ways_is_an_exact_identity():
    down, one, two = _front_contact()
    first = r_f * down / sp.sqrt(one)
    second = r_f * down * sp.sqrt(two) / two
    velocity = [sp.diff(a - b, phi) + sp.diff(a - b, delta) for a, b in zip(first, second)]
    form, values = _decide([a - b for a, b in zip(first, second)] + velocity)
    assert form.method == "exact", form.notes
    assert all(is_zero(v) for vals, _ in values for v in vals)
    assert form.false_equal_bound(len(values)) < 1e-20


def test_a_wrong_front_contact_is_a_certain_counter_example():
    down, one, two = _front_contact()
    first = r_f * down / sp.sqrt(one)
    # the second derivation dropped the steer from one term of its norm: a wrong model
    wrong = two.subs(sp.cos(delta) ** 2, 1)
    second = r_f * down * sp.sqrt(wrong) / wrong
    form, values = _decide([a - b for a, b in zip(first, second)] + [sp.sqrt(two) - sp.sqrt(one)])
    assert form.method == "exact", form.notes
    for vals, certain in values:
        # (the middle component of ``down`` is 0 in both: e - e)
        assert certain and not is_zero(vals[0]) and not is_zero(vals[2])
        assert is_zero(vals[1]) and is_zero(vals[3])


def test_constant_multiples_share_one_root():
    # sqrt(8 X) = 2 sqrt(2) sqrt(X): a non-square ratio becomes a constant root
    _, one, two = _front_contact()
    form, values = _decide([sp.sqrt(8 * two) - 2 * sp.sqrt(2) * sp.sqrt(one),
                            sp.sqrt(8 * two) - 2 * sp.sqrt(one)])
    assert form.method == "exact", form.notes
    for vals, _ in values:
        assert is_zero(vals[0]) and not is_zero(vals[1])


def test_a_wrong_screen_is_caught_at_every_point(monkeypatch):
    # radicands the screen wrongly takes as equal: every point fails the exact check, the
    # exact method refuses and the interval method (evidence, said so) takes over
    monkeypatch.setattr(radicals, "proportional",
                        lambda b, rads: [(0, 1)] * len(rads))
    import dualmech.exact.sample_space as space
    monkeypatch.setattr(space, "proportional", radicals.proportional)
    a = sp.Symbol("a", positive=True)
    form = ExactForm.build([sp.sqrt(a + 1) - sp.sqrt(a + 2)], [a])
    assert form.method == "interval"
    assert any("screened as multiples of one another are not" in n for n in form.notes), \
        form.notes


@pytest.mark.parametrize("expr", [sp.sqrt(phi ** 2 + 1) * sp.sqrt(-phi ** 2 - 1)])
def test_opposite_radicands_are_not_merged(expr):
    # X and -X: never both positive, the ratio is negative: no shared root is invented
    form = ExactForm.build([expr], [phi])
    assert not form._world or not form._world.twins


def test_mpmath_values_of_a_sum_too_long_to_compile():
    """``lambdify`` of 4000 terms raises RecursionError in CPython's compiler; the flat
    program gives the values.  Reference: mpmath's own sum of the same terms."""
    import mpmath
    from dualmech.exact.mp_program import flat_program, mp_function
    x, y = sp.symbols("x y")
    n = 4000
    big = sp.Add(*[x ** k * y ** (k % 7) / (k + 1) for k in range(n)])
    fn = flat_program([x, y], [big, sp.cos(x) ** 2 + sp.sin(x) ** 2])
    half, two = mpmath.mpf("0.5"), mpmath.mpf(2)
    with mpmath.workdps(30):
        ref = mpmath.fsum(half ** k * two ** (k % 7) / (k + 1) for k in range(n))
        got = fn(half, two)
        assert abs(got[0] - ref) < mpmath.mpf(10) ** -28 and abs(got[1] - 1) < 1e-28
    assert callable(mp_function([x], [x + 1]))
    with pytest.raises(ValueError, match="no mpmath evaluation"):
        flat_program([x], [sp.Piecewise((x, x > 0), (0, True))])


def test_a_wrong_model_too_long_to_compile_still_names_its_wrong_rows(monkeypatch):
    """Where lambdify's source cannot be compiled (RecursionError, as for a bicycle-size
    wrong model), the explanation runs on the flat program and names the same rows: the toy
    car's Lagrangian without its cos^2 term is wrong in both its equations (test_blame)."""
    from dualmech.exact import mp_program
    from dualmech.verify.check import compare
    from test_blame import ToyCarNoCos2

    def refuse(args, exprs):
        raise RecursionError("maximum recursion depth exceeded during compilation")

    flat = []
    original = mp_program.flat_program

    def counted(args, exprs):
        flat.append(len(exprs))
        return original(args, exprs)

    monkeypatch.setattr(mp_program, "_lambdified", refuse)
    monkeypatch.setattr(mp_program, "flat_program", counted)
    c = compare(ToyCarNoCos2())
    assert not c.equivalent and c.judgement.odd == ["lagrange"]
    assert {mm.equation for mm in c.mismatches if mm.model == "lagrange"} \
        == {"Lagrange, theta", "Lagrange, phi"}
    assert flat, "the flat program was not used"
