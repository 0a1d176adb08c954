"""What each catalogue problem is expected to declare and how its printed answers are judged.

Read by ``tests/test_catalogue_checks.py``.  ``MODELS`` is each problem's list of derivations
(the methods its class declares); ``VERDICTS`` is, for each printed answer of the source, the
verdict derived *by hand* (the problem module's docstring gives the working; the comment beside
an entry says why where it is not obvious).  A new catalogue problem needs an entry in both:
the catalogue checks fail, naming it, until it has them.
"""

#: problems whose every catalogue-wide check costs far more than a few seconds: their
#: parameter of each catalogue-wide parametrised test is marked slow (the quick run leaves it
#: out, the full run and CI keep it), never skipped
SLOW = {
    # eight coordinates, 21 reactions, the front contact's square root: its two derivations
    # take seconds each on one core, its check with the referee about 17 s
    "whipple_bicycle",
}


#: the bound on a false "equal" a problem's exact verdict must reach where 8 points cannot
#: reach the catalogue's 1e-60 (none now: the bicycle, of the highest degree, gives 6.7e-68)
BOUND: dict = {}


#: problems the catalogue-wide grading tests leave out, with why (said in the skip): the
#: bicycle's answers are decided on the exact route (its front contact's square root stays
#: exact, tests/test_grade_state_roots.py), but writing the generated answers expands its
#: rows of up to 180 000 characters (past 9 CPU minutes) and explaining a wrong one builds
#: the term tables of every row (past 6 minutes)
UNGRADED = {
    "whipple_bicycle": "generating its answers (expanding rows of up to 180 000 characters) "
                       "and explaining a wrong one take many minutes; its verdicts are exact "
                       "(tests/test_grade_state_roots.py)",
}


def graded_params(names) -> list:
    """:func:`catalogue_params` of ``names`` with the :data:`UNGRADED` ones skipped, saying
    why."""
    import pytest
    return [pytest.param(n, marks=pytest.mark.skip(reason=UNGRADED[n]), id=n)
            if n in UNGRADED else p for n, p in zip(names, catalogue_params(names))]


def catalogue_params(names) -> list:
    """``names`` as pytest parameters, those in :data:`SLOW` marked slow."""
    import pytest
    return [pytest.param(n, marks=pytest.mark.slow, id=n) if n in SLOW else n for n in names]


