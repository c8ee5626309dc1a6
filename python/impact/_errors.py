"""What goes wrong, as Python reports it: ``InputError`` (bad input, raised by the C++ readers),
``RunError`` (a run that failed or was refused), ``InputWarning`` (an input read with a warning,
e.g. a value that looks typed in another unit). A notebook does not show the C++ side's stderr,
so everything it would print reaches Python as an exception or through ``warnings.warn``."""
import os
import tempfile
import warnings

try:
    from ._impact import InputError, OutputError
except ImportError:  # the compiled module is not built or installed: the pure-Python parts
    class InputError(ValueError):  # (impact.results) raise these, the same kinds of error
        pass

    class OutputError(OSError):
        pass

OutputError.__doc__ = (
    "An output that could not be written (a full disk, a file-size limit, a place no file can be "
    "made during the run): an OSError naming the file and the system's reason; the previous "
    "complete file, if any, is kept (docs/reliability.md#outputs).")

InputError.__doc__ = (
    "Bad input: a file, a dict or an argument the programs would refuse (exit code 2). A "
    "ValueError whose message names the file (``<scene dict>`` for a dict), the JSON key path or "
    "the argument, and the expected value or range, one line per problem.")


class RunError(RuntimeError):
    """A run that failed (a numerical fault, a step the solver could not solve: exit code 3; an
    output it could not write is an OutputError instead) or was refused (the memory estimate above the available
    memory: exit code 4). ``reason`` is the message the programs print on stderr, ``exit_code``
    the code ``mpm run``/``pointdriver run`` would exit with, ``directory`` the run's output
    directory (scenes; None for paths), ``result`` what the run had written or computed up to the
    failure (``run_scene``'s dict or ``run_path``'s Table)."""

    def __init__(self, reason, exit_code, directory=None, result=None):
        where = f" (outputs up to the failure in {directory})" if directory else ""
        super().__init__(f"{reason}{where}")
        self.reason = reason
        self.exit_code = exit_code
        self.directory = directory
        self.result = result


class InputWarning(UserWarning):
    """An input accepted with a warning: admissible but suspicious, such as a value that looks
    typed in another unit (``/density: 2.7 looks like g/cm^3 ...; the value is used as given``,
    docs/reliability.md#units-plausibility-warn-or-refuse). Issued through ``warnings.warn``;
    ``warnings.simplefilter("error", impact.InputWarning)`` turns them into errors."""


def warn_input(messages, stacklevel):
    """Each message as an InputWarning; `stacklevel` counts from the caller of warn_input."""
    for message in messages:
        warnings.warn(message, InputWarning, stacklevel=stacklevel + 1)


def writable_directory(path, argument):
    """`path` probed with a file (its missing directories made for the probe and removed again,
    so that a run refused before it starts leaves nothing); else an InputError naming
    `argument` and the path (the run would otherwise stop at its first output)."""
    directory = os.fspath(path)
    made = []  # the directories the probe creates, deepest first
    try:
        if not directory:
            raise NotADirectoryError(0, "an empty path")
        d = os.path.abspath(directory)
        while not os.path.lexists(d) and os.path.dirname(d) != d:
            made.append(d)
            d = os.path.dirname(d)
        os.makedirs(directory, exist_ok=True)
        with tempfile.TemporaryFile(dir=directory):
            pass
    except OSError as e:
        # makedirs over a file says "File exists": the reason a user can act on is that the
        # path is a file, not a directory.
        reason = (f"a file ({os.path.realpath(directory)}), not a directory"
                  if isinstance(e, FileExistsError) and not os.path.isdir(directory)
                  else e.strerror or e)
        raise InputError(f"{argument}: {directory}: expected a directory the run can write "
                         f"into, got {reason}") from None
    finally:
        for d in made:
            try:
                os.rmdir(d)
            except OSError:
                pass
    return directory
