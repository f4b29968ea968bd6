"""Brent's root and minimum searches (rockcli.searches) against closed forms, bisection and
their bounds: what the capacity curve's zero, a capacity's ag and the optimal hinge rely on."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.searches import MAX_EVALUATIONS, brent_minimum, brent_root


def bisection(f, lo: float, hi: float) -> float:
    """The reference: halvings keeping lo where f > 0, to the last bit."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if f(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    return hi


class Counted:
    """f with its evaluations counted."""

    def __init__(self, f) -> None:
        self.f, self.calls = f, 0

    def __call__(self, x: float) -> float:
        self.calls += 1
        return self.f(x)


def test_root_of_cos_x_minus_x_is_the_dottie_number() -> None:
    f = Counted(lambda x: math.cos(x) - x)
    root = brent_root(f, 0.0, 1.0, f(0.0), f(1.0))
    assert abs(root - 0.7390851332151607) <= 2 * math.ulp(0.739)
    assert f.calls < 15


@settings(max_examples=200, deadline=None)
@given(
    st.floats(0.01, 0.99),
    st.floats(0.1, 10.0),
    st.floats(-3.0, 3.0),
)
def test_root_agrees_with_bisection_on_a_decreasing_cubic(r: float, k: float, c: float) -> None:
    """f(x) = −k(x − r)(1 + c²(x − r)²) falls through zero at r on [0, 1]."""

    def f(x: float) -> float:
        return -k * (x - r) * (1.0 + c * c * (x - r) ** 2)

    root = brent_root(f, 0.0, 1.0, f(0.0), f(1.0))
    assert abs(root - bisection(f, 0.0, 1.0)) <= 8 * math.ulp(r)


@given(st.floats(0.001, 0.999))
def test_root_of_a_drop_is_the_jump(jump: float) -> None:
    """A curve that drops through zero (a restrainer lost) has its 'root' at the jump,
    where bisection puts it; an unknown positive value at lo (inf) is allowed."""
    f = Counted(lambda x: 1.0 - x if x < jump else -1.0)
    root = brent_root(f, 0.0, 1.0, math.inf, -1.0)
    assert abs(root - jump) <= 8 * math.ulp(jump)
    assert f.calls <= MAX_EVALUATIONS


def test_root_at_the_bracket_end_and_bounded_on_noise() -> None:
    assert abs(brent_root(lambda x: -x, -1.0, 0.0, 1.0, 0.0)) < 1e-15
    noisy = Counted(lambda x: math.sin(1e6 * x) - 2.0 * (x - 0.5))
    root = brent_root(noisy, 0.0, 1.0, noisy(0.0), noisy(1.0))
    assert 0.0 <= root <= 1.0 and noisy.calls <= MAX_EVALUATIONS + 2


@settings(max_examples=200, deadline=None)
@given(st.floats(0.05, 0.95), st.floats(0.1, 100.0), st.floats(-5.0, 5.0))
def test_minimum_of_a_parabola(at: float, k: float, c: float) -> None:
    """Found to √ε·x, or to where the parabola's rise drowns in the rounding of c."""
    f = Counted(lambda x: k * (x - at) ** 2 + c)
    x, fx = brent_minimum(f, 0.0, 1.0, 1e-12)
    eps = math.ulp(1.0)
    assert abs(x - at) <= 3 * math.sqrt(eps) * abs(at) + 3 * math.sqrt(eps * (abs(c) + k) / k)
    assert fx == f.f(x) and fx <= c + k * 1e-14
    assert f.calls < 40


def test_minimum_of_a_kink_and_of_a_slope() -> None:
    """|x − 0.3| (no parabola fits its kink: golden steps) and a falling line (the minimum
    at the bracket's end)."""
    kink = Counted(lambda x: abs(x - 0.3))
    x, _ = brent_minimum(kink, 0.0, 1.0, 1e-12)
    assert abs(x - 0.3) < 1e-7 and kink.calls < 100
    x, _ = brent_minimum(lambda x: -x, 0.0, 1.0, 1e-12)
    assert 1.0 - x < 1e-7


def test_root_at_the_start_of_a_zero_plateau_as_bisection() -> None:
    """f positive, then zero over an interval: the root is where it stops being positive (a
    bisection keeping lo where f > 0 finds the same), not the bracket's end."""
    f = Counted(lambda x: 5.0 - x if x < 0.3 else 0.0)
    root = brent_root(f, 0.0, 1.0, f(0.0), f(1.0))
    assert abs(root - 0.3) <= 8 * math.ulp(0.3)
    assert abs(root - bisection(f.f, 0.0, 1.0)) <= 8 * math.ulp(0.3)


@given(st.floats(1e-9, 1.0 - 1e-9))
def test_root_of_a_drop_anywhere_in_the_bracket(jump: float) -> None:
    f = Counted(lambda x: 2.0 - x if x < jump else -0.5)
    root = brent_root(f, 0.0, 1.0, 2.0, -0.5)
    assert abs(root - jump) <= 8 * math.ulp(jump) + 2 * math.ulp(0.0)
    assert f.calls <= MAX_EVALUATIONS
