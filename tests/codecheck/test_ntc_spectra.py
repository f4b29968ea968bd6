"""The NTC elastic spectrum and return period (rockcli.codecheck.spectra).

Sources: the test vectors of spec/ntc.md ("Test vectors", computed from the NTC formulas; the
tolerance is half a unit of the last printed digit), the NTC tables (Tab. 3.2.V–VII, 3.2.I,
§2.4.3) and closed forms of the formulas themselves.
"""

from __future__ import annotations

import math

import pytest

from rockcli.codecheck.spectra import (
    ElasticSpectrum,
    LimitState,
    Soil,
    Topography,
    corner_periods,
    damping_correction,
    period_coefficient,
    pga_ground,
    reference_period,
    return_period,
    soil_amplification,
    topographic_amplification,
)
from rockcli.errors import InputError

#: spec/ntc.md test vector: grid node (6.5448 E, 45.134 N), TR 475 years: ag [g], F0, TC* [s].
NODE_AG, NODE_F0, NODE_TC = 0.0943, 2.44, 0.27


def at_node(soil: Soil | str = Soil.A, topography: Topography = Topography.T1) -> ElasticSpectrum:
    """The spectrum at the spec/ntc.md grid node."""
    return ElasticSpectrum(NODE_AG, NODE_F0, NODE_TC, soil, topography)  # type: ignore[arg-type]


def digits(printed: str) -> float:
    """Half a unit of the last printed digit: the tolerance of a printed value."""
    decimals = len(printed.split(".")[1]) if "." in printed else 0
    return 0.5 * 10.0**-decimals


# --- spec/ntc.md test vectors -----------------------------------------------------------------


@pytest.mark.parametrize(
    ("quantity", "printed"),
    [("TB", "0.09"), ("TC", "0.27"), ("TD", "1.9772")],
)
def test_node_corner_periods_soil_A(quantity: str, printed: str) -> None:
    spectrum = at_node(Soil.A)
    assert getattr(spectrum, quantity) == pytest.approx(float(printed), abs=digits(printed))


@pytest.mark.parametrize(("T", "printed"), [(0.3, "0.2071"), (1.09, "0.0570")])
def test_node_Se_soil_A(T: float, printed: str) -> None:
    spectrum = at_node(Soil.A)
    assert spectrum.Se(T) == pytest.approx(float(printed), abs=digits(printed))


def test_node_spectrum_soil_C() -> None:
    spectrum = at_node(Soil.C)
    assert spectrum.S_S == pytest.approx(1.5, abs=digits("1.5"))
    assert spectrum.C_C == pytest.approx(1.6175, abs=digits("1.6175"))
    assert spectrum.Se(0.3) == pytest.approx(0.3451, abs=digits("0.3451"))
    assert spectrum.SDe(1.09) == pytest.approx(0.04083, abs=digits("0.04083"))


# --- damping correction η (NTC Eq. 3.2.6, ξ in percent) ----------------------------------------


def test_eta_reference_damping_is_one() -> None:
    assert damping_correction(5.0) == 1.0


def test_eta_ten_percent() -> None:
    # √(10/15) = 0.81650
    assert damping_correction(10.0) == pytest.approx(0.8165, abs=digits("0.8165"))


def test_eta_floor() -> None:
    # √(10/35) = 0.5345 < 0.55 → the floor; ξ = 28 gives √(10/33) = 0.5505, above it.
    assert damping_correction(30.0) == 0.55
    assert damping_correction(28.0) == pytest.approx(math.sqrt(10 / 33), rel=1e-15)


def test_eta_refuses_impossible_damping() -> None:
    with pytest.raises(InputError, match="xi"):
        damping_correction(-5.0)


# --- return period (NTC §3.2.1 Tab. 3.2.I, §2.4.3) -----------------------------------------------


@pytest.mark.parametrize(
    ("limit_state", "printed"),
    [
        (LimitState.SLO, "30.1"),  # −50/ln(0.19)
        (LimitState.SLD, "50.3"),  # −50/ln(0.37)
        (LimitState.SLV, "474.6"),  # −50/ln(0.90)
        (LimitState.SLC, "974.8"),  # −50/ln(0.95)
    ],
)
@pytest.mark.parametrize("edition", ["2009", "2019"])
def test_return_period_VN50_CU1(limit_state: LimitState, printed: str, edition: str) -> None:
    TR = return_period(50.0, 1.0, limit_state, edition)
    assert TR == pytest.approx(float(printed), abs=digits(printed))


