"""The particle snapshots `mpm run` writes (mpm/output/vtu_writer.cpp): XML VTK unstructured grids
with raw appended binary data (little-endian, UInt64 block headers), one .vtu per step on one
rank, or one piece per rank named by a .pvtu; the .pvd lists them with their times. Read with
NumPy alone (no VTK needed); ``read_points(path, numpy=False)`` with the standard library alone.

``read_vtu``/``read_snapshot``/``read_collection`` are what ``read_run`` uses (values as floats);
``read_points`` and ``snapshots`` are the campaign scripts' form: {"points": (N, 3), field: (N,)
or (N, k)} in the file's own types, the pieces of a .pvtu joined in the order it lists them."""
import os
import re
import struct

from .._errors import InputError

_DTYPES = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4", "UInt64": "<u8",
           "UInt8": "u1"}
_ARRAY = re.compile(r'<DataArray type="(\w+)"(?: Name="([^"]*)")? NumberOfComponents="(\d+)" '
                    r'format="appended" offset="(\d+)"/>')
_SECTION = re.compile(r"<(Points|Cells|PointData)>")
_MARKER = b'<AppendedData encoding="raw">'


def _arrays(path):
    """(blob, [(section, kind, name, components, at, count)]) of one .vtu's appended arrays
    outside <Cells>: `at` is the first byte of the values, `count` their number; an InputError
    names the file and the array when the file is not what mpm writes or is cut short."""
    _require_file(path)
    with open(path, "rb") as f:
        blob = f.read()
    marker = blob.find(_MARKER)
    head = blob[:max(marker, 0)].decode("utf-8", "replace")
    if (marker < 0 or 'byte_order="LittleEndian"' not in head
            or 'header_type="UInt64"' not in head):
        raise InputError(f"{path}: expected a VTU with raw appended data, little-endian, UInt64 "
                         "headers (as mpm run writes them)")
    start = blob.index(b"_", marker) + 1
    points = re.search(r'NumberOfPoints="(\d+)"', head)
    n = int(points.group(1)) if points else 0
    sections = [(m.start(), m.group(1)) for m in _SECTION.finditer(head)]
    found = []
    for m in _ARRAY.finditer(head):
        section = ([name for at, name in sections if at < m.start()][-1:] or [""])[0]
        kind, name, components, offset = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
        if section == "Cells":
            continue
        at = start + offset
        if kind not in _DTYPES or at + 8 > len(blob):
            raise InputError(f"{path}: array {name or 'points'}: unreadable ({kind}, offset "
                             f"{offset})")
        nbytes = int.from_bytes(blob[at:at + 8], "little")
        size = int(_DTYPES[kind][-1])
        if nbytes != n * components * size or at + 8 + nbytes > len(blob):
            raise InputError(f"{path}: array {name or 'points'}: {nbytes} bytes, expected "
                             f"{n * components * size} (a file cut short?)")
        found.append((section, kind, name, components, at + 8, n * components))
    return blob, found


def read_vtu(path):
    """(positions (N, 3) [m], {field: array (N,) or (N, components)}) of one .vtu, as floats."""
    import numpy as np
    blob, arrays = _arrays(path)
    positions, fields = np.zeros((0, 3)), {}
    for section, kind, name, components, at, count in arrays:
        values = np.frombuffer(blob, np.dtype(_DTYPES[kind]), count, at).astype(float)
        values = values.reshape(-1, components) if components > 1 else values
        if section == "Points":
            positions = values
        else:
            fields[name] = values
    return positions, fields


def _require_file(path):
    """A snapshot the .pvd (or .pvtu) lists but that is gone, or not a file, is an InputError
    naming it (it was a bare FileNotFoundError)."""
    if not os.path.isfile(path):
        what = "is not a regular file" if os.path.exists(path) else "is missing"
        raise InputError(f"{path}: {what}, though the run's particles.pvd lists it (deleted, or "
                         "the run directory copied without it?)")


def read_snapshot(path):
    """(positions, fields, pieces) of a .vtu, or of the pieces a .pvtu names (several ranks),
    concatenated in rank order."""
    import numpy as np
    if not path.endswith(".pvtu"):
        positions, fields = read_vtu(path)
        return positions, fields, 1
    parts = [read_vtu(piece) for piece in _pieces(path)]
    positions = np.concatenate([p for p, _ in parts])
    fields = {name: np.concatenate([f[name] for _, f in parts]) for name in parts[0][1]}
    return positions, fields, len(parts)


def read_collection(path):
    """[(time [s], file)] of a .pvd, the files joined to the .pvd's directory."""
    with open(path) as f:
        text = f.read()
    entries = re.findall(r'<DataSet timestep="([^"]+)"[^>]*file="([^"]+)"', text)
    return [(float(t), os.path.join(os.path.dirname(path), file)) for t, file in entries]


def _pieces(path):
    """The piece files a .pvtu names, as paths beside it."""
    _require_file(path)
    with open(path) as f:
        sources = re.findall(r'<Piece Source="([^"]+)"/>', f.read())
    if not sources:
        raise InputError(f"{path}: names no piece")
    return [os.path.join(os.path.dirname(path), s) for s in sources]


def read_points(path, numpy=True):
    """{"points": positions (N, 3) [m], field: (N,) or (N, k)} of one snapshot in the file's own
    types (Int64 ids stay integers); a .pvtu (several ranks) gives its pieces joined in the order
    it lists them. ``numpy=False`` reads with the standard library alone: lists of numbers, or
    of tuples for fields of several components."""
    if path.endswith(".pvtu"):
        parts = [read_points(piece, numpy) for piece in _pieces(path)]
        if numpy:
            import numpy as np
            return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
        return {k: [v for p in parts for v in p[k]] for k in parts[0]}
    blob, arrays = _arrays(path)
    out = {}
    for _, kind, name, components, at, count in arrays:
        if numpy:
            import numpy as np
            values = np.frombuffer(blob, np.dtype(_DTYPES[kind]), count, at)
            values = values.reshape(-1, components) if components > 1 else values
        else:
            flat = struct.unpack_from("<" + str(count) + _STRUCT[kind], blob, at)
            values = ([flat[i:i + components] for i in range(0, count, components)]
                      if components > 1 else list(flat))
        out[name or "points"] = values
    return out


_STRUCT = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt64": "Q", "UInt8": "B"}


def snapshots(run_dir):
    """[(time [s], file)] of a run directory's snapshots in time order (its particles.pvd), the
    files as ``os.path.join(run_dir, name)``."""
    return read_collection(os.path.join(run_dir, "particles.pvd"))
