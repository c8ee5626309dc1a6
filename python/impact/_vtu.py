"""The particle snapshots `mpm run` writes (mpm/output/vtu_writer.cpp): XML VTK unstructured grids
with raw appended binary data (little-endian, UInt64 block headers), one .vtu per step on one
rank, or one piece per rank named by a .pvtu; the .pvd lists them with their times. Read with
NumPy alone (no VTK needed)."""
import os
import re

import numpy as np

from ._errors import InputError

_DTYPES = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4", "UInt64": "<u8",
           "UInt8": "u1"}
_ARRAY = re.compile(r'<DataArray type="(\w+)"(?: Name="([^"]*)")? NumberOfComponents="(\d+)" '
                    r'format="appended" offset="(\d+)"/>')
_SECTION = re.compile(r"<(Points|Cells|PointData)>")
_MARKER = b'<AppendedData encoding="raw">'


def read_vtu(path):
    """(positions (N, 3) [m], {field: array (N,) or (N, components)}) of one .vtu."""
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
    positions, fields = np.zeros((0, 3)), {}
    for m in _ARRAY.finditer(head):
        section = [name for at, name in sections if at < m.start()][-1:] or [""]
        kind, name, components, offset = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
        if section[0] == "Cells":
            continue
        at = start + offset
        if kind not in _DTYPES or at + 8 > len(blob):
            raise InputError(f"{path}: array {name or 'points'}: unreadable ({kind}, offset "
                             f"{offset})")
        nbytes = int.from_bytes(blob[at:at + 8], "little")
        dtype = np.dtype(_DTYPES[kind])
        if nbytes != n * components * dtype.itemsize or at + 8 + nbytes > len(blob):
            raise InputError(f"{path}: array {name or 'points'}: {nbytes} bytes, expected "
                             f"{n * components * dtype.itemsize} (a file cut short?)")
        values = np.frombuffer(blob, dtype, n * components, at + 8).astype(float)
        values = values.reshape(n, components) if components > 1 else values
        if section[0] == "Points":
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
    if not path.endswith(".pvtu"):
        positions, fields = read_vtu(path)
        return positions, fields, 1
    _require_file(path)
    with open(path) as f:
        sources = re.findall(r'<Piece Source="([^"]+)"/>', f.read())
    if not sources:
        raise InputError(f"{path}: names no piece")
    parts = [read_vtu(os.path.join(os.path.dirname(path), s)) for s in sources]
    positions = np.concatenate([p for p, _ in parts])
    fields = {name: np.concatenate([f[name] for _, f in parts]) for name in parts[0][1]}
    return positions, fields, len(parts)


def read_collection(path):
    """[(time [s], file)] of a .pvd, the files as absolute paths."""
    with open(path) as f:
        text = f.read()
    entries = re.findall(r'<DataSet timestep="([^"]+)"[^>]*file="([^"]+)"', text)
    return [(float(t), os.path.join(os.path.dirname(path), file)) for t, file in entries]