def test_2009_floor_of_35_years_on_VR() -> None:
    # NTC 2008 §2.4.3: VN·CU = 10·0.7 = 7 years → VR = 35; TR(SLV) = −35/ln(0.9) = 332.19.
    assert reference_period(10.0, 0.7, "2009") == 35.0
    assert return_period(10.0, 0.7, LimitState.SLV, "2009") == pytest.approx(
        -35.0 / math.log(0.9), rel=1e-15
    )
    # above the floor it changes nothing
    assert reference_period(50.0, 1.5, "2009") == 75.0


def test_2019_has_no_floor_on_VR() -> None:
    # see reference_period's docstring: no floor applied for NTC 2018 (unverified text)
    assert reference_period(10.0, 0.7, "2019") == pytest.approx(7.0, rel=1e-15)


def test_unknown_edition() -> None:
    with pytest.raises(InputError, match="edition"):
        return_period(50.0, 1.0, LimitState.SLV, "2008")


# --- Tab. 3.2.V: S_S with its bounds, C_C; Tab. 3.2.VI: S_T --------------------------------------

#: soil: (c0, c1, lower, upper) of S_S = c0 − c1·F0·ag/g, from spec/ntc.md's table.
SS_TABLE = {
    Soil.B: (1.40, 0.40, 1.00, 1.20),
    Soil.C: (1.70, 0.60, 1.00, 1.50),
    Soil.D: (2.40, 1.50, 0.90, 1.80),
    Soil.E: (2.00, 1.10, 1.00, 1.60),
}


@pytest.mark.parametrize("soil", list(SS_TABLE))
def test_S_S_clipped_at_both_ends_and_linear_between(soil: Soil) -> None:
    c0, c1, low, high = SS_TABLE[soil]
    F0 = 2.5
    # F0·ag tiny → c0 above the upper bound; F0·ag = 1.5 → c0 − 1.5·c1 below the lower bound
    assert soil_amplification(soil, 0.001 / F0, F0) == high
    assert soil_amplification(soil, 1.5 / F0, F0) == low
    # midway between the two clipping points the formula itself applies
    mid = 0.5 * ((c0 - high) / c1 + (c0 - low) / c1)
    assert soil_amplification(soil, mid / F0, F0) == pytest.approx(c0 - c1 * mid, rel=1e-12)
    assert low < soil_amplification(soil, mid / F0, F0) < high


def test_S_S_soil_A_is_one() -> None:
    assert soil_amplification(Soil.A, 0.5, 3.0) == 1.0


@pytest.mark.parametrize(
    ("soil", "expected"),
    [
        (Soil.A, 1.0),
        (Soil.B, 1.10 * 0.3**-0.20),
        (Soil.C, 1.05 * 0.3**-0.33),
        (Soil.D, 1.25 * 0.3**-0.50),
        (Soil.E, 1.15 * 0.3**-0.40),
    ],
)
def test_C_C_table(soil: Soil, expected: float) -> None:
    assert period_coefficient(soil, 0.3) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize(
    ("topography", "S_T"),
    [(Topography.T1, 1.0), (Topography.T2, 1.2), (Topography.T3, 1.2), (Topography.T4, 1.4)],
)
def test_S_T_table(topography: Topography, S_T: float) -> None:
    assert topographic_amplification(topography) == S_T


def test_S_is_S_S_times_S_T() -> None:
    spectrum = at_node(Soil.B, Topography.T4)
    assert spectrum.S == pytest.approx(1.20 * 1.4, rel=1e-15)  # B clipped at 1.20 here
    assert spectrum.pga_ground == pytest.approx(NODE_AG * 1.20 * 1.4, rel=1e-15)
    assert pga_ground(spectrum) == spectrum.pga_ground


def test_corner_periods_formulas() -> None:
    TB, TC, TD = corner_periods(Soil.D, 0.25, 0.4)
    assert TC == pytest.approx(1.25 * 0.4**-0.5 * 0.4, rel=1e-15)
    assert TB == pytest.approx(TC / 3, rel=1e-15)
    assert TD == pytest.approx(4.0 * 0.25 + 1.6, rel=1e-15)


