"""The response of a model to a scaled earthquake, as fragility and overturning spectra need it.

A model, a ground motion and (for a wall) a mechanism are prepared once (:func:`prepare`):
the block the time history rocks and the motion it sees, exactly as `rock assess` derives
them (rockcli.analyses.assess.rocked_input: a block at height on its floor motion, a wall's
mechanism the one named or the governing one). The floor motion is a linear filter of the
ground motion (rockcli.analyses.floor), so the ground scaled by s gives the floor motion scaled
by s, and each run scales the prepared motion.

The response of a run (:meth:`ScaledRun.response`) is the damage measure of the search
(rockcli.studies.fragility.search): max|θ|/α over both polarities, +inf when either polarity
overturns (spec/rocking.md: the verdict is the worse polarity's).

Pure and silent apart from the model derivation's own InputErrors.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from rockcli.dynamics.settings import SolverSettings
    from rockcli.mechanics import Rocker
    from rockcli.model.schema import Model
    from rockcli.records.record import Record


@dataclass(frozen=True)
class ScaledRun:
    """What a scaled run needs: the block, the motion it sees at scale 1, the settings.

    Attributes:
        block: the rocked block (a wall's mechanism as a block of its own shape).
        time, accel, dt: the motion the block sees at scale 1 [s], [g], [s].
        settings: the model's solver settings.
        engine: "fast" or "reference".
        mechanism: the mechanism's name (None: a model of one block).
    """

    block: Rocker
    time: np.ndarray
    accel: np.ndarray
    dt: float
    settings: SolverSettings
    engine: str = "fast"
    mechanism: str | None = None

    def response(self, scale: float) -> float:
        """max|θ|/α over both polarities of the motion × scale; +inf when it overturns.

        Raises:
            UndecidedRun (rockcli.studies.fragility.spectrum): a run met a non-finite number or did
            not finish.
        """
        from rockcli.dynamics.result import Verdict
        from rockcli.dynamics.settings import Engine
        from rockcli.dynamics.simulate import assess
        from rockcli.studies.fragility.spectrum import UndecidedRun

        result = assess(
            self.block,
            self.time,
            self.accel * scale,
            self.dt,
            settings=self.settings,
            engine=Engine(self.engine),
        )
        verdict = result.verdict
        if verdict is Verdict.OVERTURNS:
            return math.inf
        if verdict is not Verdict.SURVIVES:
            message = next((r.message for r in result.runs if r.message), "undecided")
            raise UndecidedRun(f"the run at scale {scale:.6g} decides nothing: {message}")
        return result.max_ratio


def prepare(
    model: Model,
    record: Record,
    *,
    mechanism: str | None = None,
    ground: bool = False,
    engine: str = "fast",
    file: str | None = None,
) -> ScaledRun:
    """The model's rocked block and the motion it sees under the record at scale 1."""
    from rockcli.analyses.assess import rocked_input, settings_from
    from rockcli.model.derive import solver_options

    block, shaking, _, rocked = rocked_input(model, record, ground, file, mechanism)
    return ScaledRun(
        block=block,
        time=shaking.time,
        accel=np.asarray(shaking.accel, dtype=float),
        dt=shaking.dt,
        settings=settings_from(solver_options(model)),
        engine=engine,
        mechanism=rocked[0] if rocked is not None else None,
    )
