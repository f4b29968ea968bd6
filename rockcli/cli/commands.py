"""The list of commands of `rock` (each in its own module)."""

from __future__ import annotations

import click

from rockcli.cli.assess import assess
from rockcli.cli.compare import compare
from rockcli.cli.fragility import fragility
from rockcli.cli.init import init
from rockcli.cli.kinematic import kinematic
from rockcli.cli.overturning import spectrum
from rockcli.cli.record import record
from rockcli.cli.report import report
from rockcli.cli.retrofit import retrofit
from rockcli.cli.risk import risk
from rockcli.cli.suite import suite
from rockcli.cli.sweep import sweep
from rockcli.cli.validate import validate
from rockcli.cli.warmup import warmup

ALL: list[click.Command] = []
ALL.append(record)
ALL.append(init)
ALL.append(assess)
ALL.append(kinematic)
ALL.append(compare)
ALL.append(warmup)
ALL.append(sweep)
ALL.append(retrofit)
ALL.append(suite)
ALL.append(report)
ALL.append(validate)
ALL.append(fragility)
ALL.append(spectrum)
ALL.append(risk)
