"""Bounded fuzz of the retrofit options' readers: any text gives numbers or one InputError."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.studies.retrofit.candidates import parse_at, parse_diameters

#: Text a user may type: digits, signs, separators, exponents, words, unicode.
TYPED = st.text(alphabet=st.sampled_from(list("0123456789.,-+eE xinfa;Ø")), max_size=30) | st.text(
    max_size=30
)


@settings(max_examples=400, deadline=None)
@given(TYPED)
def test_diameters_parse_or_refuse_in_one_line(text: str) -> None:
    try:
        values = parse_diameters(text)
    except InputError as exc:
        assert exc.where == "--diameters" and "\n" not in str(exc)
        return
    assert values and list(values) == sorted(set(values))
    assert all(math.isfinite(v) and v > 0 for v in values)


@settings(max_examples=400, deadline=None)
@given(TYPED)
def test_at_parses_or_refuses_in_one_line(text: str) -> None:
    try:
        height, from_pivot = parse_at(text)
    except InputError as exc:
        assert exc.where == "--at" and "\n" not in str(exc)
        return
    assert math.isfinite(height) and math.isfinite(from_pivot)
