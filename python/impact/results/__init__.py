"""impact.results: what `mpm run` writes, read back, and the mpm program launched from a script.
Pure Python: importable without the compiled module (``impact._impact``); the launcher, the
summary readers and ``history_rows``/``history_columns`` need the standard library alone, the
rest NumPy. The campaign scripts (campaigns/) use it from the source tree or an install.

- ``read_run(dir)`` -> Run: history (Table), summary, status, scene, snapshots, paths
- ``read_history(dir)`` -> Table; ``history_rows(dir)``, ``history_columns(dir)`` (plain lists)
- ``read_summary(dir)``, ``read_status(dir)``, ``read_scene(dir)``, ``completed(dir)``
- ``read_points(file)`` (a .vtu or .pvtu), ``snapshots(dir)``, ``read_vtu``, ``read_snapshot``,
  ``read_collection`` (a .pvd)
- ``Launcher(mpm)``, ``launch(...)``, ``find_mpm()``, ``LaunchError``, ``mpi_environment()``
"""
import importlib

_WHERE = {
    "Run": "run_dir", "Snapshot": "run_dir", "read_run": "run_dir", "FIELD_UNITS": "run_dir",
    "Table": "history", "read_history": "history", "history_rows": "history",
    "history_columns": "history", "split_header": "history",
    "read_summary": "summary", "read_status": "summary", "read_scene": "summary",
    "completed": "summary",
    "read_points": "vtu", "snapshots": "vtu", "read_vtu": "vtu", "read_snapshot": "vtu",
    "read_collection": "vtu",
    "Launcher": "launcher", "launch": "launcher", "find_mpm": "launcher",
    "LaunchError": "launcher", "mpi_environment": "launcher",
    "MPI_ROOT_ENVIRONMENT": "launcher",
}
__all__ = sorted(_WHERE)


def __getattr__(name):
    """Each name loaded from its module on first use: NumPy is imported only by the readers
    that need it."""
    if name not in _WHERE:
        raise AttributeError(f"module 'impact.results' has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{_WHERE[name]}", __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_WHERE))
