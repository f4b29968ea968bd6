"""The `rock` command group: the one place where an exception becomes an error line and exit code.

Exit codes (one meaning each): 0 done, 1 a verdict gate the user asked for (``--fail-on…``),
2 bad input, 3 an internal error, 130 interrupted (Ctrl-C). A closed pipe on standard output
(``rock kinematic … | head -1``) ends quietly with 0.

Command modules keep numpy, scipy and numba imports inside their functions, so that
``rock --help`` and model validation start without them.
"""

from __future__ import annotations

import os
import re
import sys
import traceback
import warnings

import click

from rockcli.cli.console import make_output_encodable
from rockcli.cli.exits import EXIT_INPUT, EXIT_INTERNAL, EXIT_INTERRUPTED, REPORT_TO
from rockcli.cli.invocation import set_command_line
from rockcli.errors import RockError, printable
from rockcli.process import interrupted
from rockcli.version import __version__

#: Set to 1 to see the traceback of an internal error.
DEBUG_VARIABLE = "ROCK_DEBUG"
#: click's own control flow: let click handle these.
_CLICK_FLOW = (click.exceptions.ClickException, click.exceptions.Exit, click.exceptions.Abort)


def debug_enabled() -> bool:
    """True when ROCK_DEBUG asks for tracebacks."""
    return os.environ.get(DEBUG_VARIABLE, "") not in ("", "0")


def internal_error_line(exc: BaseException) -> str:
    """The one line of an unexpected exception."""
    return (
        f"internal error: {type(exc).__name__}: {printable(str(exc))} — please report it to "
        f"{REPORT_TO} with the output of {DEBUG_VARIABLE}=1"
    )


def quiet_broken_pipe() -> None:
    """Standard output's reader went away: point stdout at devnull so that Python's final
    flush does not print "Exception ignored" (the recipe of the Python docs, "Note on
    SIGPIPE")."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass  # not a real file (a test runner's buffer): nothing to flush at exit
    finally:
        os.close(devnull)


class UsageLine(click.UsageError):
    """click's own usage error (a missing argument, an unknown option, a value outside a
    choice), shown as rock's errors are: one ``error:`` line, exit 2."""

    def __init__(self, error: click.UsageError) -> None:
        super().__init__(usage_line(error), error.ctx)

    def show(self, file=None) -> None:
        click.echo(self.message, err=True)


def usage_line(error: click.UsageError) -> str:
    """``error: what is wrong (usage: rock CMD [OPTIONS] ARGS)``: click's message, lower case
    and without its final stop as rock's lines, then the command's usage."""
    message = " ".join(error.format_message().split()).rstrip(".")
    # One sentence: "No such option '--recrd'. Did you mean '--record'?" → "…'; did you …".
    message = re.sub(r"\. ([A-Z])(?=[a-z])", lambda m: f"; {m[1].lower()}", message)
    if message[1:2].islower():
        message = message[0].lower() + message[1:]
    if error.ctx is not None:
        usage = " ".join(error.ctx.get_usage().split()).removeprefix("Usage: ")
        message += f" (usage: {usage})"
    return f"error: {printable(message)}"


def _restyled(error: click.UsageError) -> click.UsageError:
    """The usage error as a rock ``error:`` line; click's help on a bare group as it is."""
    if isinstance(error, UsageLine | click.exceptions.NoArgsIsHelpError):
        return error
    return UsageLine(error)