MODELS = {
    "ball_in_sphere": ["newton_euler", "lagrange", "angular_momentum", "multiplier"],
    "bead_on_hoop": ["newton_euler", "lagrange", "multiplier"],
    "block_in_pipe": ["newton_euler", "lagrange", "multiplier"],
    "block_on_wedge": ["newton_euler", "lagrange", "lagrange_multipliers"],
    "cart_pendulum": ["newton_euler", "lagrange", "lagrange_multipliers"],
    "compound_double_pendulum": ["newton_euler", "lagrange", "moments", "multiplier"],
    "copying_machine": ["newton_euler", "lagrange", "multiplier", "reduced"],
    "coupled_pendulums": ["newton_euler", "lagrange"],
    "falling_container": ["newton_euler", "lagrange", "lagrange_y", "newton_euler_y"],
    "four_bar": ["newton_euler", "lagrange", "multiplier"],
    "frequency_response": ["newton_euler", "lagrange"],
    "helicopter_blade": ["newton_euler", "lagrange"],
    "helicopter_blade_weighted": ["newton_euler", "lagrange"],
    "inertia_wheel_pendulum": ["newton_euler", "lagrange", "multiplier"],
    "inverted_pendulum_springs": ["newton_euler", "lagrange", "multiplier"],
    "kapitza_pendulum": ["newton_euler", "lagrange", "multiplier"],
    "mass_spring_gravity": ["newton_euler", "lagrange", "gravity_as_force"],
    "mobile_robot": ["newton_euler", "lagrange", "multiplier"],
    "mobile_robot_simplified": ["newton_euler", "lagrange"],
    "n_link_pendulum": ["newton_euler", "lagrange", "multiplier"],
    "n_link_rigid_pendulum": ["newton_euler", "lagrange", "multiplier"],
    "pendulum_on_mass": ["newton_euler", "lagrange", "multiplier"],
    "pendulum_on_rotating_plane": ["newton_euler", "lagrange", "multiplier", "contact_velocity"],
    "pendulum_particle": ["newton_euler", "lagrange", "newton_euler_inertial", "cartesian"],
    "pulley_bent_track": ["newton_euler", "lagrange", "multiplier"],
    "restrained_pendulum": ["newton_euler", "lagrange", "multiplier"],
    "restrained_pendulum_horizontal": ["newton_euler", "lagrange", "multiplier"],
    "rigid_body_euler_angles": ["newton_euler", "lagrange"],
    "rigid_rod_pendulum": ["newton_euler", "lagrange", "multiplier"],
    "rolling_cylinder": ["newton_euler", "lagrange", "multiplier"],
    "rolling_disk": ["newton_euler", "lagrange", "multiplier"],
    "satellite_polar": ["newton_euler", "lagrange"],
    "simple_pendulum": ["newton_euler", "lagrange", "angular_momentum", "multiplier"],
    "spring_mass_damper": ["newton_euler", "lagrange"],
    "symmetric_top": ["newton_euler", "lagrange", "body_axes"],
    "taut_string_masses": ["newton_euler", "lagrange"],
    "three_mass_chain": ["newton_euler", "lagrange"],
    "toy_car": ["newton_euler", "lagrange", "angular_momentum", "multiplier"],
    "trolley_pendulum": ["newton_euler", "lagrange", "bob_coordinates", "multiplier"],
    "two_rod_linkage": ["newton_euler", "lagrange", "lagrange_x", "multiplier"],
    "wheel_on_pivot": ["newton_euler", "lagrange", "angular_momentum", "multiplier",
                       "pivot_multiplier"],
    "whipple_bicycle": ["newton_euler", "lagrange"],
}

_MOBILE_ROBOT_COMMON = {"L": "correct", "I_P": "correct", "r_x, r_y, a_Px, a_Py": "correct",
                        "moment equation about P": "correct", "(2.6-2)": "correct"}

