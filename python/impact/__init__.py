"""impact-mpm from Python: materials, one-point and batch updates, point-driver paths, fitting
and checking flow-stress laws, and MPM scenes (docs/python.md).

Everything is in SI units; tables carry each column's unit (``Table.units``). Inputs are the
files the programs read, or the same documents as dicts; ``patches`` are RFC 7396 merge patches
applied in order before validation. Bad input raises ``impact.InputError`` (a ``ValueError``)
whose message names the file (or ``patches[k]`` for a value a patch set), the JSON key path and
what was expected; a run that fails or is refused raises ``impact.RunError``; an output that
cannot be written raises ``impact.OutputError`` (an ``OSError``) naming the file; inputs read with
a warning (a likely unit slip) issue an ``impact.InputWarning`` through ``warnings.warn``. Types:
the stub ``__init__.pyi`` beside this file.
"""
import json
import importlib
import math
import operator
import os
import re

from ._errors import InputError, InputWarning, OutputError, RunError  # noqa: E402
from ._errors import warn_input, writable_directory  # noqa: E402

# The results package (impact.results: read_run, read_history, the launcher, ...) is pure Python;
# the rest needs the compiled module and NumPy. Without them `import impact` still works (and
# loads neither), and the compiled API raises an ImportError saying what is missing.
#
# OpenMP threads sleep at barriers unless the caller chose otherwise: libgomp reads the policy when
# it is loaded, so before _impact (and NumPy) are. A busy core otherwise stalls every run on all
# cores (docs/performance.md#threads; the mpm program does the same, support/omp_wait_policy.hpp).
# Set only for the compiled module: a script that merely reads runs or launches programs (an
# older mpm in a benchmark) passes the environment on unchanged.
_POLICY_SET = "OMP_WAIT_POLICY" not in os.environ
if _POLICY_SET:
    os.environ["OMP_WAIT_POLICY"] = "passive"
try:
    from . import _impact
except ImportError as _missing:
    if _POLICY_SET:
        del os.environ["OMP_WAIT_POLICY"]
    np = None
    _impact = None
    _REASON = (str(_missing) if _missing.name not in ("impact", "impact._impact") else
               f"no _impact extension in {os.path.dirname(os.path.abspath(__file__))}")
    _MISSING = (f"impact: the compiled module impact._impact is not built or not installed "
                f"({_REASON}); impact.results (read_run, read_history, the vtu readers, the mpm "
                "launcher) works without it, the rest needs it: build with python3-dev and "
                "pybind11-dev (docs/python.md)")
else:
    try:
        import numpy as np
    except ImportError as _missing:
        np = None
        _impact = None
        _MISSING = (f"impact: the compiled module needs NumPy ({_missing}): install "
                    "python3-numpy; impact.results' launcher and plain readers work without it")

__all__ = ["InputError", "OutputError", "RunError", "InputWarning", "Material", "Table", "Run", "Snapshot",
           "load_material", "update", "run_path", "fit", "check", "run_scene", "resume_scene",
           "check_scene", "read_history", "read_run", "data_path", "failure_causes",
           "update_statuses", "__version__"]
if _impact is None:  # `from impact import *` takes what loads without NumPy and the module
    __all__ = ["InputError", "OutputError", "RunError", "InputWarning", "data_path", "__version__"]

_RESULTS = ("Run", "Snapshot", "Table", "read_history", "read_run")
_COMPILED = ("Material", "load_material", "update", "run_path", "fit", "check", "run_scene",
             "resume_scene", "check_scene")


def __getattr__(name):
    """The results package and its names (Run, Snapshot, Table, read_history, read_run:
    impact.results) on first use, so that `import impact` needs neither NumPy nor the compiled
    module; without the compiled module, the code tables it names (failure_causes,
    update_statuses) raise its ImportError."""
    if name == "results":
        return importlib.import_module(".results", __name__)
    if name in _RESULTS:
        return getattr(importlib.import_module(".results", __name__), name)
    if _impact is None and name in ("failure_causes", "update_statuses"):
        raise ImportError(_MISSING)
    raise AttributeError(f"module 'impact' has no attribute {name!r}")


if _impact is not None:
    __version__ = getattr(_impact, "__version__", "unknown")
    #: Names of the codes in a state's ``failure_cause`` and of an update report's ``status``.
    failure_causes = list(_impact.failure_cause_names)
    update_statuses = list(_impact.update_status_names)
