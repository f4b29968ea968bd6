"""rock from Python: the command line's analyses as functions, for notebooks and scripts.

Each function takes what the command takes and returns a :class:`Result`: the analysis' own
result object and its document, the very JSON ``rock … --format json`` prints (same keys, same
numbers). Bad input raises :class:`rockcli.errors.InputError` (one line: the file, the key,
the value and what is allowed), as the command exits 2 with that line. See docs/python.md.

    >>> import rockcli
    >>> record = rockcli.read_record("records/ricker_Tp0.5s_0.5g.txt")
    >>> result = rockcli.compare("examples/altar.toml", record)
    >>> result.document["classification"]
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rockcli.model.schema import Model
    from rockcli.records.record import Record


@dataclass(frozen=True)
class Result:
    """An analysis' result.

    Attributes:
        document: what ``--format json`` prints, as Python values (dicts, lists, numbers).
        output: the analysis' own result object (``KinematicOutput``, ``AssessmentOutput``,
            ``ComparisonOutput``: the time histories of ``assess(…, history=True)`` are there).
    """

    document: dict[str, Any]
    output: Any

    def to_json(self) -> str:
        """The document as the command prints it (indented JSON, no NaN)."""
        return json.dumps(self.document, indent=2, allow_nan=False)


def load_model(path: str | Path) -> Model:
    """The model file, read and validated (``rock validate``'s reading): a frozen pydantic
    model whose fields are the file's keys (docs/model-reference.md)."""
    from rockcli.model.load import load_model as load

    return load(str(path))


def read_record(
    path: str | Path,
    *,
    fmt: str | None = None,
    dt: float | None = None,
    units: str | None = None,
    scale: float | None = None,
    pga: float | None = None,
) -> Record:
    """A ground-motion record in g, as ``--record`` reads it (``--format``, ``--dt``,
    ``--units``, ``--scale``, ``--pga``): AT2, ESM ASCII, ITACA cor.acc or plain text."""
    from rockcli.records import files, transform

    record = files.read_record(path, fmt=fmt, dt=dt, units=units)
    if scale is not None:
        record = transform.scale(record, scale)
    if pga is not None:
        record = transform.scale_to_pga(record, pga)
    return record


def kinematic(
    model: str | Path,
    *,
    record: Record | None = None,
    edition: str | None = None,
    site: tuple[float, float] | None = None,
    grid_file: str | None = None,
    mechanism: str | None = None,
) -> Result:
    """``rock kinematic MODEL``: the code's kinematic analysis of every mechanism (α0, e*, a0*,
    d0*, the capacity curve and the checks), under the record's spectrum, a site (lon, lat with
    the hazard grid) or the model's own demand; ``mechanism`` names the one detailed."""
    from rockcli.analyses.kinematic import run_kinematic
    from rockcli.terminal.kinematic import kinematic_document

    out = run_kinematic(str(model), edition=edition, record=record, site=site,
                        grid_file=grid_file)  # fmt: skip
    return Result(kinematic_document(out.name, out.result, out.warnings, mechanism), out)


def assess(
    model: str | Path,
    record: Record,
    *,
    engine: str = "fast",
    ground: bool = False,
    mechanism: str | None = None,
    history: bool = False,
) -> Result:
    """``rock assess MODEL --record REC``: the rocking time history of both polarities and the
    verdict; ``ground`` rocks a block at height on the record itself; ``history`` keeps θ(t)
    (``result.output.result.runs[k].history``)."""
    from rockcli.analyses.assess import run_assessment_output
    from rockcli.terminal.assess import assessment_output_document

    out = run_assessment_output(str(model), record, engine, history=history, ground=ground,
                                mechanism=mechanism)  # fmt: skip
    return Result(assessment_output_document(out, record), out)


def compare(
    model: str | Path,
    record: Record,
    *,
    engine: str = "fast",
    edition: str | None = None,
    grid_file: str | None = None,
    code_demand: str = "record",
    ground: bool = False,
    mechanism: str | None = None,
) -> Result:
    """``rock compare MODEL --record REC``: both analyses on the same earthquake, side by side,
    and their classification (``code_demand="model"``: the code check on the model's own
    spectrum instead of the record's)."""
    from rockcli.analyses.compare import run_comparison_output
    from rockcli.terminal.compare import comparison_output_document, comparison_warnings

    out = run_comparison_output(str(model), record, engine=engine, edition=edition,
                                grid_file=grid_file, code_demand=code_demand, ground=ground,
                                mechanism=mechanism)  # fmt: skip
    document = comparison_output_document(out, record)
    document["warnings"] = comparison_warnings(document)
    return Result(document, out)
