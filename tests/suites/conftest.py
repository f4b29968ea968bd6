"""Shared helpers of the suite tests: suite files in a temporary folder, the shipped pulses,
the real records and the hazard grid of ../shared (skipped when absent), and an independent
reference for the response spectrum."""

from __future__ import annotations

import math
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import tomli_w

ROOT = Path(__file__).resolve().parents[2]
PULSES = sorted((ROOT / "records").glob("*.txt"))
SHARED = ROOT.parent / "shared"
SHARED_RECORDS = SHARED / "records"
GRID_FILE = SHARED / "ntc" / "AllegatoB.txt"
EXAMPLE_SUITE = ROOT / "examples" / "suites" / "laquila-slv.toml"

#: A target given by its parameters (soil A, T1): S = 1, TC = TC* = 0.3 s, TB = 0.1 s,
#: TD = 4·ag + 1.6 = 2.6 s (NTC §3.2.3.2.1, Eqs. 3.2.7–3.2.9).
TARGET = {"ag": 0.25, "F0": 2.5, "Tc_star": 0.3}


def se_by_hand(T: np.ndarray) -> np.ndarray:
    """Se(T) [g] of TARGET for 0.1 s ≤ T ≤ 2.6 s, written out from NTC Eq. 3.2.4: the plateau
    ag·S·η·F0 up to TC, then ag·S·η·F0·TC/T (η = 1 at 5 %)."""
    plateau = TARGET["ag"] * TARGET["F0"]
    return np.where(T < TARGET["Tc_star"], plateau, plateau * TARGET["Tc_star"] / T)


def write_suite(folder: Path, records: list[dict[str, Any]], **keys: Any) -> Path:
    """A suite file in ``folder`` with these [[records]] and keys (target: TARGET).

    A record given by the absolute path of an existing file elsewhere (a shipped pulse, a
    real record of ../shared) is copied into the folder and named by its file name: a suite
    reads only the files of its own folder unless --allow-outside (rockcli.suites.load).
    """
    data: dict[str, Any] = {"name": "test suite", "target": dict(TARGET), **keys}
    data["records"] = [beside(folder, record) for record in records]
    path = folder / "suite.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    return path


def beside(folder: Path, record: dict[str, Any]) -> dict[str, Any]:
    """The record entry, its file copied into ``folder`` when it lies elsewhere."""
    path = Path(str(record.get("path", "")))
    if not (path.is_absolute() and path.is_file()):
        return record
    if path.resolve().is_relative_to(folder.resolve()):
        return record
    copy = folder / path.name
    if not copy.exists():
        shutil.copyfile(path, copy)
    return {**record, "path": path.name}


def pulse_copies(folder: Path, count: int) -> list[Path]:
    """``count`` record files in ``folder``: the shipped pulses copied under new names, then
    the pulses times 2, 3, … (a suite holds each motion once)."""
    paths = []
    for i in range(count):
        source = PULSES[i % len(PULSES)]
        target = folder / f"rec{i}_{source.name}"
        multiple_of(source, target, 1 + i // len(PULSES))
        paths.append(target)
    return paths


def multiple_of(source: Path, target: Path, factor: float) -> Path:
    """A plain-text record at ``target``: the two-column record ``source`` with its
    accelerations times ``factor`` (a copy when the factor is 1), written to the last digit."""
    if factor == 1:
        shutil.copyfile(source, target)
        return target
    data = np.loadtxt(source, comments="#")
    data[:, 1] *= factor
    np.savetxt(target, data, fmt="%.17g", header="time [s], acceleration [g]")
    return target


@pytest.fixture
def shared_records() -> Path:
    """The folder of real records, or a skip when this clone has no ../shared/records."""
    if not SHARED_RECORDS.is_dir():
        pytest.skip(f"real records not available: {SHARED_RECORDS} is absent (not shipped)")
    return SHARED_RECORDS


@pytest.fixture
def grid_file() -> Path:
    """The NTC hazard grid, or a skip when this clone has no ../shared/ntc/AllegatoB.txt."""
    if not GRID_FILE.is_file():
        pytest.skip(f"NTC hazard grid not available: {GRID_FILE} is absent (not shipped)")
    return GRID_FILE


def newmark_peak(
    time: np.ndarray,
    accel_g: np.ndarray,
    periods: np.ndarray,
    *,
    dt: float,
    tail: float,
    damping: float = 0.05,
) -> np.ndarray:
    """Sa(T) = ω²·max|u| [g] at 5 % damping (or ``damping``, a fraction) by Newmark's average
    acceleration (γ = 1/2, β = 1/4; Chopra §5.4), the ground motion interpolated linearly
    onto steps of ``dt`` (an integer fraction of the record's uniform step) and followed by
    ``tail`` seconds at rest.

    An independent reference for rock's exact (Nigam & Jennings) recurrence: a different
    integrator, a finer step, explicit padding instead of a closed-form tail. Like rock (and
    the usual response-spectrum programs), the peak is taken at the record's own samples while
    the record lasts, and on the fine steps (≈ continuously) after it.
    """
    zeta, gamma, beta = damping, 0.5, 0.25
    sub = round(float(time[1] - time[0]) / dt)
    dt = float(time[1] - time[0]) / sub
    t = time[0] + dt * np.arange(int(round((time[-1] - time[0] + tail) / dt)) + 1)
    p = -np.interp(t, time, accel_g, right=0.0)  # per unit mass, in g
    sampled = (np.arange(t.size) % sub == 0) | (t > time[-1])
    omega = 2.0 * math.pi / periods
    c, k = 2.0 * zeta * omega, omega**2
    u, v, a = np.zeros_like(omega), np.zeros_like(omega), np.full_like(omega, p[0])
    peak = np.zeros_like(omega)
    denominator = 1.0 + gamma * dt * c + beta * dt * dt * k
    for p1, at_sample in zip(p[1:], sampled[1:], strict=True):
        u_star = u + dt * v + (0.5 - beta) * dt * dt * a
        v_star = v + (1.0 - gamma) * dt * a
        a = (p1 - c * v_star - k * u_star) / denominator
        u = u_star + beta * dt * dt * a
        v = v_star + gamma * dt * a
        if at_sample:
            np.maximum(peak, np.abs(u), out=peak)
    return k * peak
