"""The ground-motion record as the rest of rock sees it."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True, eq=False)
class Record:
    """A ground acceleration history, in fractions of g.

    Attributes:
        name: short label (file stem or pulse description).
        source: where it came from (the path as given, or "generated").
        format: the detected or forced format ("at2", "esm", "coracc", "plain", "pulse").
        time: sample times [s], strictly increasing, starting at time[0] (usually 0).
        accel: ground acceleration at those times [g] (m/s² and cm/s² files are divided by
            standard gravity, :data:`rockcli.units.STANDARD_GRAVITY`).
        dt: nominal sample interval [s] (the uniform spacing; for non-uniform records the
            median spacing).
        unit: the unit the file stored the values in ("g", "m/s2", "cm/s2").
        notes: transformations and remarks to show with results (scaled, flipped, trimmed…).
        warnings: doubts about the record a user must see (an implausible PGA, a resampling
            that lowered the peak); shown under the record's table and in its JSON.
        event: the earthquake as the file's header names it ("" when the format has none).
        station: the recording station as the header names it ("" when absent).
        component: the component or stream as the header names it ("" when absent).
        unit_declared: False when nothing declared the unit and g was assumed (a plain-text
            file read without ``--units`` and without a ``# units:`` line); True when a header
            or the user stated it, and for generated records.
    """

    name: str
    source: str
    format: str
    time: np.ndarray
    accel: np.ndarray
    dt: float
    unit: str = "g"
    notes: tuple[str, ...] = field(default_factory=tuple)
    warnings: tuple[str, ...] = ()
    event: str = ""
    station: str = ""
    component: str = ""
    unit_declared: bool = True

    @property
    def npts(self) -> int:
        """Number of samples."""
        return int(self.accel.size)

    @property
    def duration(self) -> float:
        """time[-1] − time[0] [s]."""
        return float(self.time[-1] - self.time[0])

    @property
    def pga(self) -> float:
        """Peak ground acceleration max|a| [g]."""
        return float(np.max(np.abs(self.accel)))

    @property
    def t_pga(self) -> float:
        """Time of the (first) absolute peak [s]."""
        return float(self.time[int(np.argmax(np.abs(self.accel)))])

    @property
    def uniform(self) -> bool:
        """True when the samples are equally spaced (to 1e-9 relative)."""
        steps = np.diff(self.time)
        return bool(np.allclose(steps, self.dt, rtol=1e-9, atol=0.0))
