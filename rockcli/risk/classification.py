"""The seismic risk class of DM 58/2017 Allegato A (the text of DM 65/2017, 7 March 2017),
conventional method: PAM from the return periods of the capacity T_Rc of each limit state,
IS-V from the SLV's peak ground accelerations, the class of each and the building's.

The steps of Allegato A §2 (conventional method), as this module reads them:

- λ(SL) = 1/T_Rc(SL) for SLO, SLD, SLV and SLC (step 3); for the serviceability states the
  return period is the lesser of its own and the SLV's: λ(SLO) = max[λ(SLO), λ(SLV)],
  λ(SLD) = max[λ(SLD), λ(SLV)] ("non si possa raggiungere lo stato limite di salvaguardia
  della vita senza aver raggiunto gli stati limite di operatività e danno", step 3, note 6).
- SLID, the start of damage: λ = 1/10 years, CR 0 % (step 4); SLR, reconstruction: λ(SLC),
  CR 100 % (step 5). CR of SLO, SLD, SLV, SLC: 7, 15, 50, 80 % (Tab. 3).
- PAM = Σ_{i=2..5} |λ(SL_i) − λ(SL_{i−1})|·[CR(SL_i) + CR(SL_{i−1})]/2 + λ(SLC)·CR(SLR), with
  SL_1..SL_5 = SLID, SLO, SLD, SLV, SLC (step 7): the area under the curve of CR against λ.
  The difference is taken in absolute value: the text writes it with the states in order of
  decreasing λ, which read literally gives a negative area; note 6 says the formula holds
  also when SLD and SLO have longer return periods than the SLV (docs/interpretations.md).
  Its own check: the minimum new building (T_R 30, 50, 475, 975 years) has PAM 1.13 %,
  class B (note to Tab. 1).
- IS-V = PGA_C(SLV)/PGA_D(SLV) (step 9).
- Classes: PAM, Tab. 1 (A+ ≤ 0.50 %, A ≤ 1.0 %, B ≤ 1.5 %, C ≤ 2.5 %, D ≤ 3.5 %, E ≤ 4.5 %,
  F ≤ 7.5 %, G beyond); IS-V, Tab. 2 (A+ > 100 %, A ≥ 80 %, B ≥ 60 %, C ≥ 45 %, D ≥ 30 %,
  E ≥ 15 %, F ≤ 15 %); the building's class is the worse of the two (step 11). On a bound that
  two rows of a table share (PAM 7.5 %: F and G; IS-V 15 %: E and F) the worse class; IS-V of
  exactly 100 %, in neither A+ (> 100 %) nor A (< 100 %): A.
- The classes an intervention gains: the class before less the class after, in the order
  A+ … G (§3.1, "numero di cambi di Classe di Rischio").

Pure and silent: math only.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

#: The classes, best first (Tab. 1: A+ … G; Tab. 2 stops at F).
CLASSES = ("A+", "A", "B", "C", "D", "E", "F", "G")
#: The share of the reconstruction cost each limit state costs (Allegato A, Tab. 3).
CR = {"SLID": 0.0, "SLO": 0.07, "SLD": 0.15, "SLV": 0.50, "SLC": 0.80, "SLR": 1.00}
#: The conventional return period of the start of damage, SLID [years] (step 4).
TR_SLID = 10.0
#: The limit states of the curve, SL_1 … SL_5 (step 7), and those a T_Rc is needed for.
CURVE_STATES = ("SLID", "SLO", "SLD", "SLV", "SLC")
NEEDED = ("SLO", "SLD", "SLV", "SLC")
#: Tab. 1: the upper bound of PAM (included) of each class A+ … F; beyond F's, G.
PAM_BOUNDS = (0.005, 0.010, 0.015, 0.025, 0.035, 0.045, 0.075)
#: Tab. 2: the lower bound of IS-V (included) of each class A … E; above 100 %, A+; else F.
ISV_BOUNDS = (0.80, 0.60, 0.45, 0.30, 0.15)


@dataclass(frozen=True)
class RiskClass:
    """The class of one set of T_Rc and one IS-V.

    Attributes:
        T_Rc: the return periods the curve uses [years], SLO … SLC, after step 3's cap.
        capped: the serviceability states whose T_Rc step 3 lowered to the SLV's.
        rates: λ of each state of the curve, SLID … SLC [1/year].
        PAM: the expected annual loss, a fraction of the reconstruction cost.
        IS_V: PGA_C(SLV)/PGA_D(SLV).
        pam_class, isv_class: the class of each (Tabb. 1, 2). risk_class: the worse.
    """

    T_Rc: dict[str, float]
    capped: tuple[str, ...]
    rates: dict[str, float]
    PAM: float
    IS_V: float
    pam_class: str
    isv_class: str
    risk_class: str


def capped_periods(T_Rc: Mapping[str, float]) -> tuple[dict[str, float], tuple[str, ...]]:  # noqa: N803
    """Step 3: T_Rc of SLO and SLD no longer than the SLV's (and which were lowered)."""
    out = {ls: float(T_Rc[ls]) for ls in NEEDED}
    capped = tuple(ls for ls in ("SLO", "SLD") if out[ls] > out["SLV"])
    for ls in capped:
        out[ls] = out["SLV"]
    return out, capped


