"""Judging printed claims about a steady motion's stability: eigenvalues at a parameter value
and critical values (a weave speed, a capsize speed), like every printed answer.

A claim (:class:`~dualmech.model.problem.Published` of kind ``"eigenvalues"`` or
``"critical"``) is about the problem's declared
:attr:`~dualmech.model.problem.Problem.steady_motion`, linearised in the reference model by
:func:`~dualmech.model.stability.linearize_about` at the default parameters.  The state
matrix is exact (rational) at each rational value of the swept parameter; its eigenvalues are
computed by mpmath at :data:`DIGITS` digits, far below any printed tolerance.  Eigenvalues
that vanish at every value (a heading, a neighbouring steady motion) are counted at a generic
value and left out, as the stability study does.

* eigenvalues: right when the printed and computed nontrivial eigenvalues pair off within the
  tolerance; else wrong, with the computed ones;
* critical: right when the number of eigenvalues with a positive real part differs at the
  printed value minus and plus the tolerance (stability changes in between); else wrong,
  with the values where it does change in the declared sweep (bisected to ``1e-12``).

A claim that cannot be judged (no steady motion declared, a model that cannot be linearised
there) is "unchecked" with the reason.

Example
-------
>>> from dualmech.problems import get
>>> [v.verdict for v in judge_stability_claims(get("rolling_disk"))]
['correct', 'correct']
"""
from __future__ import annotations

import mpmath
import sympy as sp

from dualmech.model._expr import as_expr
from dualmech.model.equations import ModelError
from dualmech.model.stability import exact_number, linearize_about

__all__ = ["judge_stability_claims", "STABILITY_KINDS", "DIGITS"]

#: the kinds of printed answer judged here
STABILITY_KINDS = ("eigenvalues", "critical")
#: working precision of the eigenvalues (decimal digits)
DIGITS = 30
METHOD = f"exact linearisation, eigenvalues by mpmath ({DIGITS} digits)"


class _Spectra:
    """The reference model's linearisation about the declared steady motion; eigenvalues at
    any value of its parameter, the structural zeros left out."""

    def __init__(self, problem):
        steady = getattr(problem, "steady_motion", None)
        if steady is None:
            raise ModelError(f"problem `{problem.name}` declares no steady motion "
                             "(`steady_motion = SteadyMotion(...)`), so a stability claim has "
                             "nothing to be about.")
        self.symbol = _symbol(problem, steady)
        lo, hi = (steady.sweep[0], steady.sweep[1]) if steady.sweep else (0.0, 1.0)
        self.sweep = tuple(steady.sweep) if steady.sweep else ()
        generic = exact_number(lo + (hi - lo) * 0.3719) if self.symbol is not None else None
        values = {s: exact_number(v) for s, v in problem.defaults().items()
                  if s != self.symbol}
        eqs = problem.model(problem.reference)
        self.lin = linearize_about(eqs, steady.about, values, self.symbol, generic=generic)
        self.memo: dict = {}
        eig = self.all(generic)
        scale = max([1] + [abs(e) for e in eig])
        self.zeros = sum(1 for e in eig if abs(e) <= mpmath.mpf(10) ** (8 - DIGITS) * scale)

    def all(self, value) -> list:
        key = None if value is None else exact_number(value)
        hit = self.memo.get(key)
        if hit is None:
            A = self.lin.at(key) if self.symbol is not None else self.lin.at()
            with mpmath.workdps(DIGITS + 10):
                M = mpmath.matrix([[mpmath.mpmathify(sp.N(x, DIGITS + 10)) for x in row]
                                   for row in A.tolist()])
                hit = list(mpmath.eig(M, left=False, right=False)) if A.rows else []
            self.memo[key] = hit
        return hit

    def nontrivial(self, value) -> list:
        return sorted(self.all(value), key=abs)[self.zeros:]

    def unstable(self, value) -> int:
        eig = self.nontrivial(value)
        scale = max([1] + [abs(e) for e in eig])
        return sum(1 for e in eig if mpmath.re(e) > mpmath.mpf(10) ** (10 - DIGITS) * scale)

    def criticals(self, lo: float, hi: float, count: int) -> list[float]:
        """Values in ``[lo, hi]`` where the number of unstable eigenvalues changes."""
        grid = [lo + (hi - lo) * k / (count - 1) for k in range(count)]
        counts = [self.unstable(v) for v in grid]
        out = []
        for a, b, ca, cb in zip(grid, grid[1:], counts, counts[1:]):
            if ca == cb:
                continue
            for _ in range(60):
                if b - a <= 1e-12 * max(1.0, abs(a)):
                    break
                mid = (a + b) / 2
                a, b = (mid, b) if self.unstable(mid) == ca else (a, mid)
            out.append((a + b) / 2)
        return out