class RockGroup(click.Group):
    """click group that turns every exception into one line on stderr and its exit code."""

    def main(self, args=None, *rest, **kwargs):
        from rockcli.process import quick_exit

        set_command_line(tuple(sys.argv[1:] if args is None else args))
        quick_exit()
        make_output_encodable()
        announce_compiling()
        with warnings.catch_warnings():  # restored after: rock run inside a host, a test
            warnings.showwarning = show_python_warning
            return super().main(args, *rest, **kwargs)

    def make_context(self, info_name, args, parent=None, **extra) -> click.Context:
        refuse_nul(args)
        try:
            return super().make_context(info_name, args, parent, **extra)
        except click.UsageError as exc:  # `rock --bogus`
            raise _restyled(exc) from None

    def invoke(self, ctx: click.Context) -> object:
        try:
            result = super().invoke(ctx)
            sys.stdout.flush()  # a closed pipe shows here, inside the handler, not at exit
            return result
        except click.UsageError as exc:  # a command's arguments: click's parser
            raise _restyled(exc) from None
        except RockError as exc:
            # Several problems of one file (rockcli.model.load.InputErrors): one line each.
            for line in getattr(exc, "lines", None) or (str(exc),):
                click.echo(f"error: {printable(line)}", err=True)
            ctx.exit(EXIT_INPUT)
        except BrokenPipeError:
            quiet_broken_pipe()
            ctx.exit(0)
        except KeyboardInterrupt:
            click.echo("interrupted", err=True)
            ctx.exit(EXIT_INTERRUPTED)
        except _CLICK_FLOW:
            raise
        except Exception as exc:
            if interrupted(exc):  # Ctrl-C inside compiled code: numba's SystemError
                click.echo("interrupted", err=True)
                ctx.exit(EXIT_INTERRUPTED)
            if debug_enabled():
                traceback.print_exc(file=sys.stderr)
            click.echo(internal_error_line(exc), err=True)
            ctx.exit(EXIT_INTERNAL)
        finally:
            show_cache_note()
        return None  # unreachable: ctx.exit raises


def refuse_nul(args: list[str]) -> None:
    """Refuse an argument with a NUL character: no path or value can hold one, and the system
    calls raise ValueError on it (click's own path checks among them). A shell cannot pass
    one; a program running rock's CLI in process can."""
    bad = next((arg for arg in args if "\x00" in str(arg)), None)
    if bad is not None:
        problem = f"a NUL character in an argument: {bad!r} (no path or value holds one)"
        raise UsageLine(click.UsageError(problem))


def show_python_warning(
    message: Warning | str,
    category: type[Warning],
    filename: str,
    lineno: int,
    file: object = None,
    line: str | None = None,
) -> None:
    """A Python warning that reached the command line (a library's, one rock did not turn into
    a note on the result): one ``warning:`` line on stderr, its text and its class, without
    the source file and line Python prints by default (an absolute path of the installation,
    and a second line of code, that say nothing to the user)."""
    text = " ".join(str(message).split())
    click.echo(f"warning: {printable(text)} ({category.__name__})", err=True)


def announce_compiling() -> None:
    """Say on stderr when the engine compiles (the first run on a machine: tens of seconds),
    and when it is done; stdout keeps only the command's output. Importing rockcli.kernels
    registers the function that compiles every kernel (rockcli.jitcache.ensure_compiled)."""
    import rockcli.kernels  # noqa: F401
    from rockcli import jitcache

    def before(estimate: float) -> None:
        click.echo(
            f"compiling the rocking engine for this machine, once: ~{estimate:.0f} s", err=True
        )

    def after(seconds: float) -> None:
        click.echo(f"engine compiled in {seconds:.0f} s; later runs start at once", err=True)

    jitcache.before_compile, jitcache.after_compile = before, after


def show_cache_note() -> None:
    """Say on stderr when the compiled engine could not be cached where it should."""
    from rockcli import jitcache

    if jitcache.NOTE:
        click.echo(f"note: {jitcache.NOTE}", err=True)


@click.group("rock", cls=RockGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="rock")
def cli() -> None:
    """Out-of-plane seismic assessment of masonry walls, altars and façades.

    The Italian code's kinematic check and a Housner rocking time history, on one TOML model.
    """


def _register() -> None:
    from rockcli.cli import commands

    for command in commands.ALL:
        cli.add_command(command)


_register()
