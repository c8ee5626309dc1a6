"""What the plot scripts write (`pointdriver plot`, `verify`, `convergence`: plot.py; `mpm plot`:
run_plot.py): figures, written as the programs write their files (support/atomic_file.hpp), and
stdout, and how they end.

A figure's format is its suffix (.png, .pdf, .svg); any other name is a usage error, so the file
written is always the file named (matplotlib would append .png to a name without a suffix). The
figure goes to `<name>.tmp` beside it and is renamed over `<name>` once written and closed: a
full disk or a file-size limit leaves the previous figure (or none), never a truncated one nor a
stray file, and is one line naming the file and the system's reason (exit 3). An existing
non-regular target (/dev/null, a FIFO) is written in place. Directories made for the figure are
removed again when it cannot be written.

What a script prints on stdout goes through `print_lines`: a full stdout is one line and exit 3,
a reader that went away (`| head`) ends the script quietly with 141 (128 + SIGPIPE, what a Unix
tool killed by SIGPIPE ends with). `run_script` runs a script's main: a FigureError is its one
line and exit code, Ctrl-C one line and 130. Standard library only.
"""
import errno
import os
import signal
import sys

FORMATS = {".png": "png", ".pdf": "pdf", ".svg": "svg"}
EXIT_USAGE = 1
EXIT_OUTPUT = 3
EXIT_INTERRUPTED = 128 + signal.SIGINT  # 130, as the programs after Ctrl-C
EXIT_BROKEN_PIPE = 128 + signal.SIGPIPE  # 141


class FigureError(Exception):
    """A figure name the scripts refuse (exit_code 1) or a figure that could not be written
    (exit_code 3); the message names the file."""

    def __init__(self, message, exit_code):
        super().__init__(message)
        self.exit_code = exit_code


def figure_format(path):
    """The matplotlib format of `path`'s suffix; FigureError (usage) for any other name."""
    fmt = FORMATS.get(os.path.splitext(path)[1].lower())
    if path and os.path.isdir(path):  # the reason to act on: a directory, not a file name
        raise FigureError(f"{path}: a directory; expected a figure file name ending in "
                          f"{', '.join(FORMATS)} (e.g. {os.path.join(path, 'run.png')})",
                          EXIT_USAGE)
    if not path or fmt is None:
        raise FigureError(f"{path or '(empty)'}: expected a figure name ending in "
                          f"{', '.join(FORMATS)}", EXIT_USAGE)
    return fmt


def _make_directories(directory):
    """Creates `directory` and its missing parents; returns those it made, deepest first."""
    made = []
    d = os.path.abspath(directory)
    while d and not os.path.lexists(d):
        made.append(d)
        parent = os.path.dirname(d)
        if parent == d:
            break
        d = parent
    for m in reversed(made):
        os.mkdir(m)
    return made


def _remove_quietly(remove, path):
    try:
        remove(path)
    except OSError:
        pass


def save_figure(fig, path, **savefig_options):
    """Writes `fig` to `path` (format from the suffix), whole or not at all; FigureError naming
    `path` and the system's reason when it cannot be written."""
    fmt = figure_format(path)
    target = os.path.realpath(path) if os.path.islink(path) else path
    in_place = os.path.exists(target) and not os.path.isfile(target)
    written = target if in_place else target + ".tmp"
    made = []
    try:
        made = _make_directories(os.path.dirname(target) or ".")
        with open(written, "wb") as f:
            fig.savefig(f, format=fmt, **savefig_options)
        if not in_place:
            os.replace(written, target)
    except OSError as e:
        if not in_place:
            _remove_quietly(os.remove, written)
        for d in made:
            _remove_quietly(os.rmdir, d)
        raise FigureError(f"cannot write {path}: {e.strerror or e}", EXIT_OUTPUT) from None


def _silence_stdout():
    """Points fd 1 at /dev/null, so that the interpreter's last flush at exit finds nothing to
    fail on (it would print 'Exception ignored ...' and exit 120)."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    os.close(devnull)


def print_lines(lines, program):
    """Prints `lines` on stdout and flushes; returns 0, or the exit code of a stdout that could
    not take them: 3 (full; one line on stderr) or 141 (closed by its reader; nothing said)."""
    try:
        sys.stdout.write("".join(line + "\n" for line in lines))
        sys.stdout.flush()
    except BrokenPipeError:
        _silence_stdout()
        return EXIT_BROKEN_PIPE
    except OSError as e:
        _silence_stdout()
        reason = e.strerror or os.strerror(e.errno or errno.EIO)
        print(f"{program}: cannot write the standard output ({reason})", file=sys.stderr)
        return EXIT_OUTPUT
    return 0


def run_script(main, argv, program):
    """`main(argv)`'s exit code; a FigureError and Ctrl-C end it with one line on stderr (the
    error's code; 130), never a traceback."""
    try:
        return main(argv)
    except FigureError as e:
        print(f"{program}: {e}", file=sys.stderr)
        return e.exit_code
    except KeyboardInterrupt:
        print(f"{program}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
