"""Layouts of the arrays passed to and from the compiled kernel (no numba import here)."""

# Parameter vector layout (packed by simulate.pack_parameters).
P_ALPHA, P_P2, P_E, P_ONE_SIDED, P_FREE_SIDE, P_REBOUND, P_LINEAR = 0, 1, 2, 3, 4, 5, 6
# P_OVERTURN: the rotation a = s·θ at which a run on side +1 counts as overturned [rad] (side
# −1: P_OVERTURN_NEG; the rectangle packs the same number twice).
P_OVERTURN, P_RTOL, P_ATOL, P_REST, P_INV_I0, P_MAX_EVENTS, P_MAX_STEPS = 7, 8, 9, 10, 11, 12, 13
P_THETA0, P_OMEGA0 = 14, 15  # initial state (free-rocking tests); 0, 0 = at rest
P_SIN_ALPHA, P_COS_ALPHA = 16, 17
# With loads or thrusts: the block's own I0 [kg·m²], the uplift acceleration of each side [g]
# and the coefficient of restitution of an impact from side −1 (P_E: from side +1).
P_I0, P_UPLIFT_POS, P_UPLIFT_NEG, P_E_NEG = 18, 19, 20, 21
# The ground acceleration [g] per N·m of restoring moment at rest, about each pivot (a
# pretensioned member raises the uplift acceleration by its moment times this), and the polar
# moment of inertia of the block and its loads about each pivot at rest [kg·m²] (impact losses).
P_PRE_SCALE_POS, P_PRE_SCALE_NEG, P_INERTIA_POS, P_INERTIA_NEG = 22, 23, 24, 25
# Index of the first sample of the free tail (the ground at rest from there on): steps past it
# are chosen by the error controller alone, not clipped at the samples; 0: every step clipped.
P_FREE_FROM = 26
# What the engine integrates (K_* below), and the collapse rotation of side −1 [rad].
P_KIND, P_OVERTURN_NEG = 27, 28
# The toothed return walls' friction of a rigid body (mechanics.Friction; 0 force: none): F
# of all the walls [N], the interface's x from pivot O and from O′, the toothing's bottom z0,
# its height h and the overlap l [m] (mechanics.friction_moment).
P_RUB, P_RUB_X_POS, P_RUB_X_NEG, P_RUB_Z0, P_RUB_H, P_RUB_L = 29, 30, 31, 32, 33, 34
N_PARAMS = 35

# Kinds of the engine's input (P_KIND), each with its own equation of motion: the paper's
# rectangle (Eq. 2, closed form; no point table), a rigid body with loads or thrusts (the
# point table of mechanics.point_table), a chain of bodies (the table of mechanics.Chain).
K_RECTANGLE, K_POINTS, K_CHAIN = 0, 1, 2


def collapse_rotation(par, s):
    """The rotation a = s·θ at which a run on side s counts as overturned [rad] (both engines;
    the fast one compiles this very function)."""
    return par[P_OVERTURN] if s > 0 else par[P_OVERTURN_NEG]


# Float outputs.
O_MAX_A, O_THETA_MAX, O_THETA_MIN, O_MAX_OMEGA, O_T_OVERTURN, O_T_UPLIFT, O_T_END = range(7)
# Kinetic energy lost in impacts and at rest [J] (P_INERTIA_*; 0 for a block without a mass).
O_IMPACT_LOSS = 7
N_FLOAT_OUT = 8
# Integer outputs (I_NONFINITE: which quantity stopped a "non-finite" run, NF_* codes).
I_STATUS, I_IMPACTS, I_STEPS, I_REJECTED, I_UPLIFTS, I_NONFINITE = range(6)
N_INT_OUT = 6
# Status codes.
STATUS_COMPLETED, STATUS_OVERTURNED, STATUS_EVENT_LIMIT, STATUS_STEP_LIMIT = 0, 1, 2, 3
STATUS_NONFINITE = 4
# Quantities that can turn non-finite (NaN or ±inf); NF_FORCE + j is restrainer row j's force.
NF_NONE, NF_THETA, NF_OMEGA, NF_ACCEL, NF_ERROR, NF_GROUND, NF_FORCE = 0, 1, 2, 3, 4, 5, 6
# Per-restrainer outputs: peak elongation [m], peak force [N], failure time [s] (nan: intact),
# first yield time [s] (nan: never), energy dissipated [J] (plastic work and the energy
# released when the member is lost).
S_MAX_U, S_MAX_FORCE, S_T_FAIL, S_T_YIELD, S_ENERGY = 0, 1, 2, 3, 4
N_SPRING_OUT = 5

# Event kinds: the block's, then a member law's (a yield, re-engage or anchor-rupture level
# reached going up; a slack point going down; the turning point of a yield plateau).
EV_NONE, EV_IMPACT, EV_OVERTURN, EV_FAIL, EV_UNRESOLVED = 0, 1, 2, 3, 4
EV_LAW_UP, EV_SLACK, EV_UNLOAD = 5, 6, 7
# A turning point of the motion under friction (θ̇ = 0 where a = s·θ > 0): the body sticks or
# the friction turns round (kernel.py).
EV_TURN = 8


STATUS_NAMES = {
    STATUS_COMPLETED: "completed",
    STATUS_OVERTURNED: "overturned",
    STATUS_EVENT_LIMIT: "event-limit",
    STATUS_STEP_LIMIT: "step-limit",
    STATUS_NONFINITE: "non-finite",
}

NONFINITE_NAMES = {
    NF_THETA: "the rotation θ",
    NF_OMEGA: "the angular velocity θ̇",
    NF_ACCEL: "the angular acceleration θ̈",
    NF_ERROR: "the integration error estimate",
    NF_GROUND: "the ground acceleration",
}
