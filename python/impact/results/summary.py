"""The JSON files of a run directory: summary.json (written when the run ends: status, steps,
wall time, observables, the final energy error), status.json (kept current while it runs) and
scene.json (the resolved scene). Standard library only."""
import json
import os

from .._errors import InputError


def _read(directory, name, required):
    path = os.path.join(os.fspath(directory), name)
    if not os.path.isfile(path):
        if required:
            raise InputError(f"{path}: expected the {name} mpm run writes, found "
                             + ("nothing" if not os.path.lexists(path) else "no regular file"))
        return None
    with open(path) as f:
        try:
            return json.load(f)
        except ValueError as e:
            raise InputError(f"{path}: not JSON ({e})") from None


def read_summary(directory, required=False):
    """summary.json of a run directory as a dict; None when it has none (the run goes on, or
    never started) unless ``required`` (then InputError)."""
    return _read(directory, "summary.json", required)


def read_status(directory, required=False):
    """status.json ("running", "completed", "failed" or "interrupted", with the step and time)."""
    return _read(directory, "status.json", required)


def read_scene(directory, required=False):
    """scene.json: the scene as the run resolved it (defaults filled in, patches applied)."""
    return _read(directory, "scene.json", required)


def completed(directory):
    """Whether the run in ``directory`` finished: its summary.json says "completed"."""
    summary = read_summary(directory)
    return isinstance(summary, dict) and summary.get("status") == "completed"
