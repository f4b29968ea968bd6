"""What the safety assessment of an existing building requires (NTC 2018 §8.3): the limit
states to be verified for the building's use class, and what the verdict of each means.

§8.3: "La valutazione della sicurezza e la progettazione degli interventi sulle costruzioni
esistenti potranno essere eseguite con riferimento ai soli SLU, salvo che per le costruzioni
in classe d'uso IV, per le quali sono richieste anche le verifiche agli SLE specificate al
§ 7.3.6 […]. Per la combinazione sismica le verifiche agli SLU possono essere eseguite
rispetto alla condizione di salvaguardia della vita umana (SLV) o, in alternativa, alla
condizione di collasso (SLC)". rock reads it (docs/interpretations.md): the ULS is verified at
the SLV (the SLC, where the edition checks it, is reported beside it); the SLE of a local
mechanism is its damage limit state, the SLD, required for class IV only; a CU that is not one
of Tab. 2.4.II's leaves the class unknown, and the ULS alone is required, as for I–III.

Pure: no numpy, no I/O.
"""

from __future__ import annotations

from rockcli.codecheck.categories import USE_COEFFICIENT

#: The ultimate limit state the assessment verifies (§8.3: SLV, or the SLC as an alternative).
ULTIMATE = "SLV"
#: The serviceability limit state of a local mechanism's check (its damage limit state).
SERVICEABILITY = "SLD"


def use_class_of(CU: float) -> str | None:  # noqa: N803 (the code's symbol)
    """The use class whose coefficient is CU (Tab. 2.4.II), or None when none is."""
    for name, coefficient in USE_COEFFICIENT.items():
        if abs(CU - coefficient) < 1e-12:
            return name
    return None


#: The names the 2009 edition's check gives the same limit states (Circolare 617/2009 §C8A.4:
#: the damage and the ultimate limit state, DLS and ULS, checked at the SLD's and the SLV's
#: demand).
EDITION_2009_NAMES = {"SLD": "DLS", "SLV": "ULS"}


def required_limit_states(use_class: str | None, edition: str = "2019") -> tuple[str, ...]:
    """The limit states §8.3 requires for an existing building of ``use_class`` (None:
    unknown, the ULS alone): the SLV for every class, and the SLD too for class IV; named as
    the ``edition``'s check names them (2009: DLS, ULS)."""
    states = (SERVICEABILITY, ULTIMATE) if use_class == "IV" else (ULTIMATE,)
    if edition == "2009":
        return tuple(EDITION_2009_NAMES[s] for s in states)
    return states


def ultimate_states(edition: str = "2019") -> tuple[str, ...]:
    """The ultimate limit state §8.3 requires of every class, named as the edition names it."""
    return (EDITION_2009_NAMES[ULTIMATE],) if edition == "2009" else (ULTIMATE,)