else:
    __version__ = "unknown"


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
        # The package read from the source tree itself (<src>/python/impact, no build).
        tree = os.path.join(os.path.dirname(os.path.dirname(here)), "data")
        if os.path.isfile(os.path.join(tree, "README.md")) or os.path.isdir(
                os.path.join(tree, "materials")):
            return os.path.join(tree, *relative)
    raise FileNotFoundError("impact: no shipped data found beside " + here)


def _json_value(value):
    """NumPy scalars and arrays and path objects as JSON values (a notebook's usual types)."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    raise TypeError(f"a {type(value).__name__} is not a JSON value")


def _non_finite(value, where):
    """The key path of the first NaN or infinite number in a document, or None."""
    if isinstance(value, float) and not math.isfinite(value):
        return where or "/"
    if isinstance(value, dict):
        items = value.items()
    elif isinstance(value, (list, tuple)):
        items = enumerate(value)
    else:
        return None
    for key, item in items:
        found = _non_finite(item, f"{where}/{key}")
        if found:
            return found
    return None


def _dumps(doc, name):
    """A document (dict) as JSON text: NumPy values converted; NaN or inf refused naming the key
    (JSON has no such numbers); another type refused naming the document."""
    try:
        plain = json.loads(json.dumps(doc, default=_json_value))
    except (TypeError, ValueError) as e:
        raise InputError(f"{name}: {e}") from None
    bad = _non_finite(plain, "")
    if bad:
        raise InputError(f"{name}: {bad}: expected a finite number, got a NaN or an infinity "
                         "(JSON has neither)")
    return json.dumps(plain)


def _patches(patches):
    if patches is None:
        return []
    if isinstance(patches, (dict, str)):  # one patch: a document or its JSON text
        patches = [patches]
    return [p if isinstance(p, str) else _dumps(p, f"patches[{k}]") for k, p in enumerate(patches)]


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
            label = _label(base_dir, "material")
            doc = _patched(dict(source), patches, label)
            self._m = _impact.read_material(_dumps(doc, label), label)
        else:
            self._m = _impact.load_material(os.fspath(source), _patches(patches))
        warn_input(self._m.warnings, stacklevel=2)

    name = property(lambda self: self._m.name, doc="the material's name")
    file = property(lambda self: self._m.file, doc="the file it was read from ('' for a dict)")
    warnings = property(lambda self: list(self._m.warnings),
                        doc="the warnings its reading gave (also issued as InputWarning)")
    density = property(lambda self: self._m.density, doc="reference density [kg/m^3]")
    room_temperature = property(lambda self: self._m.room_temperature,
                                doc="room temperature [K]")

    def to_dict(self):
        """The resolved material document (what material_check prints)."""
        return json.loads(self._m.to_json())

    def initial_state(self, temperature=None, n=1):
        """n points at rest at ``temperature`` [K] (default: the material's room temperature),
        as a state dict of arrays with leading dimension n."""
        t = self.room_temperature if temperature is None else temperature
        return self._m.initial_state(float(t), int(n))

    def __repr__(self):
        return f"Material({self.name!r}, file={self.file!r})"


def _merge_patch(target, patch, target_name="merge_patch target", patch_name="merge_patch patch"):
    """RFC 7396 merge patch, by the library's own (nlohmann::json::merge_patch, as the programs
    apply --set); the names are what an InputError calls the two documents."""
    return json.loads(_impact.merge_patch(_dumps(target, target_name), _dumps(patch, patch_name),
                                          target_name, patch_name))


def _patched(doc, patches, label):
    """A dict document with ``patches`` merged in order (``patches[k]`` in messages)."""
    for k, p in enumerate(_patches(patches)):
        doc = _merge_patch(doc, json.loads(p), label, f"patches[{k}]")
    return doc


def load_material(source, patches=None, base_dir=None):
    """A Material from a file name or a dict (see Material)."""
    return Material(source, patches, base_dir)


_TENSOR_KEYS = ("stress", "F", "R")


def _shape(a):
    return "(" + ", ".join(str(k) for k in a.shape) + ("," if a.ndim == 1 else "") + ")"


def update(material, state, L, dt, F1=None):
    """One constitutive step of N points (the solver's batched update, bit for bit the one-point
    update): ``state`` is a dict of arrays with leading dimension N (``Material.initial_state``;
    missing keys start at rest), ``L`` the velocity gradients (N, 3, 3) [1/s], ``dt`` [s], ``F1``
    the end-of-step deformation gradients (default exp(L dt) F). A single point may be given
    without the leading dimension (``L`` (3, 3), scalars and (3, 3) tensors in ``state``); the
    result then has none either. Returns (new state, report): the report's ``status`` and
    ``failure`` are names ("ok", "none", ...), the rest arrays (``plastic_work`` in J/m^3).
    Raises InputError naming the argument or ``state`` key (and the first point) for a wrong
    shape, an unknown key, or a value no state can hold (NaN, a temperature <= 0, a negative
    plastic strain, a negative damage, det F <= 0, ...)."""
    mat = material if isinstance(material, Material) else Material(material)
    L = np.asarray(L, dtype=float)
    if L.ndim not in (2, 3) or L.shape[-2:] != (3, 3):
        raise InputError(f"L: expected velocity gradients of shape (N, 3, 3), or (3, 3) for one "
                         f"point [1/s], got {_shape(L)}")
    single = L.ndim == 2
    if not isinstance(state, dict):
        raise InputError(f"state: expected a dict of arrays (Material.initial_state), got "
                         f"{type(state).__name__}")
    if single:
        L = L[None]
        batched = {}
        for key, value in state.items():
            a = np.asarray(value)
            # A point's own shape gets the leading dimension; (1, ...) arrays are kept.
            batched[key] = a[None] if a.ndim == (2 if key in _TENSOR_KEYS else 0) else a
        state = batched
        if F1 is not None:
            F1 = np.asarray(F1, dtype=float)
            F1 = F1[None] if F1.ndim == 2 else F1
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
    ``warnings`` (also issued as InputWarning). A step the driver cannot solve raises RunError
    (``pointdriver run`` exits 3): its ``reason`` says which step and why, its ``result`` is the
    Table computed up to it and ``result.replay`` a path document repeating the failed step."""
    if isinstance(path, dict):
        label = _label(base_dir, "path")
        r = _impact.run_path_document(_dumps(_patched(path, patches, label), label), label)
    else:
        r = _impact.run_path_file(os.fspath(path), _patches(patches))
    from .results.history import table as _make_table
    columns = r.pop("columns")
    warn_input(r["warnings"], stacklevel=2)
    replay = r.pop("replay")
    result = _make_table(columns, replay=json.loads(replay) if replay else None, **r)
    if not result.completed:
        raise RunError(result.error, _impact.exit_run_failed, result=result)
    return result


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
        text = _impact.fit_document(_dumps(config, _label(base_dir, "fit")), _label(base_dir, "fit"))
    else:
        text = _impact.fit_file(os.fspath(config))
    report = _with_arrays(json.loads(text))
    warn_input(report.get("warnings", []), stacklevel=2)
    return report


