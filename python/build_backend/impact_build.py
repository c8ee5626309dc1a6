"""The in-tree PEP 517 backend of `pip install .` (pyproject.toml names it through backend-path):
CMake builds the extension `impact._impact`, this module packs it with the pure-Python package
and the shipped data into a wheel. It needs the standard library, CMake and the Debian packages
the build needs; nothing is downloaded (no build requirements).

Where it builds: the config setting ``build-dir`` (``pip install . --config-settings
build-dir=build``), else ``$IMPACT_BUILD_DIR``, else ``build/pip-<python tag>`` in the source
tree. A directory that is already configured is only built (target impact_python), never
reconfigured; a new one is configured Release, without the tests, for the interpreter running
pip. ``jobs`` (config setting) or ``$CMAKE_BUILD_PARALLEL_LEVEL`` sets the build's parallelism
(default: the processor count).

The wheel holds impact/ (the .py files, the type stub, py.typed, the extension) and the shipped
data as ``<prefix>/share/impact/data``, where ``impact.data_path`` finds it, as after
``cmake --install``. docs/python.md#pip-install.
"""
import base64
import hashlib
import io
import os
import re
import subprocess
import sys
import sysconfig
import tarfile
import zipfile

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NAME = "impact_mpm"  # the distribution's name normalised for file names (PEP 427)
SUMMARY = ("impact-mpm from Python: materials, batch constitutive updates, point-driver paths, "
           "fitting, MPM scenes")


class BuildError(RuntimeError):
    pass


def _version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        match = re.search(r"project\(\s*impact_mpm\s+VERSION\s+([0-9.]+)", f.read())
    if not match:
        raise BuildError(f"{SOURCE}/CMakeLists.txt: no project(impact_mpm VERSION x.y.z)")
    return match.group(1)


def _tag():
    """cpXY-cpXY-<platform>: the extension is built for this interpreter and machine."""
    python = f"cp{sys.version_info[0]}{sys.version_info[1]}"
    platform = re.sub(r"[-.]", "_", sysconfig.get_platform())
    return f"{python}-{python}{sys.abiflags}-{platform}"


def _dist_info():
    return f"{NAME}-{_version()}.dist-info"


def _metadata():
    return (f"Metadata-Version: 2.1\nName: impact-mpm\nVersion: {_version()}\n"
            f"Summary: {SUMMARY}\nLicense: MIT\nRequires-Python: >=3.9\nRequires-Dist: numpy\n"
            "\nThe Python module `impact` of impact-mpm (docs/python.md of the repository).\n")


def _wheel_file():
    return (f"Wheel-Version: 1.0\nGenerator: impact_build {_version()}\nRoot-Is-Purelib: false\n"
            f"Tag: {_tag()}\n")


def _run(cmd):
    print("impact_build:", " ".join(cmd), file=sys.stderr, flush=True)
    done = subprocess.run(cmd, stdout=sys.stderr)
    if done.returncode != 0:
        raise BuildError(f"{' '.join(cmd)} exited with code {done.returncode}")


def _build_extension(config_settings):
    """Builds impact_python; returns the path of the extension built for this interpreter."""
    settings = config_settings or {}
    build = (settings.get("build-dir") or os.environ.get("IMPACT_BUILD_DIR")
             or os.path.join(SOURCE, "build", "pip-" + _tag().split("-")[0]))
    build = os.path.abspath(build)
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        _run(["cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
              "-DIMPACT_BUILD_TESTS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"])
    jobs = settings.get("jobs") or os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or os.cpu_count()
    _run(["cmake", "--build", build, "--target", "impact_python", "--parallel", str(jobs or 1)])
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    extension = os.path.join(build, "python", "impact", "_impact" + suffix)
    if not os.path.exists(extension):
        found = [f for f in os.listdir(os.path.join(build, "python", "impact"))
                 if f.startswith("_impact.")] if os.path.isdir(
                     os.path.join(build, "python", "impact")) else []
        raise BuildError(f"{build}: no {os.path.basename(extension)} for {sys.executable} "
                         f"(found: {', '.join(found) or 'none'}; the build directory was "
                         "configured for another Python, or without python3-dev and "
                         "pybind11-dev: use another build-dir)")
    return extension


