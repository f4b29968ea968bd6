"""`python -m rockcli` runs the command-line interface."""

from rockcli.cli.main import cli

if __name__ == "__main__":
    cli(prog_name="rock")  # the usage lines say "rock", as the installed command
