"""Running the mpm program from a script: ``mpm run``, ``mpm check`` and ``mpm study`` with
``--out``, ``--threads``, ``--set`` patches and, on several MPI ranks, under ``mpirun -np N``.
Standard library only: the campaign scripts use it on machines without NumPy or the compiled
module.

    mpm = Launcher("build/bin/mpm")
    mpm.command("run", "scene.json", out="runs/a", threads=2, sets=['{"time": ...}'])
      -> ['build/bin/mpm', 'run', 'scene.json', '--out', 'runs/a', '--threads', '2',
          '--set', '{"time": ...}']
    done = mpm.run("run", "scene.json", out="runs/a", threads=2)   # CompletedProcess
"""
import os
import shlex
import shutil
import subprocess

#: What Open MPI needs to start ranks as root (containers, CI); ``mpi_environment`` adds it.
MPI_ROOT_ENVIRONMENT = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}
_HERE = os.path.dirname(os.path.abspath(__file__))


class LaunchError(RuntimeError):
    """A program that exited with a code other than 0 (or could not be started): ``command``
    (the argument list), ``returncode`` (None if it never started), ``stderr`` (what it printed
    there, when captured); the message ends with the last lines of stderr."""

    def __init__(self, command, returncode, stderr="", reason=None):
        tail = "\n".join((stderr or "").rstrip().splitlines()[-12:])
        what = reason or f"exited {returncode}"
        super().__init__(f"{shlex.join(command)}: {what}" + (f"\n{tail}" if tail else ""))
        self.command = command
        self.returncode = returncode
        self.stderr = stderr


def find_mpm(explicit=None):
    """The mpm program: ``explicit`` when given (a path, or a name on PATH), else the one built
    beside this package (<source>/build/bin/mpm from the source tree; <prefix>/bin/mpm from an
    install, the package in share/impact/python or lib/python3.X/site-packages), else ``mpm``
    on PATH.
    Returns a path (or the name as given); FileNotFoundError when none is found."""
    if explicit:
        return os.fspath(explicit)
    for candidate in _beside_package():
        if os.access(candidate, os.X_OK) and os.path.isfile(candidate):
            return candidate
    found = shutil.which("mpm")
    if found:
        return found
    raise FileNotFoundError("mpm: not built (cmake --build build) nor on PATH; pass its path")


def _beside_package():
    """Where the mpm of this package's own tree is, by the tree's layout (no guess outside it):
    the source tree <src>/python/impact/results -> <src>/build/bin/mpm; the build tree's copy
    <build>/python/impact/results -> <build>/bin/mpm; an install <prefix>/share/impact/python/
    impact/results or <prefix>/lib/python3.X/site-packages/impact/results -> <prefix>/bin/mpm."""
    package = os.path.dirname(_HERE)  # .../impact
    parent = os.path.dirname(package)  # <src>/python, <build>/python, share/impact/python, ...
    root = os.path.dirname(parent)  # <src> or <build> in a tree
    if os.path.isfile(os.path.join(root, "CMakeCache.txt")):  # a build tree
        return [os.path.join(root, "bin", "mpm")]
    if os.path.isfile(os.path.join(root, "CMakeLists.txt")):  # the source tree
        return [os.path.join(root, "build", "bin", "mpm")]
    tail = parent.replace(os.sep, "/")
    if tail.endswith("/share/impact/python"):
        return [os.path.normpath(os.path.join(parent, "..", "..", "..", "bin", "mpm"))]
    if os.path.basename(parent) == "site-packages" and os.path.basename(
            os.path.dirname(parent)).startswith("python"):
        return [os.path.normpath(os.path.join(parent, "..", "..", "..", "bin", "mpm"))]
    return []


def mpi_environment(env=None):
    """``env`` (default: this process's environment) with MPI_ROOT_ENVIRONMENT added."""
    return dict(os.environ if env is None else env, **MPI_ROOT_ENVIRONMENT)