def check(config, base_dir=None):
    """Checks a material against measured curves with tolerances (``pointdriver check``; file or
    dict). Returns check_report.json as a dict (``passed``, ``exceeded``, per-curve errors in
    Pa, under ``curves``) with ``series`` as in fit."""
    if isinstance(config, dict):
        text = _impact.check_document(_dumps(config, _label(base_dir, "check")),
                                      _label(base_dir, "check"))
    else:
        text = _impact.check_file(os.fspath(config))
    report = _with_arrays(json.loads(text))
    warn_input(report.get("warnings", []), stacklevel=2)
    return report


def _scene_source(scene, base_dir):
    """(file, text, label) for the C++ side; a dict's ``extends`` is resolved here."""
    if not isinstance(scene, dict):
        return os.fspath(scene), "", ""
    doc = dict(scene)
    label = _label(base_dir, "scene")
    if "extends" in doc:
        base = os.path.join(os.path.abspath(base_dir or os.getcwd()), doc.pop("extends"))
        doc = _merge_patch(json.loads(_impact.scene_document(base)), doc, base, label)
    return "", _dumps(doc, label), label


def check_scene(scene, patches=None, threads=0, base_dir=None):
    """``mpm check``: the validated scene (``resolved``), ``warnings``, and unless the memory
    estimate refuses it (``refusal``) the ``report`` (particles, nodes, time step, memory). The
    warnings are also issued as InputWarning."""
    file, text, label = _scene_source(scene, base_dir)
    checked = json.loads(_impact.check_scene(file, text, label, _patches(patches),
                                             _threads(threads)))
    warn_input(checked["warnings"], stacklevel=2)
    return checked


