"""impact-mpm from Python: materials, one-point and batch updates, point-driver paths, fitting
and checking flow-stress laws, and MPM scenes (docs/python.md).

Everything is in SI units; tables carry each column's unit (``Table.units``). Inputs are the
files the programs read, or the same documents as dicts; ``patches`` are RFC 7396 merge patches
applied in order before validation. Bad input raises ``impact.InputError`` (a ``ValueError``)
whose message names the file, the JSON key path and what was expected.
"""
import csv
import json
import os

import numpy as np

from ._impact import InputError  # noqa: F401  (public)
from . import _impact

__all__ = ["InputError", "Material", "Table", "load_material", "update", "run_path", "fit",
           "check", "run_scene", "check_scene", "read_history", "data_path", "failure_causes",
           "update_statuses", "__version__"]

__version__ = getattr(_impact, "__version__", "unknown")

#: Names of the codes in a state's ``failure_cause`` and of an update report's ``status``.
failure_causes = list(_impact.failure_cause_names)
update_statuses = list(_impact.update_status_names)


def data_path(*relative):
    """The path of a shipped data file (``data_path("materials", "al6061_t6.json")``): the
    install's share/impact/data beside the module, else the source tree of this build."""
    here = os.path.dirname(os.path.abspath(__file__))
    probe = here
    for _ in range(6):  # <prefix>/lib/python3.X/site-packages/impact -> <prefix>/share/impact
        probe = os.path.dirname(probe)
        candidate = os.path.join(probe, "share", "impact", "data")
        if os.path.isdir(candidate):
            return os.path.join(candidate, *relative)
    if os.environ.get("IMPACT_NO_SOURCE_TREE") != "1":
        try:
            from ._source_tree import SOURCE_DIR
            return os.path.join(SOURCE_DIR, "data", *relative)
        except ImportError:
            pass
    raise FileNotFoundError("impact: no shipped data found beside " + here)


class Table(dict):
    """Named columns (NumPy arrays) with their SI units in ``units`` (``units["time"] == "s"``).
    Other results of the run are attributes (``completed``, ``error``, ...)."""

    def __init__(self, columns, units, **info):
        super().__init__(columns)
        self.units = units
        self.__dict__.update(info)

    def __repr__(self):
        return (f"Table({len(self)} columns x {len(next(iter(self.values()), []))} rows: "
                + ", ".join(f"{k} [{u}]" for k, u in list(self.units.items())[:6]) + ", ...)")


def _split_header(cell):
    """'stress_xx [Pa]' -> ('stress_xx', 'Pa'); a cell without a unit gets ''."""
    cell = cell.strip()
    if cell.endswith("]") and " [" in cell:
        name, unit = cell[:-1].rsplit(" [", 1)
        return name, unit
    return cell, ""


def _table(named_columns, **info):
    columns, units = {}, {}
    for cell, values in named_columns.items():
        name, unit = _split_header(cell)
        columns[name], units[name] = np.asarray(values), unit
    return Table(columns, units, **info)


def _patches(patches):
    if patches is None:
        return []
    if isinstance(patches, dict):
        patches = [patches]
    return [json.dumps(p) for p in patches]


def _label(base_dir, kind):
    """The name a dict input gets in messages; relative files in it resolve against base_dir."""
    return os.path.join(os.path.abspath(base_dir or os.getcwd()), f"<{kind} dict>")


class Material:
    """A validated material: ``Material("al6061_t6.json")``, ``Material(document_dict)``, or
    either with ``patches``. ``to_dict()`` gives the resolved parameters (what material_check
    prints)."""

    def __init__(self, source, patches=None, base_dir=None):
        if isinstance(source, Material):
            source = source.to_dict()
        if isinstance(source, dict):
            doc = dict(source)
            for p in _patches(patches):
                doc = _merge_patch(doc, json.loads(p))
            self._m = _impact.read_material(json.dumps(doc), _label(base_dir, "material"))
        else:
            self._m = _impact.load_material(os.fspath(source), _patches(patches))

    name = property(lambda self: self._m.name)
    file = property(lambda self: self._m.file)
    warnings = property(lambda self: list(self._m.warnings))
    density = property(lambda self: self._m.density, doc="reference density [kg/m^3]")
    room_temperature = property(lambda self: self._m.room_temperature, doc="[K]")

    def to_dict(self):
        return json.loads(self._m.to_json())

    def initial_state(self, temperature=None, n=1):
        """n points at rest at ``temperature`` [K] (default: the material's room temperature),
        as a state dict of arrays with leading dimension n."""
        t = self.room_temperature if temperature is None else temperature
        return self._m.initial_state(float(t), int(n))

    def __repr__(self):
        return f"Material({self.name!r}, file={self.file!r})"


def _merge_patch(target, patch):
    """RFC 7396 merge patch, by the library's own (nlohmann::json::merge_patch, as the programs
    apply --set)."""
    return json.loads(_impact.merge_patch(json.dumps(target), json.dumps(patch)))


def load_material(source, patches=None, base_dir=None):
    """A Material from a file name or a dict (see Material)."""
    return Material(source, patches, base_dir)


