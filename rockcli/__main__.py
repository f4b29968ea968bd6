"""`python -m rockcli` runs the command-line interface."""

import sys

if __name__ == "__main__":
    try:
        from rockcli.cli.main import cli
    except KeyboardInterrupt:  # Ctrl-C while the command loads: as during the command
        sys.stderr.write("interrupted\n")
        sys.exit(130)
    cli(prog_name="rock")  # the usage lines say "rock", as the installed command
