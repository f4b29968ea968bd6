"""The exit codes of `rock`, one meaning each (documented in the README)."""

from __future__ import annotations

#: The command did what was asked.
EXIT_DONE = 0
#: A verdict gate the user asked for (--fail-on-overturn, --fail-on, --fail-on-uls) tripped;
#: `rock validate`: a case of the casebook is outside its tolerance.
EXIT_GATE = 1
#: Bad input (same as click's usage errors).
EXIT_INPUT = 2
#: An unexpected exception (a bug of rock) or a run that broke down (a non-finite state).
EXIT_INTERNAL = 3
#: Interrupted by Ctrl-C (128 + SIGINT, the shell's convention).
EXIT_INTERRUPTED = 130

#: Where internal errors should be reported.
REPORT_TO = "the rock maintainers"
#: The RunStatus of a run whose integration produced NaN or infinity.
NON_FINITE = "non-finite"


def non_finite_line(runs: list[dict]) -> str | None:
    """The error line when a rocking run ended in a non-finite state, else None."""
    bad = [r for r in runs if r.get("status") == NON_FINITE]
    if not bad:
        return None
    which = "; ".join(f"polarity {r['polarity']:+d}: {r.get('message', '')}" for r in bad)
    return (
        f"internal error: the rocking integration produced a non-finite state ({which}); "
        f"the result above is not reliable — please report it to {REPORT_TO}"
    )