# --- the spectrum's shape ------------------------------------------------------------------------

SPECTRA = [
    at_node(Soil.A),
    at_node(Soil.C, Topography.T2),
    ElasticSpectrum(ag=0.26, F0=2.36, Tc_star=0.35, soil=Soil.D),
]


@pytest.mark.parametrize("spectrum", SPECTRA)
@pytest.mark.parametrize("xi", [5.0, 10.0, 30.0])
@pytest.mark.parametrize("corner", ["TB", "TC", "TD"])
def test_Se_continuous_at_corners(spectrum: ElasticSpectrum, xi: float, corner: str) -> None:
    T = getattr(spectrum, corner)
    # the left branch at T(1 − 1e-12) against the right branch at T: the formulas join
    assert spectrum.Se(T * (1 - 1e-12), xi) == pytest.approx(spectrum.Se(T, xi), rel=1e-9)


@pytest.mark.parametrize("spectrum", SPECTRA)
def test_Se_at_zero_period_is_ag_S(spectrum: ElasticSpectrum) -> None:
    assert spectrum.Se(0.0) == pytest.approx(spectrum.ag * spectrum.S, rel=1e-15)


@pytest.mark.parametrize("spectrum", SPECTRA)
def test_SDe_is_Se_g_T_over_2pi_squared_up_to_TE(spectrum: ElasticSpectrum) -> None:
    for T in (0.1, 0.5, 1.0, 2.5, spectrum.TE):
        expected = spectrum.Se(T) * 9.81 * (T / (2 * math.pi)) ** 2
        assert spectrum.SDe(T) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize("spectrum", SPECTRA)
def test_SDe_at_TE_steps_down_as_the_code_writes_it(spectrum: ElasticSpectrum) -> None:
    # Not continuous in the code itself: Se·g·(T/2π)² at TE (T > TD) is ag·g·S·η·F0·TC·TD/4π²,
    # the TE–TF branch starts at 0.025·ag·g·S·TC·TD·F0·η: ratio 0.025·4π² = 0.98696.
    TE = spectrum.TE
    ratio = spectrum.SDe(TE * (1 + 1e-12)) / spectrum.SDe(TE)
    assert ratio == pytest.approx(0.025 * 4 * math.pi**2, rel=1e-9)


@pytest.mark.parametrize("spectrum", SPECTRA)
def test_SDe_reaches_dg_at_TF_and_stays(spectrum: ElasticSpectrum) -> None:
    dg = 0.025 * spectrum.ag * 9.81 * spectrum.S * spectrum.TC * spectrum.TD
    assert spectrum.SDe(spectrum.TF) == pytest.approx(dg, rel=1e-12)
    assert spectrum.SDe(spectrum.TF * 1.5) == pytest.approx(dg, rel=1e-15)


def test_TE_per_soil() -> None:
    TE = {soil: at_node(soil).TE for soil in Soil}
    assert TE == {Soil.A: 4.5, Soil.B: 5.0, Soil.C: 6.0, Soil.D: 6.0, Soil.E: 6.0}


def test_curve_matches_pointwise() -> None:
    spectrum = SPECTRA[1]
    Se, SDe = spectrum.curve([0.0, 0.3, 1.09, 7.0], xi=10.0)
    assert Se[2] == spectrum.Se(1.09, 10.0)
    assert SDe[3] == spectrum.SDe(7.0, 10.0)


# --- bad input ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("field", "values"),
    [("ag", (0.0, 2.44, 0.27)), ("F0", (0.0943, -1.0, 0.27)), ("Tc_star", (0.0943, 2.44, 0.0))],
)
def test_non_positive_parameters_refused(field: str, values: tuple[float, float, float]) -> None:
    with pytest.raises(InputError, match=field):
        ElasticSpectrum(*values)


def test_unknown_soil_refused() -> None:
    with pytest.raises(InputError, match="soil"):
        at_node("F")


def test_soil_given_as_text_is_accepted() -> None:
    assert at_node("C").soil is Soil.C


def test_negative_period_refused() -> None:
    with pytest.raises(InputError, match="T"):
        SPECTRA[0].Se(-0.1)