VERDICTS = {
    "ball_in_sphere": {
        "longitudinal and circumferential velocity": "correct",  # v = a th' e_th + a sin th ph' e_ph
        "momentum dT/dphi'": "correct",        # = h_O . Z
        "momentum is conserved": "correct",    # phi cyclic, no moment about Z
        "initial longitude rate": "correct",   # a sin(theta0) phi'0 = v
        "value of the momentum": "correct",    # sin^2 theta0 v/(a sin theta0) = (v/a) sin theta0
        "energy T + V": "correct",             # read with phi' (see module docstring)
        "energy is conserved": "correct",      # no force does work
        "value of the energy": "correct",      # = m v^2/2 + m g a cos theta0
        "sum q' dT/dq' = 2T": "correct",       # T quadratic in the rates
        "sum q' (Lagrange's equation)": "correct",
    },
    "bead_on_hoop": {
        "velocity of bead, velocity of hoop": "correct",
        "T": "correct",
        "U": "correct",
        "equation of motion": "correct",     # m R^2 th'' - m R^2 w^2 s c + m g R s = 0
        "angular acceleration": "correct",   # (omega^2 cos th - g/R) sin th
    },
    "block_in_pipe": {
        "generalised forces": "correct",   # the damper's -d y' e_r . dr/dq: (0, -d y')
        "Lagrangian": "correct",           # block as a particle in polar coordinates
    },
    "block_on_wedge": {
        "v_block^2": "correct",  # v = (q2' + q1' cos a) i - q1' sin a j
        "U": "correct",          # the block is q1 sin a below the top of the incline
        "q1''": "correct",       # (M + m) - m cos^2 a = M + m sin^2 a
        "q2''": "correct",       # the q2 Lagrange equation (horizontal momentum) / (M + m)
    },
    "cart_pendulum": {
        "Q1, Q2": "correct",                 # F . dr_B/dq with x_B = x + l sin th
        "U": "correct",                      # bob l (1 - cos th) above its lowest point
        "T_pendulum": "correct",             # v_B = (x' + l th' cos th, l th' sin th)
        "T_pendulum (expanded)": "correct",  # the same, multiplied out
        "equation of motion, x": "correct",  # d/dt dT/dx' + c x' + k x = Q1
        "equation of motion, theta": "wrong",  # m0 l th'' must be m0 l^2 th''
    },
    "compound_double_pendulum": {
        "horizontal position and velocity of G": "correct",
        "vertical position and velocity of G (downwards)": "correct",
        "T": "correct",
        "T (expanded)": "correct",          # cos th1 cos th2 + sin th1 sin th2 = cos(th1 - th2)
        "V": "correct",
        "theta1: dT/dth1', d/dt, dT/dth1, dV/dth1": "correct",
        "theta1: Lagrange's equation": "correct",
        "theta1: divided through": "wrong",       # g a sin th1 for g sin th1
        "theta2: dT/dth2'": "wrong",               # m b^2 th1' for m b^2 th2'
        "theta2: d/dt, dT/dth2, dV/dth2": "correct",
        "theta2: Lagrange's equation": "correct",
        "theta2: finally": "wrong",                # g b sin th2 (and 3 b only for I0 = 2 m b^2)
    },
    "copying_machine": {
        "T": "correct",
        "U": "correct",
        "R": "correct",
        "Q1, Q2": "correct",
        "derivatives": "correct",
        "Lagrange's equation for theta": "wrong",   # - dU/dtheta, must be + dU/dtheta
        "static equation": "correct",
        "theta from y": "correct",
        "equations of motion": "correct",
        "one-coordinate equation": "correct",
    },
    "coupled_pendulums": {
        "(a) torque about O, linearised": "correct",
        "(a) m1, m2": "correct",
        "(a) k1, k2, k3, k4": "correct",
        "(b) omega^2": "correct",
        "(b) mode ratio a1/a2": "correct",            # +1 and -1
        "(b) mode ratio a1/a2, second form": "correct",
    },
    "falling_container": {
        # x2 from the ground (the source's words): k(x1 - x2) for k(x1 - x2 + l0)
        "x-equation 1, x2 from the ground": "wrong",
        # x2 from the spring's free length (the datum its U implies): right
        "x-equation 1, x2 from the free length": "correct",
        # m1 x2'' for m2 x2'' in both readings (and k(x2 - x1) for k(x2 - x1 - l0))
        "x-equation 2, x2 from the ground": "wrong",
        "x-equation 2, x2 from the free length": "wrong",
        "y-equation 1": "correct",   # (m1 + m2) y1'' + m2 y2'' + (m1 + m2) g = 0
        "y-equation 2": "correct",   # m2 (y1'' + y2'') + c y2' + k y2 + m2 g = 0
    },
    "four_bar": {
        # the module docstring's own hand derivation: the sum of the j_A balances, and m1's
        # balance across its crank, both hold on the motion
        "equation of motion": "correct",
        "m1 along j_A": "correct",
    },
    "frequency_response": {
        "(a) model": "correct",
        "(a) X(0) = F0/k": "correct",
        "(a) omega_n = sqrt(k/m)": "correct",
        "(a) X(omega)": "correct",
    },
    "helicopter_blade": {
        # a rising blade meets the air from above: alpha0 - beta'/Omega, not + (module doc)
        "angle of attack": "wrong",
        "lift per unit length, factored (at the tip)": "wrong",
        "lift per unit length, expanded (at the tip)": "correct",
        "generalised force Q": "correct",        # int_0^L w(x) x dx, the moment arm included
    },
    # the printed answers (angle of attack, lift, Q) do not involve the weight: same verdicts
    "helicopter_blade_weighted": {
        "angle of attack": "wrong",
        "lift per unit length, factored (at the tip)": "wrong",
        "lift per unit length, expanded (at the tip)": "correct",
        "generalised force Q": "correct",
    },
    "inertia_wheel_pendulum": {
        "(a) generalised forces": "correct",
        "(b) angular velocities": "correct",
        "(b) positions and velocities": "correct",
        "(c) T1, T2": "correct",
        "(c) U1, U2": "correct",
        "(d) dL/dq1'": "wrong",                 # l_c1 not squared; q1'' for q1'
        "(d) dL/dq1": "correct",
        "(d) q1 equation": "wrong",             # m1 l_c1 q1'' must be m1 l_c1^2 q1''
        "(d II) dL/dq2', dL/dq2": "wrong",      # I2 (q1'' + q2'') for I2 (q1' + q2')
        "(d II) q2 equation": "correct",
        "(d) equations of motion": "wrong",     # the set holds the wrong q1 equation
    },
    # every printed step of (a)-(c) is right (hand-checked in the module doc)
    "inverted_pendulum_springs": {
        "(a) T": "correct",
        "(a) V": "correct",
        "(a) L": "correct",
        "(b) derivatives of L": "correct",
        "(b) equation of motion": "correct",
        "(c) first-order form": "correct",
        "(c) Jacobian entry": "correct",
        "(c) Jacobian at theta = 0": "correct",
        "(c) eigenvalues squared": "correct",
    },
    # Landau & Lifshitz's equation, with their a = -(our a): right (module docstring)
    "kapitza_pendulum": {"equation of motion": "correct"},
    "mass_spring_gravity": {
        "T": "correct",                     # v = x' j
        "U": "correct",                     # extension x, height x
        "Lagrange's equation": "correct",   # d/dt (M x') + k x + M g = F
        "equation of motion": "correct",    # M x'' + k x = F - M g
        "generalised momentum": "correct",  # dT/dx' = M x' = p . j
    },
    "mobile_robot": {
        "mass centre (vertical, horizontal)": "wrong",   # x + L sin(phi): sign of L sin(phi)
        "(2.6-9)": "correct", **_MOBILE_ROBOT_COMMON, "(2.6-11)": "correct",
        "(2.6-12)": "correct", "H = f - M x''": "correct",
        "detailed model (2.6-10), (2.6-13)": "correct", "x'' and phi'' solved": "correct",
    },
    "mobile_robot_simplified": {
        "(2.6-1)": "correct", **_MOBILE_ROBOT_COMMON,
        "simplified model (2.6-1), (2.6-2)": "correct",
    },
    # dualmech's own parametric chains: no source prints their answers
    "n_link_pendulum": {},
    "n_link_rigid_pendulum": {},
    "pendulum_on_mass": {
        # i_A entry: 16/3 (rod) + 1/2 (disk) + 50 (parallel axis) = 335/6, printed 331/6
        "(b) inertia about A": "wrong",
        "(b) K-K component": "correct",           # 16/3 + 1 + 50 = 169/3
        "(c) mass centre": "correct",             # (m(-2r) + 2m(-5r)) / 3m = -4r
        "(c) Newton, M, J": "correct",            # k y - M g + F_Ry = -M y''
        "(c) Newton, pendulum, J": "correct",     # a_C . J = -y'' + 4r (theta'' sin + theta'^2 cos)
        "(c) combined y equation": "correct",     # difference of the two above
        "(c) torque about A, multiplied out": "wrong",   # the weight is -3 m g J, printed -m g J
        "(c) torque about A": "correct",          # (-4r j_A) x (-3 m g J) = -12 r m g sin K
        "(c) theta equation": "correct",          # Euler about A; the v_A x v_C terms cancel
        "(c) T": "correct",
        "(c) V": "correct",                       # up to the constant -(M + 3m) g l0
        # d/dtheta' of (25/6) m r^2 theta'^2 is (25/3) m r^2 theta', printed 25/6
        "(c) dL/dtheta'": "wrong",
        "(c) d/dt dL/dtheta'": "correct",
        "(c) dL/dtheta": "correct",
    },
    "pendulum_on_rotating_plane": {
        "(a) r_rel, v_rel, w": "correct",
        "(a) V_xyz": "correct",
        "(a) X and Z in x, y, z": "correct",
        "(a) v": "wrong",                    # theta'' printed where theta' belongs
        "(b) T": "correct",
        "(c) V, L": "correct",
        "(d) constraint v_z": "correct",
        "(d) theta: dL/dtheta', d/dt, dL/dtheta": "correct",
        "(d) theta equation": "correct",
        "(d) equation of motion": "correct",
        "(d) beta: dL/dbeta', d/dt, dL/dbeta": "correct",
        "(d) beta equation with lambda_B": "correct",
        "(d) normal force lambda_B": "correct",
    },
    "pendulum_particle": {
        "inertial (1), (2)": "correct",
        "x, x'": "correct",
        "x''": "wrong",                              # -l cos th th'': the sign of the first term
        "constraint, 1st derivative": "wrong",       # x' x'' + y' y'' for x x' + y y'
        "constraint, 2nd derivative": "correct",
        "rod force from the 2nd derivative": "correct",
        "velocity, body": "correct",
        "acceleration, body": "wrong",               # the factor l dropped
        "body, vector equation": "correct",
        "body, b1 and b2": "correct",
        "T, U": "correct",
        "dL/dtheta'": "wrong",                       # m l^2 th'' for m l^2 th'
        "dL/dtheta": "correct",
        "equation of motion": "correct",
        "equation of motion, final": "correct",
        "r, v, v.v": "correct",
    },
    "pulley_bent_track": {
        "(b) T": "correct",          # pulley: (1/2)(m r^2/2)(x'/r)^2 = m x'^2/4
        "(b) V": "correct",          # M2 drops x sin(theta0)
        "(b) L": "correct",
        "(c) Xi_x": "correct",       # F I . e = F cos(theta0); dashpot -c x'
        "(d) equation of motion": "correct",
    },
    # the source's own model: every printed answer follows from it
    "restrained_pendulum": {
        "T": "correct",                   # m (l th')^2 / 2
        "R": "correct",                   # dashpot rate a th' along its arc
        "U": "correct",                   # spring travel b th along its arc
        "equation of motion": "correct",  # the energies above, by hand (module doc)
        "linearised equation: M, C, K": "correct",
    },
    # spring and dashpot kept horizontal: the printed answers hold to first order only
    "restrained_pendulum_horizontal": {
        "T": "correct",
        "R": "wrong",                     # rate a th' cos th, printed a th'
        "U": "wrong",                     # travel b sin th, printed b th
        "equation of motion": "wrong",    # small-angle k b^2 th, c a^2 th'
        "linearised equation: M, C, K": "correct",
    },
    "rigid_body_euler_angles": {
        "(5) Euler's equations": "correct",         # H_G = (A w1, B w2, C w3), transport theorem
        "(5) R1": "correct",                        # rows: x1, y1, z1 in X, Y, Z
        "(5) R2": "correct",
        "(5) R3": "correct",
        "(5) full transformation": "correct",
        "(5) spin rates from the matrices": "correct",   # right, with redundant R3 and R1 factors
        "(5) w1, w2, w3": "correct",
        "(5) kinetic energy": "correct",
        "(5) dT/dpsi'": "correct",                  # only w3 holds psi', with coefficient 1
    },
    # every printed formula on the two slides is right (checked by hand in the module doc)
    "rigid_rod_pendulum": {
        "v_c": "correct", "w_ib": "correct", "I_z": "correct", "T": "correct",
        "U": "correct", "L": "correct", "dL/dtheta', dL/dtheta": "correct",
        "equation of motion": "correct", "equation of motion, final": "correct",
    },
    "rolling_disk": {
        # no slip: the contact point's velocity is zero, x' = r phi' cos(psi), y' = r phi'
        # sin(psi) (Greenwood, Advanced Dynamics; the module docstring derives it)
        "rolling rows": "correct",
        # the thin disk upright at speed v: lambda^2 = 4 (g r - 3 v^2)/(5 r^2), stable for
        # v^2 > g r/3 (the classic result; derived by hand in the module docstring)
        "lean eigenvalues squared on upright rolling": "correct",
        # the same as numbers at r = 0.3, g = 10: v_c = sqrt(3/3) = 1 and, at v = 1/2,
        # lambda = +-sqrt(4 (3 - 3/4) / 0.45) = +-sqrt(20)
        "critical speed (m/s)": "correct",
        "lean eigenvalues at v = 0.5 m/s": "correct",
    },
    "rolling_cylinder": {
        "(a) v_C": "correct",
        "(a) v_P": "correct",
        "(a) r_P": "correct",
        "(a) L": "correct",
        "(a) L, second form": "wrong",            # + 2 r R cos(theta) for - 2 r R cos(theta)
        "(a) equation of motion": "wrong",        # m r R sin(theta) theta'^2 missing
        "(c) f(theta), h(theta)": "correct",
        "(c) linearised, n even": "correct",
        "(c) linearised, n odd": "correct",
        "(c) omega_n": "correct",
        "(c) T_n": "correct",
        "(c) T_n in sigma, mu": "correct",
    },
    # T = m (r^2 theta'^2 + r'^2)/2, read with the handwritten 1/2: right
    "satellite_polar": {"(3) kinetic energy": "correct"},
    "simple_pendulum": {
        "T": "correct",                    # |v| = a theta'
        "V": "correct",                    # height a (1 - cos theta) above the lowest point
        "equation of motion": "correct",   # M a^2 theta'' + M g a sin theta = 0
        "small angles: coefficients of theta'', theta": "correct",  # sin theta ~ theta
        "generalised momentum is the angular momentum": "correct",  # M a^2 theta' both
    },
    "spring_mass_damper": {
        "T": "correct",               # m v^2 / 2 of the block
        "U": "correct",               # minus the work of -k x from 0 to x
        "R": "correct",               # dashpot force -b x' = -dR/dx'
        "Q": "correct",               # f(t) i . dv/dx' = f(t)
        "dR/dx', dU/dx": "correct",
        "equation of motion": "correct",
    },
    # T = (A w1^2 + A w2^2 + C w3^2)/2 about the tip: hand-checked, right
    "symmetric_top": {"(5) T with A = B": "correct"},
    "taut_string_masses": {
        "L, expanded": "correct",          # sqrt(a^2 + d^2) = a (1 + d^2/(2a^2)) + O(d^4)
        "Delta = L - 3a": "correct",
        "U = P Delta": "correct",
        "T": "correct",
        "equations of motion": "correct",
        "mass and stiffness matrices": "correct",
        "natural frequencies w^2": "correct",   # det [[2p - w^2 m, -p], [-p, 2p - w^2 m]] = 0
        "mode shapes x2/x1": "correct",
    },
    "three_mass_chain": {
        "dT/dx_i'": "correct",
        "dU/dx_i": "correct",
        "(1)": "correct",
        "(2)": "correct",
        "(3)": "correct",
        "matrix form": "correct",
        "mass and stiffness matrices": "correct",
        "M_ij is d^2 T / dx_i' dx_j'": "correct",
        "T = q'^T M q'/2, V = q^T K q/2": "correct",
    },
    "toy_car": {
        "(1) i_B, j_B, k_B": "correct",          # columns of rot_x(phi) rot_y(theta)
        "(1) rotation matrix": "correct",        # rot_y(theta)^T rot_x(phi)^T, rows i_B, j_B, k_B
        "(2) angular velocities": "correct",     # phi' I and theta' j_A
        "(2) initial rates": "correct",          # v = R (phi' cos(theta) j_B - theta' i_B)
        "(3) linear momentum": "correct",        # m (phi' I + theta' j_B) x (-R k_B)
        "(4) angular momentum h_O": "correct",   # (-R k_B) x p
        "(5) hints": "correct",                  # I = cos(theta) i_B + sin(theta) k_B
        "(5) Coriolis term": "correct",          # 2 phi' I x (-R theta' i_B)
        "(8) acceleration": "correct",           # k_A = cos(theta) k_B - sin(theta) i_B
        "(8) Newton's second law": "correct",
        "(9) hints": "correct",
        # + 2 phi' theta' sin(theta) j_B: the Coriolis term's sign flipped (it is -2, as in (8))
        "(9) restated vector equation, j_B": "wrong",
        "(9) equations of motion": "correct",    # i_B: theta equation, j_B: phi equation
        "(10) reaction F_r": "correct",          # k_B: F_r - m g cos(phi) cos(theta) = m a . k_B
        # (-R k_B) x (-m g K) = -m g R (sin(phi) i_B + cos(phi) sin(theta) j_B): R lost, angles
        # swapped
        "(B) torque of gravity about O": "wrong",
        # d/dt h_O = m R^2 (...): printed with m R from the third line of the derivation on
        "(B) rate of h_O": "wrong",
        "(B) vector equation": "wrong",          # made of the two wrong sides above
        "(B) equations of motion": "correct",    # the two errors cancel in the boxed results
    },
    "trolley_pendulum": {
        "Lagrange's equation, d/dt dT/dq' - dT/dq + dV/dq = Q": "correct",
        # - dL/dq'_i where - dL/dq_i belongs: a momentum where a force belongs
        "Lagrange's equation, d/dt dL/dq' - dL/dq' = Q": "wrong",
        "energy balance d/dt (T + V) = sum Q q'": "correct",
    },
    "two_rod_linkage": {
        "(a) x(theta)": "correct",
        "(a) x'(theta, theta')": "correct",
        "(a) theta'(x, x')": "correct",          # on the branch sin(theta) > 0
        "(a) x''": "correct",
        "(a) theta''": "correct",
        "(b) T": "correct",
        "(b) V, middle form": "wrong",           # k |r_B|^2/2 for k (|r_B| - l0)^2/2
        "(b) V": "correct",
        "(b) Xi_x": "correct",
        "(b) L in x": "correct",
        "(b) x equation": "wrong",               # m g (l0 - x)/sqrt(D) for m g (l0 + x)/(2 sqrt(D))
        "(b) Xi_theta": "correct",
        "(b) L in theta": "correct",
        "(b) theta equation": "correct",
        "(B) I projection": "correct",
        "(B) F_R": "correct",
        "(B) F_R in x": "correct",
        "(B) F_R in theta": "wrong",             # k (2 l cos(theta)) for k (2 l cos(theta) - l0)
    },
    "wheel_on_pivot": {
        "(a) inertia about G": "correct",
        "(a) spin rate": "correct",
        "(a) L_G": "correct",
        "(a) p, r_OG, r_OC": "correct",
        "(a) L_O, first line": "wrong",          # L_G copied with -(l/a) i for -(2l/a) i
        "(a) L_O": "correct",
        "(b) rate of L_O": "correct",
        "(b) rate of L_O, steady": "correct",
        "(b) sum of moments about O": "correct",
        "(b) F_y": "correct",
        "(b) contact force relation": "correct",
    },
    "whipple_bicycle": {
        # Meijaard et al. (2007) Table 2: the roll/steer eigenvalues at v = 0..10 m/s, printed
        # to 14 digits; sympy's independent Kane model of the same benchmark
        # (tests/test_whipple_bicycle.py, SYMPY_RES) has the same eigenvalues to 1e-9
        **{f"Table 2, eigenvalues at v = {v} m/s": "correct" for v in range(11)},
        # section 5: where the weave pair and the capsize root cross zero (bisected on the
        # linearisation; the same speeds where sympy's state matrix changes stability)
        "weave speed (m/s)": "correct",
        "capsize speed (m/s)": "correct",
    },
}