def update(material, state, L, dt, F1=None):
    """One constitutive step of N points (the solver's batched update, bit for bit the one-point
    update): ``state`` is a dict of arrays with leading dimension N (``Material.initial_state``;
    missing keys start at rest), ``L`` the velocity gradients (N, 3, 3) [1/s], ``dt`` [s], ``F1``
    the end-of-step deformation gradients (default exp(L dt) F). A single point may be given
    without the leading dimension. Returns (new state, report): the report's ``status`` and
    ``failure`` are names ("ok", "none", ...), the rest arrays (``plastic_work`` in J/m^3)."""
    mat = material if isinstance(material, Material) else Material(material)
    L = np.asarray(L, dtype=float)
    single = L.ndim == 2
    if single:
        L = L[None]
        state = {k: np.asarray(v)[None] for k, v in state.items()}
        F1 = None if F1 is None else np.asarray(F1, dtype=float)[None]
    new, report = _impact.update(mat._m, state, L, float(dt), F1)
    report["status"] = np.array(_impact.update_status_names)[report["status"]]
    report["failure"] = np.array(_impact.failure_cause_names)[report["failure"]]
    if single:
        new = {k: v[0] for k, v in new.items()}
        report = {k: v[0] for k, v in report.items()}
    return new, report


def run_path(path, patches=None, base_dir=None):
    """Runs a point-driver path (file or dict; docs/pointdriver.md) and returns its rows as a
    Table of the CSV's columns (``time`` [s], ``stress_xx`` [Pa], ``plastic_strain`` [-], ...),
    with ``completed``, ``steps``, ``end_time``, ``failure``, ``failure_time``, ``error`` and
    ``warnings``. A run that cannot finish returns what it computed, ``completed`` False."""
    if isinstance(path, dict):
        doc = path
        for p in _patches(patches):
            doc = _merge_patch(doc, json.loads(p))
        r = _impact.run_path_document(json.dumps(doc), _label(base_dir, "path"))
    else:
        r = _impact.run_path_file(os.fspath(path), _patches(patches))
    columns = r.pop("columns")
    return _table(columns, **r)


def _with_arrays(report):
    """Curves' lists as NumPy arrays."""
    for curve in report.get("series", []):
        for part in curve.values():
            for key in ("plastic_strain", "stress", "temperature"):
                if key in part:
                    part[key] = np.asarray(part[key])
    return report


def fit(config, base_dir=None):
    """Fits a flow-stress law (docs/fitting.md) from a FIT configuration (file or dict). Returns
    fit_report.json as a dict, plus ``fitted_material`` (a material document: pass it to
    Material), ``converged`` and ``series`` (per experiment: ``data``, ``fitted``, ``material``,
    each with ``plastic_strain`` [-] and ``stress`` [Pa] arrays, for plotting)."""
    if isinstance(config, dict):
        text = _impact.fit_document(json.dumps(config), _label(base_dir, "fit"))
    else:
        text = _impact.fit_file(os.fspath(config))
    return _with_arrays(json.loads(text))


def check(config, base_dir=None):
    """Checks a material against measured curves with tolerances (``pointdriver check``; file or
    dict). Returns check_report.json as a dict (``passed``, ``exceeded``, per-curve errors in
    Pa, under ``curves``) with ``series`` as in fit."""
    if isinstance(config, dict):
        text = _impact.check_document(json.dumps(config), _label(base_dir, "check"))
    else:
        text = _impact.check_file(os.fspath(config))
    return _with_arrays(json.loads(text))


def _scene_source(scene, base_dir):
    """(file, text, label) for the C++ side; a dict's ``extends`` is resolved here."""
    if not isinstance(scene, dict):
        return os.fspath(scene), "", ""
    doc = dict(scene)
    if "extends" in doc:
        base = os.path.join(os.path.abspath(base_dir or os.getcwd()), doc.pop("extends"))
        doc = _merge_patch(json.loads(_impact.scene_document(base)), doc)
    return "", json.dumps(doc), _label(base_dir, "scene")


def check_scene(scene, patches=None, threads=0, base_dir=None):
    """``mpm check``: the validated scene (``resolved``), ``warnings``, and unless the memory
    estimate refuses it (``refusal``) the ``report`` (particles, nodes, time step, memory)."""
    file, text, label = _scene_source(scene, base_dir)
    return json.loads(_impact.check_scene(file, text, label, _patches(patches), int(threads)))


def read_history(directory):
    """history.csv of a run directory as a Table (``time`` [s], energies [J], momentum ...)."""
    with open(os.path.join(directory, "history.csv"), newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    columns = {cell: np.array([float(r[k]) for r in body]) for k, cell in enumerate(header)}
    return _table(columns)


def run_scene(scene, out, patches=None, threads=0, progress=False, base_dir=None):
    """``mpm run``: runs a scene (file or dict) to its end time, writing into ``out`` what the
    program writes. Returns a dict: ``exit_code`` (0 done, 3 a numerical fault, 4 refused for
    memory; docs/mpm.md), ``directory``, ``warnings``, ``summary`` (summary.json) and
    ``history`` (history.csv as a Table)."""
    file, text, label = _scene_source(scene, base_dir)
    code, directory, warnings = _impact.run_scene(file, text, label, _patches(patches),
                                                  os.fspath(out), int(threads), bool(progress))
    result = {"exit_code": code, "directory": directory, "warnings": list(warnings)}
    summary = os.path.join(directory, "summary.json")
    if os.path.exists(summary):
        with open(summary) as f:
            result["summary"] = json.load(f)
    if os.path.exists(os.path.join(directory, "history.csv")):
        result["history"] = read_history(directory)
    return result