def curve_rates(T_Rc: Mapping[str, float]) -> dict[str, float]:  # noqa: N803
    """λ of SLID … SLC (steps 3–4): 1/T_Rc, and the SLID's conventional 1/10 years."""
    return {"SLID": 1.0 / TR_SLID, **{ls: 1.0 / T_Rc[ls] for ls in NEEDED}}


def expected_annual_loss(rates: Mapping[str, float]) -> float:
    """PAM (step 7): the trapezoids of the curve of CR against λ from SLID to SLC, and the
    SLR's rectangle λ(SLC)·CR(SLR)."""
    area = sum(
        abs(rates[b] - rates[a]) * (CR[b] + CR[a]) / 2.0
        for a, b in zip(CURVE_STATES[:-1], CURVE_STATES[1:], strict=True)
    )
    return area + rates["SLC"] * CR["SLR"]


def pam_class(pam: float) -> str:
    """Tab. 1: the class of a PAM (a fraction: 0.0113 is 1.13 %)."""
    for bound, name in zip(PAM_BOUNDS, CLASSES, strict=False):
        if pam <= bound and not (name == "F" and pam == bound):  # 7.5 %: F and G, the worse
            return name
    return CLASSES[-1]


def isv_class(isv: float) -> str:
    """Tab. 2: the class of an IS-V (a fraction: 1.0 is 100 %)."""
    if isv > 1.0:
        return "A+"
    for bound, name in zip(ISV_BOUNDS, CLASSES[1:], strict=False):
        if isv >= bound and not (name == "E" and isv == bound):  # 15 %: E and F, the worse
            return name
    return "F"


def worse(first: str, second: str) -> str:
    """The worse of two classes (step 11)."""
    return max(first, second, key=CLASSES.index)


def classes_gained(before: str, after: str) -> int:
    """How many classes an intervention gains (§3.1): negative when it loses some."""
    return CLASSES.index(before) - CLASSES.index(after)


def classify(T_Rc: Mapping[str, float], IS_V: float) -> RiskClass:  # noqa: N803
    """The class of the return periods of the capacity of SLO, SLD, SLV and SLC [years] and
    the IS-V (every T_Rc finite and positive; the caller checks)."""
    periods, capped = capped_periods(T_Rc)
    rates = curve_rates(periods)
    pam = expected_annual_loss(rates)
    by_pam, by_isv = pam_class(pam), isv_class(IS_V)
    return RiskClass(periods, capped, rates, pam, IS_V, by_pam, by_isv, worse(by_pam, by_isv))