def run_scene(scene, out, patches=None, threads=0, progress=False, base_dir=None,
              overwrite=False):
    """``mpm run``: runs a scene (file or dict) to its end time, writing into ``out`` what the
    program writes (``read_run(out)`` reads it back). Returns a dict: ``exit_code`` (0),
    ``directory``, ``warnings`` (also issued as InputWarning before the run starts), ``status``
    (status.json), ``summary`` (summary.json) and ``history`` (history.csv as a Table).

    Raises InputError for bad input and for an ``out`` that cannot be written; OutputError (an
    OSError naming the file and the system's reason) when an output cannot be written during the
    run (a full disk, a file-size limit; exit code 3 of ``mpm run``); RunError when the run fails
    (a numerical fault, energy growth: exit code 3, the partial outputs in ``out``) or is refused
    (the memory or step estimate: exit code 4, nothing written, no directory made); an ``out``
    holding the checkpoint of a run that has not finished raises InputError naming
    ``resume_scene(out)`` to continue it and ``overwrite=True`` (``mpm run --overwrite``) to start
    a new run over it;
    Ctrl-C (SIGINT, a notebook's interrupt) stops the run after the step under way, writes a
    checkpoint and raises KeyboardInterrupt, whose message says how to continue
    (``resume_scene(out)``)."""
    file, text, label = _scene_source(scene, base_dir)
    out = writable_directory(out, "out")
    try:
        code, directory, warnings, message, interrupt = _impact.run_scene(
            file, text, label, _patches(patches), out, _threads(threads), bool(progress),
            bool(overwrite), lambda w: warn_input(w, stacklevel=3))
    except InputError as e:
        raise InputError(_in_python_words(str(e))) from None
    return _finish(code, directory, list(warnings), message, interrupt)


def _in_python_words(message):
    """mpm run's remedies for an unfinished run in `out`, as a Python user gives them."""
    message = re.sub(r"'mpm run --restart ([^']*)'", lambda m: f"impact.resume_scene({m.group(1)!r})",
                     message)
    return message.replace("start a new run over it with --overwrite",
                           "start a new run over it with run_scene(..., overwrite=True)")


def resume_scene(directory, threads=0, progress=False):
    """``mpm run --restart``: continues the run in ``directory`` from its checkpoint (written
    every ``output.checkpoint_interval_steps`` and on Ctrl-C), bit for bit as if it had not
    stopped, writing into the same directory. Returns and raises as run_scene; a checkpoint that
    is missing or does not belong to the directory's scene.json raises InputError."""
    directory = os.fspath(directory)
    code, message, interrupt = _impact.resume_scene(directory, _threads(threads), bool(progress))
    return _finish(code, directory, [], message, interrupt)


def _threads(threads):
    """threads as the programs take it: 0 (all the cores) or 1 to 256 (mpm's --threads)."""
    try:
        n = None if isinstance(threads, bool) else operator.index(threads)
    except TypeError:
        n = None
    if n is None or not 0 <= n <= 256:
        raise InputError(f"threads: expected 0 (all the cores) or a whole number from 1 to 256, "
                         f"got {threads!r}")
    return n


def _finish(code, directory, warnings, message, interrupt):
    """run_scene's result, or the exception of a run that did not complete."""
    result = {"exit_code": code, "directory": directory, "warnings": warnings}
    for name, read in (("status", _read_json), ("summary", _read_json)):
        value = read(os.path.join(directory, name + ".json"))
        if value is not None:
            result[name] = value
    # Regular files only: a device in a file's place (the run failed writing it) would be read
    # without end.
    if os.path.isfile(os.path.join(directory, "history.csv")):
        from .results.history import read_history
        result["history"] = read_history(directory)
    if code == 0:
        return result
    # The reason as `mpm run` prints it: the exception a run threw, the refusal, else the
    # message status.json keeps.
    reason = message or result.get("status", {}).get("message") or f"exit code {code}"
    if interrupt is not None:
        note = f"{reason}; from Python: impact.resume_scene({directory!r})"
        if isinstance(interrupt, KeyboardInterrupt) and not interrupt.args:
            interrupt.args = (note,)
        else:
            interrupt.add_note(note)
        raise interrupt
    raise RunError(reason, code, directory, result)


def _read_json(path):
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        return json.load(f)


if _impact is None:
    def _not_built(name):
        def missing(*args, **kwargs):
            raise ImportError(_MISSING)
        missing.__name__ = missing.__qualname__ = name
        missing.__doc__ = f"Needs the compiled module: {_MISSING}"
        return missing

    for _name in _COMPILED:
        globals()[_name] = _not_built(_name)
    del _name
