"""Plots of the results (PNG or SVG, chosen by the file suffix): output, like the tables.

matplotlib is an optional dependency (``pip install '.[plot]'`` from the repository's
folder), imported inside the functions (:mod:`.files`), so that ``rock --help`` and the
numeric core never load it; the modules here import only the standard library at their top.

- :func:`plot_assessment`: θ/α of both polarities against time, over the record.
- :func:`plot_kinematic`: the capacity curve a*–d* with the checks' demands.
- :func:`plot_comparison`: both, side by side.
- :func:`plot_sweep`: the collapse map of a systemic study, code against rocking.
- :func:`plot_suite`: a record suite's spectra, their mean, the target and its band.
"""

from __future__ import annotations

from rockcli.plots.capacity import plot_kinematic
from rockcli.plots.collapse import outcome, plot_sweep
from rockcli.plots.comparison import plot_comparison
from rockcli.plots.files import MISSING, OPTION, check_plot_path, plot_format
from rockcli.plots.histories import plot_assessment
from rockcli.plots.suite import plot_suite

__all__ = [
    "MISSING",
    "OPTION",
    "check_plot_path",
    "outcome",
    "plot_assessment",
    "plot_comparison",
    "plot_format",
    "plot_kinematic",
    "plot_suite",
    "plot_sweep",
]
