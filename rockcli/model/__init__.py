"""The model file: pydantic schema, TOML read/write, derivation of the core's parameters.

Validate once, at the edge (spec/style.md, principle 2): :func:`load_model` turns a TOML file
into a frozen :class:`Model` or raises one :class:`~rockcli.errors.InputError`;
:func:`to_block` and :func:`solver_options` give the numeric core its frozen dataclasses of SI
floats. Nothing here imports numpy, scipy or numba.
"""

from rockcli.model.derive import AnalysisOptions, Description, describe, solver_options, to_block
from rockcli.model.load import load_model, to_toml, validate_model
from rockcli.model.schema import Model

__all__ = [
    "AnalysisOptions",
    "Description",
    "Model",
    "describe",
    "load_model",
    "solver_options",
    "to_block",
    "to_toml",
    "validate_model",
]
