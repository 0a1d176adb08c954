"""Stability of a problem's steady motion over a parameter sweep: eigenvalues, the values
where stability changes, every derivation linearised and compared.

:func:`stability` linearises each model of a problem about the same steady motion
(:func:`dualmech.model.stability.linearize_about`; a model in other coordinates gets the
steady motion through the problem's coordinate map), computes the reference model's
eigenvalues (NumPy) at each swept value and finds the critical values:

* "an eigenvalue passes through zero" -- the lowest nonzero coefficient of the exact
  characteristic polynomial changes sign (bracketed on the sweep, refined by ``brentq``); a
  real pair meeting at zero and leaving as an imaginary pair (a conservative system becoming
  stable) is said so;
* "real part crosses zero" -- the largest real part of a complex pair changes sign
  (``brentq`` on it);
* "a pair becomes complex" / "a pair becomes real" -- the number of complex eigenvalues
  changes (bisection).

Eigenvalues that vanish at every value of the parameter (a heading nothing depends on, a
neighbouring steady motion, a conserved quantity) are counted once, exactly, from the
characteristic polynomial at a generic rational value (past :data:`EXACT_SIZE` states,
numerically), and left out of the verdicts.  The
derivations' eigenvalues are compared at the start, middle and end of the sweep.

Example
-------
>>> from dualmech.problems import get
>>> study = stability(get("pendulum_particle"))
>>> study.derivations["agree"], [round(float(abs(e)), 6) for e in study.eigenvalues[0]]
(True, [3.132092, 3.132092])
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from collections.abc import Mapping

import numpy as np
import sympy as sp
from scipy.optimize import brentq

from dualmech.model._expr import as_expr
from dualmech.model.equations import ModelError
from dualmech.model.stability import SteadyLinearisation, exact_number, linearize_about
from dualmech.numeric.simulation import problem_parameters

__all__ = ["StabilityStudy", "Critical", "stability", "steady_state_from_names",
           "root_locus_chart"]


@dataclass(frozen=True)
class Critical:
    """A parameter value where the eigenvalues change character."""

    value: float
    kind: str
    stable_below: bool
    stable_above: bool

    def as_dict(self) -> dict:
        return {"value": self.value, "kind": self.kind, "stable_below": self.stable_below,
                "stable_above": self.stable_above}


@dataclass
class StabilityStudy:
    """The result of :func:`stability`; ``str()`` is the report, :meth:`as_dict` the JSON."""

    name: str
    model: str
    why: str
    parameter: str | None
    values: list
    eigenvalues: list
    trivial_zeros: int
    stable: list
    critical: list
    linearisation: SteadyLinearisation
    derivations: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        lin = self.linearisation
        return {"name": self.name, "model": self.model, "steady_motion": self.why,
                "parameter": self.parameter, "values": self.values,
                "eigenvalues": [[[float(e.real), float(e.imag)] for e in row]
                                for row in self.eigenvalues],
                "trivial_zeros": self.trivial_zeros, "stable": self.stable,
                "critical": [c.as_dict() for c in self.critical],
                "states": list(lin.states), "dropped": list(lin.dropped),
                "dependent": list(lin.dependent),
                "constraints": [{"row": r, "level": k} for r, k in lin.constraints],
                "matrix": None if lin.symbolic is None else str(lin.symbolic.tolist()),
                "derivations": self.derivations}

    def __str__(self) -> str:
        lin, p = self.linearisation, self.parameter
        lines = [f"{self.name}: stability of {self.why or 'the steady motion'} "
                 f"(model {self.model})",
                 f"  state: {', '.join(lin.states)}"
                 + (f"; cyclic, dropped: {', '.join(lin.dropped)}" if lin.dropped else "")
                 + (f"; dependent: {', '.join(lin.dependent)}" if lin.dependent else "")]
        if lin.constraints:
            lines.append("  constraints: " + "; ".join(f"[{r}] {k}" for r, k in lin.constraints))
        if lin.symbolic is not None:
            lines.append(f"  A{f'({p})' if p else ''} = {lin.symbolic.tolist()}")
        lines.append(f"  eigenvalues zero at every value (left out of the verdict): "
                     f"{self.trivial_zeros}")
        for v, eig, ok in zip(self.values, self.eigenvalues, self.stable):
            head = f"{p} = {v:<10.6g}" if p else "  at the point"
            lines.append(f"  {head} {'stable  ' if ok else 'unstable'}  "
                         + "  ".join(_complex(e) for e in eig))
        for c in self.critical:
            lines.append(f"  critical: {p} = {c.value:.12g} ({c.kind}; "
                         f"{'stable' if c.stable_below else 'unstable'} below, "
                         f"{'stable' if c.stable_above else 'unstable'} above)")
        if not self.critical and p:
            lines.append(f"  critical: none in the sweep of {p}")
        lines.append("  derivations: " + self.derivations.get("summary", ""))
        return "\n".join(lines)


def _complex(e) -> str:
    return f"{e.real:+.6g}" + (f"{e.imag:+.6g}j" if e.imag else "")


# -- the steady motion --------------------------------------------------------------------
def steady_state_from_names(problem, numbers: Mapping[str, float]) -> dict:
    """``{"theta": 0.1, "theta_dot": 2}`` (or ``"theta'"``) as ``{q: 0.1, q': 2}`` in the
    reference model's coordinates; an unknown name is refused (``ValueError``).

    >>> from dualmech.problems import get
    >>> steady_state_from_names(get("simple_pendulum"), {"theta_dot": 0})
    {Derivative(theta(t), t): 0}
    """
    coords = problem.model(problem.reference).coordinates
    known = {}
    for q in coords:
        name = q.func.__name__
        known[name] = q
        known[f"{name}_dot"] = known[f"{name}'"] = q.diff(q.args[0])
    out = {}
    for name, value in numbers.items():
        if name not in known:
            raise ValueError(f"`--about`: {name!r} is not a coordinate of `{problem.name}` or "
                             f"its rate; the coordinates are "
                             f"{', '.join(q.func.__name__ for q in coords)} (rates: name_dot).")
        out[known[name]] = exact_number(value)
    return out


def _about_in(problem, eqs, about: dict) -> dict:
    """``about`` (reference coordinates) for model ``eqs`` (via the coordinate map)."""
    ref = problem.model(problem.reference)
    if set(eqs.coordinates) == set(ref.coordinates):
        return dict(about)
    mapping = problem.coordinate_maps().get(eqs.name)
    if mapping is None:
        raise ModelError(f"model `{eqs.name}` uses other coordinates and the problem gives no "
                         "coordinate map for it.")
    rules = {}
    for q in ref.coordinates:
        rules[q.diff(q.args[0])] = about.get(q.diff(q.args[0]), 0)
    values = {q: about.get(q, 0) for q in ref.coordinates}
    out = {}
    for q, expr in mapping.items():
        rate = as_expr(expr).diff(q.args[0])
        out[q] = as_expr(expr).subs(values)
        out[q.diff(q.args[0])] = rate.subs(rules).subs(values)
    return out


def _parameter(problem, name: str | None, about: dict):
    if not name:
        return None
    for p in problem.parameters:
        if p.symbol.name == name:
            return p.symbol
    for value in about.values():
        for s in as_expr(value).free_symbols:
            if s.name == name:
                return s
    raise ValueError(f"the swept parameter {name!r} is neither a parameter of `{problem.name}` "
                     f"({', '.join(p.symbol.name for p in problem.parameters)}) nor a symbol "
                     "of the steady motion.")


# -- eigenvalues --------------------------------------------------------------------------
#: largest reduced state whose characteristic polynomial is formed exactly
EXACT_SIZE = 10


class _Spectrum:
    """Eigenvalues of one linearisation, with the structural zeros counted exactly."""

    def __init__(self, lin: SteadyLinearisation, generic):
        self.lin = lin
        lam = sp.Symbol("lambda")
        size = len(lin.states)
        self.exact = size <= EXACT_SIZE
        if not self.exact:   # too big for an exact characteristic polynomial: numbers
            self._matrix = (sp.lambdify([lin.parameter], lin.symbolic, "numpy")
                            if lin.symbolic is not None and lin.parameter is not None else None)
            eig = self.all(generic)
            self.zeros = int(np.sum(np.abs(eig) <= 1e-9 * max(1.0, float(np.max(np.abs(eig))))))
            self._coefficient = lambda v: float(np.real(np.prod(self.nontrivial(v))))
            return
        if lin.symbolic is not None and lin.parameter is not None:
            self._matrix = sp.lambdify([lin.parameter], lin.symbolic, "numpy")
            poly = sp.Poly(lin.symbolic.charpoly(lam).as_expr(), lam)
            coeffs = poly.all_coeffs()[::-1]
            at = {lin.parameter: generic}
            self.zeros = next(k for k, c in enumerate(coeffs)
                              if sp.cancel(c).subs(at) != 0) if any(
                sp.cancel(c).subs(at) != 0 for c in coeffs) else len(coeffs) - 1
            self._coefficient = sp.lambdify([lin.parameter], sp.cancel(coeffs[self.zeros]))
        else:
            self._matrix = None
            coeffs = lin.at(generic).charpoly(lam).all_coeffs()[::-1]
            self.zeros = next(k for k, c in enumerate(coeffs) if c != 0)
            self._coefficient = None

    def matrix(self, value) -> np.ndarray:
        if self.lin.parameter is None:
            return np.array(self.lin.at().evalf(30), dtype=float)
        if self._matrix is not None:
            return np.array(self._matrix(value), dtype=float)
        return np.array(self.lin.at(value).evalf(30), dtype=float)

    def all(self, value) -> np.ndarray:
        return np.linalg.eigvals(self.matrix(value))

    def nontrivial(self, value) -> np.ndarray:
        eig = self.all(value)
        return eig[np.argsort(np.abs(eig))][self.zeros:]

    def coefficient(self, value) -> float:
        """The lowest nonzero coefficient of the characteristic polynomial at ``value`` (past
        :data:`EXACT_SIZE`, the product of the nonzero eigenvalues: the same sign)."""
        if self._coefficient is not None:
            return float(self._coefficient(value))
        lam = sp.Symbol("lambda")
        return float(self.lin.at(value).charpoly(lam).all_coeffs()[::-1][self.zeros])


def _tol(eig) -> float:
    return 1e-7 * max(1.0, float(np.max(np.abs(eig)))) if len(eig) else 1e-7


def _stable(eig) -> bool:
    return bool(len(eig) == 0 or np.max(eig.real) <= _tol(eig))


def _complex_count(eig) -> int:
    return int(np.sum(np.abs(eig.imag) > _tol(eig)))


def _real_count(eig) -> int:
    return len(eig) - _complex_count(eig)


def _hopf(eig) -> float | None:
    pairs = eig[np.abs(eig.imag) > _tol(eig)]
    return float(np.max(pairs.real)) if len(pairs) else None


def _critical(spec: _Spectrum, values, nontrivial, stable) -> list[Critical]:
    out = []
    coef = [spec.coefficient(v) for v in values]
    for i in range(len(values) - 1):
        a, b = values[i], values[i + 1]
        ea, eb = nontrivial[i], nontrivial[i + 1]
        crossed = False
        if coef[i] == 0 or coef[i] * coef[i + 1] < 0:
            before = i - 1 if coef[i] == 0 and i > 0 else i   # a zero on a sweep value
            root = a if coef[i] == 0 else brentq(spec.coefficient, a, b, xtol=1e-14, rtol=1e-15)
            eb4 = nontrivial[before]
            drop = _real_count(eb4) - _real_count(eb)
            kind = ("a real pair meets at zero and becomes imaginary" if drop == 2 else
                    "an imaginary pair meets at zero and becomes real" if drop == -2 else
                    "a real eigenvalue crosses zero")
            out.append(Critical(float(root), kind, stable[before], stable[i + 1]))
            crossed = True
        ha, hb = _hopf(ea), _hopf(eb)
        if ha is not None and hb is not None and (ha - _tol(ea)) * (hb - _tol(eb)) < 0 \
                and abs(ha) > _tol(ea) and abs(hb) > _tol(eb):
            def f(v):
                return _hopf(spec.nontrivial(v)) or 0.0
            out.append(Critical(float(brentq(f, a, b, xtol=1e-14)),
                                "real part crosses zero (a complex pair)", stable[i],
                                stable[i + 1]))
        elif not crossed and _complex_count(ea) != _complex_count(eb):
            lo, hi, ca = a, b, _complex_count(ea)
            for _ in range(60):
                mid = (lo + hi) / 2
                lo, hi = (mid, hi) if _complex_count(spec.nontrivial(mid)) == ca else (lo, mid)
            kind = "a pair becomes complex" if _complex_count(eb) > ca else "a pair becomes real"
            out.append(Critical((lo + hi) / 2, kind, stable[i], stable[i + 1]))
    return out


# -- the study ----------------------------------------------------------------------------
def stability(problem, about: Mapping | None = None, parameter: str | None = None,
              sweep: tuple | None = None, model: str | None = None,
              independent=None, params: Mapping | None = None) -> StabilityStudy:
    """Linearise every model of ``problem`` about a steady motion; eigenvalues over a sweep.

    ``about``, ``parameter`` and ``sweep`` default to the problem's declared
    :class:`~dualmech.model.facts.SteadyMotion` (else: at rest, every coordinate zero, at
    the default parameters).  ``model`` is the one whose eigenvalues are reported (default
    the reference); every model that can be linearised is compared with it.  ``params``
    (name or symbol -> number) replaces default parameter values; ``independent`` names the
    reported model's independent coordinates and speeds (see
    :func:`~dualmech.model.stability.linearize_about`).
    """
    declared = getattr(problem, "steady_motion", None)
    why = ""
    if about is None and declared is not None:
        about, why = declared.about, declared.why
        parameter = parameter if parameter is not None else (declared.parameter or None)
        sweep = sweep if sweep is not None else (declared.sweep or None)
    about = dict(about or {})
    why = why or ("the state " + ", ".join(f"{k} = {v}" for k, v in about.items())
                  if about else "the state at rest with every coordinate zero")
    symbol = _parameter(problem, parameter, about)
    if sweep and symbol is None:
        raise ValueError("a sweep needs a parameter: give PARAM=START:STOP:N.")
    values = [float(v) for v in np.linspace(*sweep)] if sweep else [None]
    defaults = {s: v for s, v in problem_parameters(problem, params, check_ranges=False).items()
                if s != symbol}
    lo, hi = (values[0], values[-1]) if sweep else (1, 1)
    generic = exact_number(lo + (hi - lo) * 0.3719) if sweep else None
    main = model or problem.reference
    lins, failed = {}, {}
    for name, eqs in problem.models().items():
        try:
            lins[name] = linearize_about(eqs, _about_in(problem, eqs, about), defaults, symbol,
                                         independent if name == main else None, generic)
        except ModelError as exc:
            if name == main:
                raise
            failed[name] = str(exc)
    if main not in lins:
        raise ModelError(f"problem `{problem.name}` has no model {main!r}.")
    specs = {name: _Spectrum(lin, generic) for name, lin in lins.items()}
    spec = specs[main]
    nontrivial = [spec.nontrivial(v) for v in values]
    stable = [_stable(e) for e in nontrivial]
    critical = _critical(spec, values, nontrivial, stable) if sweep else []
    study = StabilityStudy(problem.name, main, why, parameter if symbol is not None else None,
                           values, [spec.all(v) for v in values], spec.zeros, stable,
                           critical, lins[main])
    study.derivations = _compare(specs, main, values, failed, study.parameter)
    return study


def _compare(specs: dict, main: str, values, failed: dict, p) -> dict:
    at = sorted({values[0], values[len(values) // 2], values[-1]}, key=lambda v: v or 0)
    worst, scale = 0.0, 1.0
    for v in at:
        ref = _sorted(specs[main].nontrivial(v))
        scale = max(scale, float(np.max(np.abs(ref))) if len(ref) else 1.0)
        for spec in specs.values():
            other = _sorted(spec.nontrivial(v))
            gap = (0.0 if not len(ref) else float(np.max(np.abs(other - ref)))) \
                if len(other) == len(ref) else math.inf
            worst = max(worst, gap)
    agree = worst <= 1e-9 * scale
    where = ", ".join("the point" if v is None else f"{p} = {v:g}" for v in at)
    names = ", ".join(specs)
    summary = (f"{names} linearised; their nonzero eigenvalues "
               + (f"agree at {where} (largest difference {worst:.1e})" if agree else
                  f"DISAGREE at {where} (largest difference {worst:.3g})")
               if len(specs) > 1 else f"only {names} could be linearised")
    if failed:
        summary += "; not linearised: " + "; ".join(f"{k} ({v})" for k, v in failed.items())
    return {"models": list(specs), "agree": bool(agree) if len(specs) > 1 else None,
            "max_difference": worst, "at": at, "not_linearised": failed, "summary": summary}


def _sorted(eig) -> np.ndarray:
    return np.array(sorted(eig, key=lambda e: (round(e.real, 6), round(e.imag, 6))))


def root_locus_chart(study: StabilityStudy, path) -> str:
    """Write the root locus (eigenvalues coloured by the parameter) as a PNG; return ``path``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    values = [0.0 if v is None else v for v in study.values]
    re = np.concatenate([e.real for e in study.eigenvalues])
    im = np.concatenate([e.imag for e in study.eigenvalues])
    col = np.concatenate([[v] * len(e) for v, e in zip(values, study.eigenvalues)])
    sc = ax.scatter(re, im, c=col, s=12, cmap="viridis")
    if study.parameter:
        fig.colorbar(sc, ax=ax, label=study.parameter)
    ax.axvline(0, color="k", lw=0.8)
    ax.axhline(0, color="0.7", lw=0.5)
    ax.set_xlabel("real part (1/s)")
    ax.set_ylabel("imaginary part (rad/s)")
    crit = "; ".join(f"{study.parameter} = {c.value:.6g}" for c in study.critical)
    ax.set_title(f"{study.name}: root locus ({study.model})" + (f"\ncritical: {crit}" if crit
                                                                else ""), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return str(path)
