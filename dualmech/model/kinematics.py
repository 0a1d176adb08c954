"""Frames chained by rotation matrices, vectors in any frame, and point kinematics.

A :class:`Frame` is its rotation matrix relative to its parent plus the position of its
origin.  The matrix ``R`` maps child components to parent components, ``v_parent = R v_child``:
its *columns* are the child's unit vectors written in the parent.  (Course notes often print
the transpose, whose rows are the child's unit vectors.)

Angular velocity comes from the matrices, ``skew(w) = R^T dR/dt`` in child axes, and the time
derivative of a vector in any frame follows the transport theorem
``d/dt|_A v = d/dt|_B v + w_{B/A} x v``.

Example
-------
The toy car of MIT 2.003J quiz 1: the track frame A turns by ``phi`` about the ground ``I``
axis, the car frame B by ``theta`` about ``j_A``.

>>> import sympy as sp
>>> from dualmech.model.kinematics import Frame, rot_x, rot_y, coordinate, t
>>> phi, theta = coordinate("phi"), coordinate("theta")
>>> O = Frame.ground("O")
>>> A = O.child("A", rot_x(phi))
>>> B = A.child("B", rot_y(theta))
>>> B.z.express(O).components.T
Matrix([[sin(theta(t)), -sin(phi(t))*cos(theta(t)), cos(phi(t))*cos(theta(t))]])
>>> B.ang_vel_in(O).express(B).simplify().components.T
Matrix([[cos(theta(t))*Derivative(phi(t), t), Derivative(theta(t), t), sin(theta(t))*Derivative(phi(t), t)]])
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from typing import Iterable

import symengine as se
import sympy as sp

from dualmech.model._algebra import merge_names, names_of, time_se, to_se, to_sp
from dualmech.model._expr import as_expr, as_matrix, refuse_text, refuse_text_in

__all__ = [
    "t", "coordinate", "rate", "rot_x", "rot_y", "rot_z", "rot_axis", "skew", "unskew",
    "Frame", "Vector", "Point", "RelativeMotion",
]

#: The time symbol shared by every model.
t = sp.Symbol("t", real=True)


def coordinate(name: str) -> sp.Expr:
    """A generalised coordinate ``name(t)`` as an undefined function of time.

    Examples
    --------
    >>> theta = coordinate("theta")
    >>> theta, rate(theta)
    (theta(t), Derivative(theta(t), t))
    """
    return sp.Function(name, real=True)(t)


def rate(q, n: int = 1) -> sp.Expr:
    """The ``n``-th time derivative of ``q``: ``q'`` for ``n = 1``, ``q''`` for ``n = 2``.

    ``q`` is a coordinate (:func:`coordinate`) or any expression of ``t``.

    Examples
    --------
    >>> theta = coordinate("theta")
    >>> rate(theta)
    Derivative(theta(t), t)
    >>> rate(sp.sin(theta), 2) == sp.sin(theta).diff(t, 2)
    True
    """
    if not isinstance(n, int) or isinstance(n, bool) or n < 1:
        raise ValueError(f"`n` must be a positive integer, got {n!r}.")
    return as_expr(q).diff(t, n)


def rot_x(angle) -> sp.Matrix:
    """Rotation by ``angle`` about the x axis (columns: the rotated axes in the old frame)."""
    angle = as_expr(angle)
    c, s = sp.cos(angle), sp.sin(angle)
    return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_y(angle) -> sp.Matrix:
    """Rotation by ``angle`` about the y axis."""
    angle = as_expr(angle)
    c, s = sp.cos(angle), sp.sin(angle)
    return sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rot_z(angle) -> sp.Matrix:
    """Rotation by ``angle`` about the z axis (columns: the rotated axes in the old frame).

    Examples
    --------
    >>> import sympy as sp
    >>> rot_z(sp.pi / 2)
    Matrix([
    [0, -1, 0],
    [1,  0, 0],
    [0,  0, 1]])
    """
    angle = as_expr(angle)
    c, s = sp.cos(angle), sp.sin(angle)
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


@refuse_text
def rot_axis(axis, angle) -> sp.Matrix:
    """Rotation by ``angle`` about the unit vector ``axis`` (Rodrigues' formula).

    ``axis`` is a 3-sequence of components; it must have unit length (checked when the
    components are numbers).
    """
    if isinstance(axis, (str, bytes, bytearray)):
        raise TypeError(f"`axis` of rot_axis() got the text {axis!r:.60}; give its three "
                        "components as numbers or sympy expressions.")
    n = sp.Matrix([as_expr(c) for c in axis])
    angle = as_expr(angle)
    if n.shape != (3, 1):
        raise ValueError("`axis` must have 3 components.")
    norm2 = sp.nsimplify(sum(c**2 for c in n)) if all(c.is_number for c in n) else None
    if norm2 is not None and sp.simplify(norm2 - 1) != 0:
        raise ValueError(f"`axis` must be a unit vector; its squared length is {norm2}.")
    c, s = sp.cos(angle), sp.sin(angle)
    return c * sp.eye(3) + s * skew(n) + (1 - c) * (n * n.T)


@refuse_text
def skew(w) -> sp.Matrix:
    """The matrix ``W`` with ``W v = w x v``."""
    w = list(w)
    return sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def unskew(W: sp.Matrix) -> sp.Matrix:
    """The vector ``w`` of a skew-symmetric matrix ``W = skew(w)``."""
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


@refuse_text_in
class Frame:
    """A reference frame: a rotation matrix and an origin relative to a parent frame.

    Build frames with :meth:`Frame.ground` and :meth:`Frame.child`; do not call the
    constructor directly.  The products of rotation matrices down a chain are formed in
    symengine (:mod:`dualmech.model._algebra`) and converted to sympy only when asked for.

    Attributes ``x``, ``y``, ``z`` are the frame's unit vectors; :meth:`vector` builds a vector
    from components along them; :meth:`ang_vel_in` is the angular velocity relative to another
    frame of the same chain (from the rotation matrices: ``skew(w) = R^T dR/dt``).

    Examples
    --------
    A track turning at the rate ``phi'`` about the vertical, and a car tilted on it:

    >>> from dualmech import Frame, coordinate, rot_x, rot_z
    >>> phi, theta = coordinate("phi"), coordinate("theta")
    >>> O = Frame.ground("O")
    >>> A = O.child("A", rot_z(phi))
    >>> B = A.child("B", rot_x(theta))
    >>> B.ang_vel_in(O).express(B).components.T
    Matrix([[Derivative(theta(t), t), sin(theta(t))*Derivative(phi(t), t), cos(theta(t))*Derivative(phi(t), t)]])
    """

    def __init__(self, name: str, parent: Frame | None, rotation: sp.Matrix,
                 origin: "Vector | None"):
        self.name = name
        self.parent = parent
        self.rotation = as_matrix(rotation)
        if self.rotation.shape != (3, 3):
            raise ValueError(f"the rotation of frame `{name}` must be 3x3, "
                             f"got {self.rotation.shape}.")
        self._origin = origin
        self._rot = None          # (symengine matrix, names), built on first use
        self._root = None
        self._dcm: dict = {}

    def __repr__(self) -> str:
        return f"Frame({self.name!r})"

    # -- construction ------------------------------------------------------------------
    @classmethod
    def ground(cls, name: str = "O") -> "Frame":
        """The inertial frame, root of every chain."""
        return cls(name, None, sp.eye(3), None)

    def child(self, name: str, rotation=None, origin: "Vector | None" = None) -> "Frame":
        """A frame rotated by ``rotation`` relative to this one, origin at ``origin``.

        ``origin`` is the position of the child's origin relative to this frame's origin
        (any frame's vector); the default is the same origin.
        """
        rotation = sp.eye(3) if rotation is None else rotation
        return Frame(name, self, rotation, origin)

    # -- unit vectors ------------------------------------------------------------------
    @property
    def x(self) -> "Vector":
        return Vector._of(self, _unit(0), {})

    @property
    def y(self) -> "Vector":
        return Vector._of(self, _unit(1), {})

    @property
    def z(self) -> "Vector":
        return Vector._of(self, _unit(2), {})

    def vector(self, *components) -> "Vector":
        """The vector with ``components`` along this frame's x, y, z axes."""
        if len(components) == 1 and hasattr(components[0], "__len__"):
            components = tuple(components[0])
        if len(components) != 3:
            raise ValueError(f"a vector needs 3 components, got {len(components)}.")
        return Vector(self, sp.Matrix(components))

    # -- chains ------------------------------------------------------------------------
    def chain(self) -> list["Frame"]:
        """Frames from the root down to this one."""
        out, f = [], self
        while f is not None:
            out.append(f)
            f = f.parent
        return out[::-1]

    @property
    def root(self) -> "Frame":
        f = self
        while f.parent is not None:
            f = f.parent
        return f

    def _rotation_se(self) -> tuple:
        if self._rot is None:
            names = {}
            for c in self.rotation:
                names = merge_names(names, names_of(c))
            self._rot = (se.DenseMatrix(3, 3, [to_se(c) for c in self.rotation]), names)
        return self._rot

    def _root_se(self) -> tuple:
        """``(R, names)`` with ``v_root = R v_self``, in symengine (built once)."""
        if self._root is None:
            if self.parent is None:
                self._root = (se.eye(3), {})
            else:
                (P, pn), (R, rn) = self.parent._root_se(), self._rotation_se()
                self._root = (R if self.parent.parent is None else P * R, merge_names(pn, rn))
        return self._root

    def _dcm_se(self, other: "Frame") -> tuple:
        """``(R, names)`` with ``v_other = R v_self``, in symengine."""
        if other is self:
            return se.eye(3), {}
        if other is self.parent:
            return self._rotation_se()
        if self is other.parent:
            R, names = other._rotation_se()
            return R.T, names
        hit = self._dcm.get(id(other))
        if hit is None or hit[0] is not other:
            _same_tree(self, other)
            (Ro, no), (Rs, ns) = other._root_se(), self._root_se()
            hit = self._dcm[id(other)] = (other, Ro.T * Rs, merge_names(no, ns))
        return hit[1], hit[2]

    def rotation_to_root(self) -> sp.Matrix:
        """``R`` with ``v_root = R v_self``."""
        R, names = self._root_se()
        return _sp_matrix(R, names)

    def dcm(self, other: "Frame") -> sp.Matrix:
        """``R`` with ``v_other = R v_self``: components in ``self`` to components in ``other``."""
        _same_tree(self, other)
        if other is self:
            return sp.eye(3)
        if other is self.parent:
            return self.rotation
        if self is other.parent:
            return other.rotation.T
        return _sp_matrix(*self._dcm_se(other))

    def ang_vel_in(self, other: "Frame") -> "Vector":
        """Angular velocity of this frame relative to ``other``, from the rotation matrices."""
        _same_tree(self, other)
        return self._ang_vel(other)

    def _ang_vel(self, other: "Frame") -> "Vector":
        if other is self.root:
            return self._ang_vel_root()
        return self._ang_vel_root()._sub(other._ang_vel_root())

    def ang_acc_in(self, other: "Frame") -> "Vector":
        """Angular acceleration of this frame relative to ``other`` (derivative seen in ``other``)."""
        return self.ang_vel_in(other).dt(other)

    def _ang_vel_root(self) -> "Vector":
        """Angular velocity relative to the root, with components in this frame's own axes.

        Built down the chain, ``w_f = R_f^T w_parent + unskew(R_f^T dR_f/dt)`` in ``f``'s axes,
        so a deep chain (z-y-z Euler angles) gives the short textbook components instead of
        the root components multiplied through every rotation matrix.
        """
        w = self.__dict__.get("_w_root")
        if w is None:
            if self.parent is None:
                w = Vector._of(self, _unit(-1), {})
            else:
                up = self.parent._ang_vel_root()
                R, names = self._rotation_se()
                rate = _relative_rate(self.rotation)
                rn = {}
                for c in rate:
                    rn = merge_names(rn, names_of(c))
                comps = R.T * se.DenseMatrix(3, 1, list(up._comps))
                w = Vector._of(self, tuple(comps[i] + to_se(rate[i]) for i in range(3)),
                               merge_names(merge_names(up._names, names), rn))
            self._w_root = w   # a frame's rotation never changes: built once
        return w

    def origin_from_root(self) -> "Vector":
        """Position of this frame's origin relative to the root origin."""
        total = Vector._of(self.root, _unit(-1), {})
        for f in self.chain()[1:]:
            if f._origin is not None:
                total = total._add(f._origin)
        return total


def _relative_rate(R: sp.Matrix) -> sp.Matrix:
    """``unskew(R^T dR/dt)`` in the child's axes: exactly ``a' e_i`` for an elementary
    rotation by ``a`` about axis ``i`` (no simplification needed), else simplified."""
    for i, rot in enumerate((rot_x, rot_y, rot_z)):
        j = (i + 1) % 3
        if R[i, i] == 1 and isinstance(R[j, j], sp.cos):
            a = R[j, j].args[0]
            for angle in (a, -a):   # cos(-a) is printed cos(a): rot_y(-theta) is by -theta
                if R == rot(angle):
                    w = [0, 0, 0]
                    w[i] = angle.diff(t)
                    return sp.Matrix(w)
    if all(x.is_number for x in R):
        return sp.zeros(3, 1)
    return unskew(R.T * R.diff(t)).applyfunc(sp.trigsimp)


def _same_tree(a: Frame, b: Frame) -> None:
    if a.root is not b.root:
        raise ValueError(f"frames `{a.name}` and `{b.name}` belong to different chains; "
                         "build every frame from one ground frame.")


def _sp_matrix(M, names) -> sp.Matrix:
    return sp.Matrix(M.rows, M.cols, [to_sp(x, names) for x in M])


@cache
def _unit(i: int) -> tuple:
    """Components of the ``i``-th unit vector (``-1``: the zero vector), in symengine."""
    zero, one = se.Integer(0), se.Integer(1)
    return tuple(one if j == i else zero for j in range(3))


@refuse_text_in
class Vector:
    """A vector as its components in one frame.  Arithmetic converts to the left operand's frame.

    ``components`` is a sympy column; the arithmetic runs on a symengine copy of it
    (:mod:`dualmech.model._algebra`), so a chain of products and time derivatives builds no sympy
    expression until someone reads the result.

    Examples
    --------
    >>> import sympy as sp
    >>> from dualmech import Frame, coordinate, rot_z
    >>> theta = coordinate("theta")
    >>> O = Frame.ground(); arm = O.child("arm", rot_z(theta))
    >>> v = 2 * arm.x + O.y              # components in arm's axes (the left operand's frame)
    >>> v.express(O).components.applyfunc(sp.simplify).T
    Matrix([[2*cos(theta(t)), 2*sin(theta(t)) + 1, 0]])
    >>> arm.x.dot(O.x), arm.x.cross(arm.y).express(O).components.T
    (cos(theta(t)), Matrix([[0, 0, 1]]))
    """

    def __init__(self, frame: Frame, components):
        comps = as_matrix(components)
        if comps.shape != (3, 1):
            raise ValueError(f"a vector needs 3x1 components, got {comps.shape}.")
        self.frame = frame
        self._sp = comps
        self._se = None
        self._nm = None

    @classmethod
    def _of(cls, frame: Frame, comps: tuple, names: dict) -> "Vector":
        v = cls.__new__(cls)
        v.frame, v._sp, v._se, v._nm = frame, None, tuple(comps), names
        return v

    # -- the two forms -----------------------------------------------------------------
    @property
    def components(self) -> sp.Matrix:
        """Components in :attr:`frame` (a sympy 3x1 matrix)."""
        if self._sp is None:
            self._sp = sp.Matrix(3, 1, [to_sp(c, self._nm) for c in self._se])
        return self._sp

    @property
    def _comps(self) -> tuple:
        if self._se is None:
            names = {}
            for c in self._sp:
                names = merge_names(names, names_of(c))
            self._se, self._nm = tuple(to_se(c) for c in self._sp), names
        return self._se

    @property
    def _names(self) -> dict:
        if self._nm is None:
            self._comps  # noqa: B018
        return self._nm

    def __repr__(self) -> str:
        return f"Vector({self.frame.name}, {list(self.components)})"

    # -- arithmetic (symengine) ----------------------------------------------------------
    def _in(self, frame: Frame) -> "Vector":
        if frame is self.frame:
            return self
        R, names = self.frame._dcm_se(frame)
        c = self._comps
        comps = tuple(R[i, 0] * c[0] + R[i, 1] * c[1] + R[i, 2] * c[2] for i in range(3))
        return Vector._of(frame, comps, merge_names(self._names, names))

    def _add(self, other: "Vector") -> "Vector":
        o = other._in(self.frame)
        return Vector._of(self.frame, tuple(a + b for a, b in zip(self._comps, o._comps)),
                          merge_names(self._names, o._names))

    def _sub(self, other: "Vector") -> "Vector":
        o = other._in(self.frame)
        return Vector._of(self.frame, tuple(a - b for a, b in zip(self._comps, o._comps)),
                          merge_names(self._names, o._names))

    def _scaled(self, k, names: dict) -> "Vector":
        return Vector._of(self.frame, tuple(k * c for c in self._comps),
                          merge_names(self._names, names))

    def _dot(self, other: "Vector") -> tuple:
        """``(value, names)`` of the dot product, in symengine."""
        o = other._in(self.frame)
        a, b = self._comps, o._comps
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2], merge_names(self._names, o._names)

    def _cross(self, other: "Vector") -> "Vector":
        o = other._in(self.frame)
        a, b = self._comps, o._comps
        comps = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
        return Vector._of(self.frame, comps, merge_names(self._names, o._names))

    def _dt(self, frame: Frame) -> "Vector":
        dt = time_se()
        local = Vector._of(self.frame, tuple(c.diff(dt) for c in self._comps), self._names)
        if frame is self.frame:
            return local
        return local._add(self.frame._ang_vel(frame)._cross(self))

    def _is_zero(self) -> bool:
        return all(c == 0 for c in self._comps)

    # -- the symengine form (for builders of equations: dualmech.model.direct, dualmech.model.bodies) --
    @classmethod
    def from_se(cls, frame: Frame, components, names: dict) -> "Vector":
        """The vector with symengine ``components`` in ``frame``; ``names`` maps their symbol
        names back to sympy (see :func:`dualmech.model._algebra.to_sp`)."""
        return cls._of(frame, tuple(components), names)

    @property
    def se_components(self) -> tuple:
        """The components in symengine."""
        return self._comps

    @property
    def se_names(self) -> dict:
        """Symbol names of :attr:`se_components` -> the caller's sympy symbols."""
        return self._names

    def dot_se(self, other: "Vector") -> tuple:
        """``(value, names)``: the dot product in symengine, not converted to sympy."""
        return self._dot(_vector(other, "dot_se"))

    # -- public ------------------------------------------------------------------------
    def express(self, frame: Frame) -> "Vector":
        """The same vector with components in ``frame``."""
        if frame is not self.frame:
            _same_tree(self.frame, frame)
        return self._in(frame)

    def __add__(self, other: "Vector") -> "Vector":
        if isinstance(other, int) and other == 0:
            return self
        if not isinstance(other, Vector):
            return NotImplemented
        return self._add(other)

    __radd__ = __add__

    def __neg__(self) -> "Vector":
        return Vector._of(self.frame, tuple(-c for c in self._comps), self._names)

    def __sub__(self, other: "Vector") -> "Vector":
        if not isinstance(other, Vector):
            return NotImplemented
        return self._sub(other)

    def __mul__(self, scalar) -> "Vector":
        if isinstance(scalar, Vector):
            raise TypeError("use `dot` or `cross` to multiply two vectors.")
        k = as_expr(scalar)
        return self._scaled(to_se(k), names_of(k))

    __rmul__ = __mul__

    def __truediv__(self, scalar) -> "Vector":
        k = as_expr(scalar)
        return self._scaled(1 / to_se(k), names_of(k))

    def dot(self, other: "Vector") -> sp.Expr:
        return to_sp(*self._dot(_vector(other, "dot")))

    def cross(self, other: "Vector") -> "Vector":
        return self._cross(_vector(other, "cross"))

    def outer(self, other: "Vector") -> sp.Matrix:
        """Components of the dyad ``self (x) other`` in ``self.frame``."""
        return self.components * _vector(other, "outer").express(self.frame).components.T

    def dt(self, frame: Frame) -> "Vector":
        """Time derivative as seen from ``frame`` (transport theorem)."""
        return self._dt(frame)

    def diff(self, var, frame: Frame) -> "Vector":
        """Partial derivative with respect to ``var`` (a symbol, coordinate or its rate) in ``frame``."""
        return Vector(frame, self.express(frame).components.diff(var))

    def subs(self, *args, **kwargs) -> "Vector":
        return Vector(self.frame, self.components.subs(*args, **kwargs))

    def simplify(self) -> "Vector":
        return Vector(self.frame, self.components.applyfunc(sp.trigsimp))

    def magnitude_squared(self) -> sp.Expr:
        return self.dot(self)

    def is_zero(self) -> bool:
        return all(sp.simplify(c) == 0 for c in self.components)


def _vector(other, method: str) -> Vector:
    if not isinstance(other, Vector):
        raise TypeError(f"Vector.{method}() needs another Vector, got {type(other).__name__} "
                        f"{other!r:.60}; multiply by a scalar with `*` instead.")
    return other


@refuse_text_in
class Point:
    """A point placed relative to another point (or to a frame's origin).

    ``Point.origin(frame)`` is the origin of ``frame``; ``p.locate(name, r)`` makes the point
    at ``p + r``.  Velocities and accelerations are time derivatives of the position from the
    ground origin, seen from the frame asked for.

    Examples
    --------
    The bob of a pendulum of length ``l``: its acceleration has the tangential part
    ``l theta''`` and the centripetal part ``l theta'^2`` towards the pivot.

    >>> import sympy as sp
    >>> from dualmech import Frame, Point, coordinate, rot_z
    >>> theta = coordinate("theta"); l = sp.Symbol("l", positive=True)
    >>> O = Frame.ground(); arm = O.child("arm", rot_z(theta))
    >>> bob = Point.origin(O, "pivot").locate("bob", -l * arm.y)
    >>> a = bob.acc(O).express(arm).components
    >>> a.T
    Matrix([[l*Derivative(theta(t), (t, 2)), l*Derivative(theta(t), t)**2, 0]])
    """

    def __init__(self, name: str, position: Vector):
        self.name = name
        self._position = position  # from the root origin

    def __repr__(self) -> str:
        return f"Point({self.name!r})"

    @classmethod
    def origin(cls, frame: Frame, name: str | None = None) -> "Point":
        return cls(name or frame.name, frame.origin_from_root())

    def locate(self, name: str, r: Vector) -> "Point":
        """The point at ``r`` from this one.

        From a point at the root origin the position keeps ``r``'s own frame (e.g. a body's
        axes), so its derivatives stay short instead of passing through every rotation matrix
        up to the root.
        """
        if self._position._is_zero():
            return Point(name, r)
        return Point(name, self._position._add(r))

    def pos_from(self, other: "Point | None" = None) -> Vector:
        """Position relative to ``other`` (the root origin by default)."""
        if other is None:
            return self._position
        return self._position._sub(other._position)

    def vel(self, frame: Frame) -> Vector:
        """Velocity seen from ``frame``."""
        return self._position._dt(frame)

    def acc(self, frame: Frame) -> Vector:
        """Acceleration seen from ``frame``."""
        return self._position._dt(frame)._dt(frame)


@refuse_text_in
@dataclass(frozen=True)
class RelativeMotion:
    """Acceleration of a point P moving in a frame B, split into the textbook terms.

    ``a_P/O = a_Q/O + dw/dt x r + w x (w x r) + 2 w x v_rel + a_rel`` with ``Q`` a point fixed
    in B, ``r = P - Q``, ``w`` the angular velocity of B in O and ``v_rel``, ``a_rel`` the
    velocity and acceleration of P seen from B.  ``coriolis`` is ``2 w x v_rel``.

    Examples
    --------
    A bead sliding at ``r(t)`` along a rod that turns at ``phi'``: the Coriolis term is
    ``2 r' phi'`` across the rod.

    >>> from dualmech import Frame, Point, RelativeMotion, coordinate, rot_z
    >>> r, phi = coordinate("r"), coordinate("phi")
    >>> O = Frame.ground(); rod = O.child("rod", rot_z(phi))
    >>> hub = Point.origin(O); bead = hub.locate("bead", r * rod.x)
    >>> parts = RelativeMotion.of(bead, hub, rod, O)
    >>> parts.coriolis.express(rod).components.T
    Matrix([[0, 2*Derivative(phi(t), t)*Derivative(r(t), t), 0]])
    >>> (parts.total() - bead.acc(O)).express(O).components.applyfunc(sp.simplify).T
    Matrix([[0, 0, 0]])
    """

    base: Vector
    tangential: Vector
    centripetal: Vector
    coriolis: Vector
    relative: Vector

    @classmethod
    def of(cls, point: Point, base: Point, moving: Frame, ground: Frame) -> "RelativeMotion":
        r = point.pos_from(base)
        w = moving.ang_vel_in(ground)
        v_rel = r.dt(moving)
        return cls(base=base.acc(ground), tangential=w.dt(ground).cross(r),
                   centripetal=w.cross(w.cross(r)), coriolis=2 * w.cross(v_rel),
                   relative=v_rel.dt(moving))

    def total(self) -> Vector:
        return self.base + self.tangential + self.centripetal + self.coriolis + self.relative

    def terms(self) -> dict[str, Vector]:
        return {"base": self.base, "tangential": self.tangential,
                "centripetal": self.centripetal, "coriolis": self.coriolis,
                "relative": self.relative}


@refuse_text
def components_in(vectors: Iterable[Vector], frame: Frame) -> list[sp.Matrix]:
    return [v.express(frame).components for v in vectors]