def _symbol(problem, steady):
    name = steady.parameter
    if not name:
        return None
    for p in problem.parameters:
        if p.symbol.name == name:
            return p.symbol
    for value in steady.about.values():
        for s in as_expr(value).free_symbols:
            if s.name == name:
                return s
    raise ModelError(f"the steady motion's parameter {name!r} is neither a parameter of "
                     f"`{problem.name}` nor a symbol of the steady motion.")


def judge_stability_claims(problem, printed: list | None = None) -> list:
    """Verdicts (:class:`~dualmech.verify.published.PublishedVerdict`) on the stability
    claims among ``printed`` (default ``problem.published()``), in their order."""
    from dualmech.verify.published import PublishedVerdict
    pubs = [p for p in (problem.published() if printed is None else printed)
            if p.kind in STABILITY_KINDS]
    if not pubs:
        return []
    try:
        spectra = _Spectra(problem)
    except (ModelError, ValueError, ZeroDivisionError) as exc:
        return [PublishedVerdict(p.label, p.where, "unchecked",
                                 f"NOT CHECKED, the steady motion could not be linearised: {exc}",
                                 "none") for p in pubs]
    out = []
    for pub in pubs:
        try:
            verdict, detail = (_eigenvalues if pub.kind == "eigenvalues" else _critical)(
                spectra, pub)
        except (ModelError, ValueError, ZeroDivisionError) as exc:
            verdict, detail = "unchecked", f"NOT CHECKED: {exc}"
        out.append(PublishedVerdict(pub.label, pub.where, verdict, detail, METHOD))
    return out


def _eigenvalues(spectra: _Spectra, pub) -> tuple[str, str]:
    at = float(pub.at)
    got = spectra.nontrivial(exact_number(as_expr(pub.at)))
    want = [complex(p) for p in pub.printed]
    shown = ", ".join(_show(e) for e in sorted(got, key=lambda e: (float(mpmath.re(e)),
                                                                   float(mpmath.im(e)))))
    name = spectra.symbol.name if spectra.symbol is not None else "the parameter"
    if len(got) != len(want):
        return "wrong", (f"at {name} = {at:g} the steady motion has {len(got)} nonzero "
                         f"eigenvalues, not {len(want)}: {shown}")
    left, worst = list(got), 0.0
    for w in want:
        k = min(range(len(left)), key=lambda i: abs(left[i] - w))
        worst = max(worst, float(abs(left.pop(k) - w)))
    if worst <= pub.tolerance:
        return "correct", (f"at {name} = {at:g} every printed eigenvalue is within "
                           f"{worst:.1e} of a computed one (tolerance {pub.tolerance:g})")
    return "wrong", (f"at {name} = {at:g} the computed eigenvalues are {shown}; the printed "
                     f"ones differ by up to {worst:.3g} (tolerance {pub.tolerance:g})")


def _critical(spectra: _Spectra, pub) -> tuple[str, str]:
    if spectra.symbol is None:
        raise ModelError("the steady motion has no parameter, so it has no critical value.")
    name, tol = spectra.symbol.name, pub.tolerance
    value = float(pub.printed[0])
    below, above = spectra.unstable(value - tol), spectra.unstable(value + tol)
    if below != above:
        return "correct", (f"{below} unstable eigenvalue(s) at {name} = {value - tol:.12g}, "
                           f"{above} at {value + tol:.12g}: stability changes within the "
                           f"tolerance {tol:g}")
    lo, hi, count = spectra.sweep or (value / 2, value * 2, 21)
    lo, hi = float(min(lo, value - tol)), float(max(hi, value + tol))
    found = spectra.criticals(lo, hi, max(3, min(int(count), 41)))
    where = (f"it changes at {name} = " + ", ".join(f"{c:.12g}" for c in found)) if found \
        else "it does not change there"
    return "wrong", (f"{below} unstable eigenvalue(s) both at {name} = {value - tol:.12g} and "
                     f"{value + tol:.12g}: stability does not change within {tol:g} of "
                     f"{value:g}; on {name} in [{lo:g}, {hi:g}] {where}")


def _show(e) -> str:
    re, im = float(mpmath.re(e)), float(mpmath.im(e))
    return f"{re:.12g}" if im == 0 else f"{re:.12g}{'+' if im > 0 else '-'}{abs(im):.12g}i"
