"""Property: whatever the text, a reader returns a Record or raises one InputError.

spec/records.md and the brief: "never a raw ValueError/IndexError escaping". The alphabet holds
the characters of the record headers, so hypothesis reaches deep into every reader.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.records.parse import parse_text

ALPHABET = "0123456789 .-+eE:\n\r#NPTSDTUNITSOFGnaif,=()"
HEADERS = st.sampled_from([
    "",
    "A\nB\nACCELERATION IN UNITS OF G\nNPTS= 3, DT= .01 SEC\n",
    "A\nB\nThe units are (g)\n3  0.01  NPTS, DT\n",
    "EVENT_NAME: X\nEVENT_ID: Y\nSAMPLING_INTERVAL_S: 0.01\nNDATA: 3\nUNITS: cm/s^2\n",
    "a:1\nb:2\nc:3\nd:4\ne:5\nf:6\nTime Increment (s) : 0.01\nNumber of Data : 3\ni:9\nj\n",
])  # fmt: skip


@settings(max_examples=300, deadline=None)
@given(head=HEADERS, body=st.text(alphabet=ALPHABET, max_size=200),
       fmt=st.sampled_from([None, "at2", "esm", "coracc", "plain"]),
       dt=st.sampled_from([None, 0.01, -1.0, float("nan")]))  # fmt: skip
def test_readers_raise_only_input_error(head: str, body: str, fmt: str | None, dt: float) -> None:
    try:
        record = parse_text(head + body, fmt=fmt, dt=dt)
    except InputError:
        return
    assert record.npts >= 1 and record.dt > 0
    assert np.isfinite(record.accel).all()
    assert (np.diff(record.time) > 0).all()


@pytest.mark.parametrize("text", ["", "\n\n", "#only comments\n", "\r\r\n"])
def test_empty_texts(text: str) -> None:
    with pytest.raises(InputError):
        parse_text(text)
