"""A fragility document read at the edge: the damage states of `rock fragility` output (its
JSON contract: rockcli.studies.fragility.results), for the annual rate of each on a site's
hazard. (`rock fragility fit` writes "im": "im", a measure it cannot know: refused.)

Only a fragility on the peak ground acceleration can be put on the NTC hazard, whose grid
gives ag (and, with the soil, the surface PGA): ``"im": "pga"``. Every other measure is
refused in one line naming it and what is accepted.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

from rockcli.errors import InputError
from rockcli.studies.fragility.study import MAX_INTENSITY, Measure
from rockcli.textfile import TOML_LIMIT, read_text

#: The intensity measures whose hazard the NTC grid gives.
ACCEPTED_IM = ("pga",)
#: A fragility document's size limit [bytes] (a study's records and bands fit well inside).
FRAGILITY_LIMIT = 16 * TOML_LIMIT
#: The most damage states read (a study's points × states).
MAX_STATES = 1000
#: Bounds of a median [g] (the largest PGA a fragility study may name) and of a dispersion.
MEDIAN_MAX = MAX_INTENSITY[Measure.PGA]
BETA_MAX = 5.0

ACCEPTED_TEXT = 'the JSON of `rock fragility` with [intensity] measure = "pga"'


@dataclass(frozen=True)
class FragilityState:
    """One damage state: its name, median θ [g] and dispersion β (None: not fitted)."""

    name: str
    median: float | None
    beta: float | None
    point: str = ""

    @property
    def fitted(self) -> bool:
        """The fragility gives its median and dispersion."""
        return self.median is not None and self.beta is not None


def read_fragility(path: str) -> tuple[FragilityState, ...]:
    """The damage states of the fragility document at ``path`` (InputError naming the file
    and the key otherwise)."""
    text = read_text(path, "fragility file", FRAGILITY_LIMIT)
    try:
        doc = json.loads(text)
    except RecursionError:
        raise InputError("not JSON (nested too deep)", file=path, allowed=ACCEPTED_TEXT) from None
    except ValueError as exc:
        raise InputError(f"not JSON ({exc})", file=path, allowed=ACCEPTED_TEXT) from None
    if not isinstance(doc, dict) or not isinstance(doc.get("damage_states"), list):
        raise InputError("no damage_states list", file=path, where="damage_states",
                         allowed=ACCEPTED_TEXT)  # fmt: skip
    im = doc.get("im")
    if im not in ACCEPTED_IM:
        raise InputError(
            "no im key" if im is None else "the intensity is not the PGA the hazard grid gives",
            file=path,
            where="im",
            value=im,
            allowed=f"one of: {', '.join(ACCEPTED_IM)}: {ACCEPTED_TEXT}",
        )
    states = doc["damage_states"]
    if not states or len(states) > MAX_STATES:
        raise InputError(f"{len(states)} damage states", file=path, where="damage_states",
                         allowed=f"1 to {MAX_STATES}")  # fmt: skip
    return tuple(_state(path, k, entry) for k, entry in enumerate(states))


def _state(path: str, k: int, entry: Any) -> FragilityState:
    where = f"damage_states[{k}]"
    if not isinstance(entry, dict):
        raise InputError("not an object", file=path, where=where, allowed="{name, median, beta}")
    name = entry.get("name")
    if not isinstance(name, str) or not name:
        raise InputError("no name", file=path, where=f"{where}.name", allowed="a text")
    median, beta = entry.get("median", "missing"), entry.get("beta", "missing")
    if median is None and beta is None:  # the study could not fit it: said in the output
        return FragilityState(name, None, None, _point(entry))
    _bounded(path, f"{where}.median", median, MEDIAN_MAX, "g")
    _bounded(path, f"{where}.beta", beta, BETA_MAX, "")
    return FragilityState(name, float(median), float(beta), _point(entry))


def _bounded(path: str, where: str, value: Any, high: float, unit: str) -> None:
    ok = isinstance(value, (int, float)) and not isinstance(value, bool)
    try:
        ok = ok and math.isfinite(float(value)) and 0.0 < float(value) <= high
    except OverflowError:  # an integer of hundreds of digits
        ok = False
    if not ok:
        bound = f"a number in (0, {high:g}]" + (f" {unit}" if unit else "")
        raise InputError("not usable", file=path, where=where, value=value, allowed=bound)


def _point(entry: dict[str, Any]) -> str:
    """A study point's labels (a fragility over several models), as text."""
    point = entry.get("point")
    return ", ".join(f"{k} = {v}" for k, v in point.items()) if isinstance(point, dict) else ""