class Launcher:
    """Builds and runs mpm command lines. ``mpm`` is the program (find_mpm's rules);
    ``mpirun`` the MPI launcher with its options as one string (``"mpirun --oversubscribe"``,
    split as a shell would) or a list, used when ``ranks`` > 1: ``mpirun... -np N
    mpirun_options... mpm ...``."""

    def __init__(self, mpm=None, mpirun="mpirun", mpirun_options=()):
        self.mpm = find_mpm(mpm)
        self.mpirun = shlex.split(mpirun) if isinstance(mpirun, str) else list(mpirun)
        self.mpirun_options = list(mpirun_options)

    def command(self, action, *targets, out=None, options=(), threads=None, sets=(), ranks=1,
                extra=()):
        """The argument list of ``mpm ACTION TARGETS... [--out OUT] [OPTIONS...] [--threads N]
        [--set PATCH]... [EXTRA...]``, under ``mpirun -np RANKS`` when RANKS > 1. ``sets`` are
        JSON merge patches (text, or dicts written as JSON); ``threads`` None leaves the
        program's default (all cores)."""
        if action not in ("run", "check", "study"):
            raise ValueError(f"action: expected run, check or study, got {action!r}")
        if not isinstance(ranks, int) or isinstance(ranks, bool) or ranks < 1:
            raise ValueError(f"ranks: expected a whole number >= 1, got {ranks!r}")
        cmd = [self.mpm, action] + [os.fspath(t) for t in targets]
        if out is not None:
            cmd += ["--out", os.fspath(out)]
        cmd += [os.fspath(o) for o in _listed(options)]
        if threads is not None and threads != 0:  # 0 or None: the program's default
            if not isinstance(threads, int) or isinstance(threads, bool) or threads < 0:
                raise ValueError(f"threads: expected a whole number >= 1 (0 or None: the "
                                 f"program's default), got {threads!r}")
            cmd += ["--threads", str(threads)]
        for patch in _listed(sets):
            cmd += ["--set", patch if isinstance(patch, str) else _json(patch)]
        cmd += [os.fspath(e) for e in _listed(extra)]
        if ranks > 1:
            cmd = self.mpirun + ["-np", str(ranks)] + self.mpirun_options + cmd
        return cmd

    def run(self, action, *targets, check=True, capture=True, env=None, timeout=None,
            stdout=None, stderr=None, **options):
        """Runs ``command(action, *targets, **options)`` to its end and returns the
        CompletedProcess (text; stdout and stderr captured unless ``capture`` is False or
        ``stdout``/``stderr`` are given). With ``check``, an exit code other than 0 raises
        LaunchError with the tail of stderr; a program that cannot be started raises
        LaunchError too."""
        cmd = self.command(action, *targets, **options)
        kwargs = {"env": env, "timeout": timeout, "text": True}
        if capture and stdout is None and stderr is None:
            kwargs["capture_output"] = True
        else:
            kwargs.update(stdout=stdout, stderr=stderr)
        try:
            done = subprocess.run(cmd, **kwargs)
        except OSError as e:
            raise LaunchError(cmd, None, reason=f"cannot be started ({e.strerror or e})") from None
        if check and done.returncode != 0:
            raise LaunchError(cmd, done.returncode, done.stderr or "")
        return done

    def start(self, action, *targets, env=None, stdout=None, stderr=None,
              start_new_session=False, **options):
        """Starts ``command(action, *targets, **options)`` and returns the Popen (for a run the
        caller waits on, signals or times)."""
        return self.popen(self.command(action, *targets, **options), env=env, stdout=stdout,
                          stderr=stderr, start_new_session=start_new_session)

    @staticmethod
    def popen(command, **kwargs):
        """Starts a command line ``command()`` built (to print or log it first): the Popen."""
        return subprocess.Popen(command, **kwargs)


def launch(action, *targets, mpm=None, mpirun="mpirun", mpirun_options=(), **options):
    """``Launcher(mpm, mpirun, mpirun_options).run(action, *targets, **options)``: e.g.
    ``launch("run", "scene.json", out="runs/a", threads=2, sets=[patch], ranks=2)``."""
    return Launcher(mpm, mpirun, mpirun_options).run(action, *targets, **options)


def _listed(items):
    """A sequence of command-line items: None as none, one string, path or patch as one."""
    if items is None:
        return []
    if isinstance(items, (str, bytes, dict, os.PathLike)):
        return [items]
    return list(items)


def _json(document):
    """A merge patch as JSON text; NaN and infinities are refused here (not JSON: mpm would
    refuse the text with a parse error naming no key)."""
    import json
    try:
        return json.dumps(document, allow_nan=False)
    except ValueError as e:
        raise ValueError(f"sets: a patch holds a NaN or an infinity ({e}): {document!r}") from None
