"""`python -m rockcli` runs the command-line interface."""

import sys

from rockcli.process import exit_at_once

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
        exit_at_once(EXIT_INTERRUPTED)
    except SystemExit as exc:
        if exc.code == EXIT_INTERRUPTED:
            exit_at_once(EXIT_INTERRUPTED)
        raise


if __name__ == "__main__":
    main()
