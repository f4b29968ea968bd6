"""`python -m rockcli` runs the command-line interface."""

import sys

#: Exit code after Ctrl-C (rockcli.cli.exits.EXIT_INTERRUPTED, not imported: it loads click).
EXIT_INTERRUPTED = 130


def main() -> None:
    """Run `rock`; after Ctrl-C, end with 130 here.

    Under ``python -m``, CPython 3.11 ends a process whose Ctrl-C went through an import
    (rock imports lazily, so in its first second most do) by SIGINT, after it handled the
    interrupt and asked for exit 130: the parent sees −2, not 130 (a script such as the
    installed `rock` exits at SystemExit, with 130). rockcli.process.exit_at_once ends it.
    """
    try:
        from rockcli.cli.main import cli

        cli(prog_name="rock")  # the usage lines say "rock", as the installed command
    except KeyboardInterrupt:  # Ctrl-C while the command loads: as during the command
        sys.stderr.write("interrupted\n")
        _exit_at_once(EXIT_INTERRUPTED)
    except SystemExit as exc:
        if exc.code == EXIT_INTERRUPTED:
            _exit_at_once(EXIT_INTERRUPTED)
        _ignore_late_interrupts()
        raise


def _ignore_late_interrupts() -> None:
    """The command has ended (its output written, its code decided): a Ctrl-C from now on is
    ignored. CPython's finalization puts SIGINT back to the system's default before the
    process ends, so a Ctrl-C in those last milliseconds killed it by the signal (the parent
    saw −2, neither the command's code nor 130); an ignored signal stays ignored."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _exit_at_once(code: int) -> None:
    """rockcli.process.exit_at_once, imported when needed: the module imported at the top of
    the `rock` script stays as small as can be, so that a Ctrl-C in the interpreter's start-up
    window outside rock's reach is as short as it can be."""
    from rockcli.process import exit_at_once

    exit_at_once(code)


if __name__ == "__main__":
    main()
