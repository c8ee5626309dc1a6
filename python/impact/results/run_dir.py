"""Reading a run directory back (what `mpm run` or ``run_scene`` wrote, on one rank or several):
the history as named columns with units, summary.json, status.json, the resolved scene, the
particle snapshots (positions and fields) and the particle paths."""
import json
import os
import re

import numpy as np

from .._errors import InputError
from .history import Table, read_history, table
from .vtu import read_collection, read_snapshot

#: Units of the snapshot fields (docs/mpm.md#output); indices and flags are "-".
FIELD_UNITS = {"velocity": "m/s", "stress": "Pa", "plastic_strain": "-", "temperature": "K",
               "damage": "-", "mass": "kg", "volume": "m^3", "pressure": "Pa",
               "von_mises": "Pa", "material": "-", "object": "-", "field": "-", "id": "-",
               "failure_cause": "-", "failed_in_tension": "-", "instability": "-", "failed": "-",
               "F": "-", "R": "-", "plastic_strain_rate": "1/s", "internal_energy": "J/kg",
               "porosity": "-", "flow_internal": "Pa", "melted": "-"}
#: In plane strain the extensive fields are per metre of thickness along z (docs/mpm.md#output).
PLANE_STRAIN_UNITS = {"mass": "kg/m", "volume": "m^3/m"}
_INDICES = ("material", "object", "field", "id", "failure_cause", "instability")
_FLAGS = ("failed", "failed_in_tension", "melted")
#: The tensors written row by row, 9 components (docs/mpm.md#snapshot-fields).
_TENSORS = ("F", "R")


class Snapshot:
    """One particle snapshot of a run: ``time`` [s], ``step`` and ``file``; ``positions`` (N, 3)
    [m] and ``fields`` (a Table: ``velocity`` (N, 3) [m/s], ``stress``, ``F`` and ``R``
    (N, 3, 3), the scalar fields (N,), ``id`` the particle's seed index, ...) are read from the
    file on first use. On several ranks the pieces are joined in rank order (``pieces`` of them),
    and a shuffled store (``solver.shuffle_particles``) is in its own order: sort by ``id`` to
    compare with a one-rank run in seed order. In plane strain ``mass`` and ``volume`` are per metre of
    thickness (``fields.units``: kg/m, m^3/m)."""

    def __init__(self, time, file, plane_strain=False):
        self.time = time
        self.file = file
        self._units = {**FIELD_UNITS, **(PLANE_STRAIN_UNITS if plane_strain else {})}
        match = re.search(r"step_(\d+)", os.path.basename(file))
        self.step = int(match.group(1)) if match else -1
        self._data = None

    def _load(self):
        if self._data is None:
            positions, raw, pieces = read_snapshot(self.file)
            columns = {}
            for name, values in raw.items():
                if name == "stress":  # xx yy zz xy yz xz -> symmetric (N, 3, 3)
                    s = np.empty((len(values), 3, 3))
                    for k, (i, j) in enumerate(((0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2))):
                        s[:, i, j] = s[:, j, i] = values[:, k]
                    values = s
                elif name in _TENSORS:  # row by row -> (N, 3, 3)
                    values = values.reshape(len(values), 3, 3)
                elif name in _INDICES:
                    values = values.astype(np.int64)
                elif name in _FLAGS:
                    values = values != 0.0
                columns[name] = values
            units = {name: self._units.get(name, "") for name in columns}
            self._data = positions, Table(columns, units), pieces
        return self._data

    @property
    def positions(self):
        """Particle positions (N, 3) [m]."""
        return self._load()[0]

    @property
    def fields(self):
        """The snapshot's point data as a Table (units in ``fields.units``)."""
        return self._load()[1]

    @property
    def pieces(self):
        """The number of files (ranks) the snapshot was written in."""
        return self._load()[2]

    def __repr__(self):
        return f"Snapshot(time={self.time!r}, step={self.step}, file={self.file!r})"


class Run:
    """A run directory read back by ``read_run``: ``history`` (a Table of history.csv:
    ``time`` [s], the energy books [J], momentum [kg m/s], boundary impulse [N s], gauges; in
    plane strain per metre of thickness, [J/m] ...: ``history.units`` holds the header's),
    ``summary`` (summary.json, None while the run goes on), ``status`` (status.json: ``status``
    is "running", "completed", "failed" or "interrupted"), ``scene`` (the resolved scene.json),
    ``snapshots`` (a list of Snapshot, in time order) and ``paths`` (per particle path of
    ``output.particle_paths``, its CSV as a Table)."""

    def __init__(self, directory, history, summary, status, scene, snapshots, paths):
        self.directory = directory
        self.history = history
        self.summary = summary
        self.status = status
        self.scene = scene
        self.snapshots = snapshots
        self.paths = paths

    def __repr__(self):
        state = (self.status or {}).get("status", "unknown")
        return (f"Run({self.directory!r}, {state}, {len(self.history.get('time', []))} history "
                f"rows, {len(self.snapshots)} snapshots)")


def _json(path):
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def _read_csv_table(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    values = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return table({cell: values[:, k] for k, cell in enumerate(header)})


def read_run(directory):
    """Reads a run directory (``mpm run --out DIR``, ``run_scene(out=DIR)``, one rank or several)
    into a Run: history with units, summary, status, resolved scene, snapshots and particle
    paths. Raises InputError when DIR holds no history.csv."""
    directory = os.fspath(directory)
    if not os.path.isfile(os.path.join(directory, "history.csv")):
        raise InputError(f"{directory}: expected a run directory (history.csv, as mpm run "
                         "writes it), found none")
    scene = _json(os.path.join(directory, "scene.json"))
    plane_strain = (isinstance(scene, dict) and isinstance(scene.get("grid"), dict)
                    and scene["grid"].get("geometry") == "plane_strain")
    pvd = os.path.join(directory, "particles.pvd")
    snapshots = ([Snapshot(t, f, plane_strain) for t, f in read_collection(pvd)]
                 if os.path.exists(pvd) else [])
    paths = {}
    paths_dir = os.path.join(directory, "paths")
    if os.path.isdir(paths_dir):
        for name in sorted(os.listdir(paths_dir)):
            if name.endswith(".csv"):
                paths[name[:-4]] = _read_csv_table(os.path.join(paths_dir, name))
    return Run(directory, read_history(directory), _json(os.path.join(directory, "summary.json")),
               _json(os.path.join(directory, "status.json")),
               scene, snapshots, paths)