def _package_files(extension):
    """(path in the wheel, path on disk) of everything installed."""
    files = []
    package = os.path.join(SOURCE, "python", "impact")
    for root, dirs, names in os.walk(package):  # impact/ and its subpackage impact/results/
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        for name in sorted(names):
            if name.endswith((".py", ".pyi")) or name == "py.typed":
                disk = os.path.join(root, name)
                files.append(("impact/" + os.path.relpath(disk, package).replace(os.sep, "/"),
                              disk))
    files.append(("impact/" + os.path.basename(extension), extension))
    data = os.path.join(SOURCE, "data")
    prefix = f"{NAME}-{_version()}.data/data/share/impact/data/"
    for root, dirs, names in os.walk(data):
        dirs.sort()
        for name in sorted(names):
            disk = os.path.join(root, name)
            files.append((prefix + os.path.relpath(disk, data).replace(os.sep, "/"), disk))
    files.append((f"{_dist_info()}/LICENSE", os.path.join(SOURCE, "LICENSE")))
    return files


def _record_line(name, content):
    digest = base64.urlsafe_b64encode(hashlib.sha256(content).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(content)}"


def _write_dist_info(directory):
    info = os.path.join(directory, _dist_info())
    os.makedirs(info, exist_ok=True)
    for name, text in (("METADATA", _metadata()), ("WHEEL", _wheel_file())):
        with open(os.path.join(info, name), "w") as f:
            f.write(text)
    return _dist_info()


# PEP 517 hooks.

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _write_dist_info(metadata_directory)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    extension = _build_extension(config_settings)
    name = f"{NAME}-{_version()}-{_tag()}.whl"
    records = []
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", zipfile.ZIP_DEFLATED) as whl:
        def add(arcname, content, mode=0o644):
            info = zipfile.ZipInfo(arcname, date_time=(2026, 1, 1, 0, 0, 0))
            info.external_attr = (0o100000 | mode) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            whl.writestr(info, content)
            records.append(_record_line(arcname, content))

        for arcname, disk in _package_files(extension):
            with open(disk, "rb") as f:
                add(arcname, f.read(), 0o755 if disk == extension else 0o644)
        add(f"{_dist_info()}/METADATA", _metadata().encode())
        add(f"{_dist_info()}/WHEEL", _wheel_file().encode())
        add(f"{_dist_info()}/top_level.txt", b"impact\n")
        record = f"{_dist_info()}/RECORD"
        whl.writestr(record, "\n".join(records + [f"{record},,"]) + "\n")
    return name


def build_sdist(sdist_directory, config_settings=None):
    """The source tree as git tracks it (or, outside git, without build and output folders)."""
    try:
        listed = subprocess.run(["git", "-C", SOURCE, "ls-files", "-z"], capture_output=True,
                                check=True).stdout.decode().split("\0")
        files = [f for f in listed if f and os.path.isfile(os.path.join(SOURCE, f))]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for root, dirs, names in os.walk(SOURCE):
            rel = os.path.relpath(root, SOURCE)
            dirs[:] = sorted(d for d in dirs if not (rel == "." and (
                d.startswith(("build", ".")) or d == "out")) and d != "__pycache__")
            files += [os.path.normpath(os.path.join(rel, n)) for n in sorted(names)]
    top = f"{NAME}-{_version()}"
    name = top + ".tar.gz"
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz", format=tarfile.PAX_FORMAT) as t:
        for f in files:
            t.add(os.path.join(SOURCE, f), arcname=f"{top}/{f}", recursive=False)
        pkg_info = _metadata().encode()
        info = tarfile.TarInfo(f"{top}/PKG-INFO")
        info.size = len(pkg_info)
        t.addfile(info, io.BytesIO(pkg_info))
    return name
