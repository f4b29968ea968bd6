"""`rock fragility`: fragility functions (for now, `rock fragility fit` of a data set)."""

from __future__ import annotations

import click

from rockcli.cli.inputs import InputPath, RockCommand, RockCommands
from rockcli.cli.options import output_format


@click.group(cls=RockCommands, short_help="Fragility functions: fit a lognormal fragility.")
def fragility() -> None:
    """Fragility functions: the probability of a damage state given the intensity."""


@fragility.command(cls=RockCommand, short_help="Fit a lognormal fragility to IDA or MSA data.")
@click.argument("data", type=InputPath("file"))
@click.option(
    "--method",
    type=click.Choice(["msa", "ida"]),
    default="msa",
    show_default=True,
    help="msa: columns im, runs, exceedances (counts at intensity levels); ida: column im "
    "(each record's intensity at which the damage state is first reached).",
)
@click.option(
    "--ddof",
    type=click.Choice(["0", "1"]),
    default="0",
    show_default=True,
    help="IDA: the divisor of β², n (0: the maximum likelihood) or n − 1 (1: Baker 2015).",
)
@output_format
def fit(data, method, ddof, output):
    """Fit P(DS | IM) = Φ(ln(IM/θ)/β) to DATA.csv: the median θ and dispersion β, and a 95 %
    bootstrap band. MSA by maximum likelihood on the binomial counts (Baker 2015); IDA as the
    lognormal of the collapse intensities."""
    import numpy as np

    from rockcli.errors import InputError
    from rockcli.fragility.data import read_data
    from rockcli.fragility.fit import ida_band, ida_fit, msa_band, msa_fit
    from rockcli.terminal.fragility import fit_document, fit_report
    from rockcli.terminal.table import show

    found = read_data(data, method)
    try:
        if method == "ida":
            result = ida_fit(found.im, int(ddof))
            at = np.sort(found.im)
            band = ida_band(found.im, at, ddof=int(ddof))
        else:
            assert found.runs is not None and found.exceedances is not None
            result = msa_fit(found.im, found.runs, found.exceedances)
            at = found.im
            band = msa_band(found.im, found.runs, found.exceedances, at)
    except ValueError as exc:
        raise InputError(str(exc), file=data, allowed="a data set that defines a fragility "
                         "(some runs reach the damage state, some do not)") from None  # fmt: skip
    show(fit_document(found, result, at, band), output, fit_report)
