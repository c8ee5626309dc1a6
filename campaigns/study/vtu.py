"""Reads the particle snapshots `mpm run` writes (XML VTK UnstructuredGrid, raw appended data with
UInt64 headers, little endian; mpm/output/vtu_writer.cpp): positions and point-data arrays as numpy
arrays. No VTK needed; ParaView reads the same files directly."""

import os
import re

import numpy as np

_TYPES = {"Float64": "<f8", "Int64": "<i8", "UInt8": "u1"}
_ARRAY = re.compile(rb'<DataArray type="(\w+)"(?: Name="(\w+)")? NumberOfComponents="(\d+)"'
                    rb' format="appended" offset="(\d+)"/>')


def read_vtu(path):
    """{"points": (n, 3) array [m], field name: (n,) or (n, k) array} of one snapshot. A .pvtu
    (a run on several MPI ranks: one .vtu piece per rank) gives its pieces concatenated in the
    order it lists them."""
    if path.endswith(".pvtu"):
        with open(path) as f:
            sources = re.findall(r'<Piece Source="([^"]+)"', f.read())
        pieces = [read_vtu(os.path.join(os.path.dirname(path), s)) for s in sources]
        return {k: np.concatenate([p[k] for p in pieces]) for k in pieces[0]} if pieces else {}
    with open(path, "rb") as f:
        blob = f.read()
    start = blob.index(b'<AppendedData encoding="raw">')
    data = blob.index(b"_", start) + 1
    out = {}
    for m in _ARRAY.finditer(blob[:start]):
        kind, name, comps, offset = m.group(1).decode(), m.group(2), int(m.group(3)), int(m.group(4))
        at = data + offset
        nbytes = int(np.frombuffer(blob, "<u8", 1, at)[0])
        dtype = np.dtype(_TYPES[kind])
        values = np.frombuffer(blob, dtype, nbytes // dtype.itemsize, at + 8)
        key = name.decode() if name else "points"
        out[key] = values.reshape(-1, comps) if comps > 1 else values
    return out


def snapshots(run_dir):
    """The snapshot files of a run directory, in time order (from particles.pvd)."""
    with open(f"{run_dir}/particles.pvd") as f:
        text = f.read()
    return [(float(t), f"{run_dir}/{name}")
            for t, name in re.findall(r'timestep="([^"]+)" part="0" file="([^"]+)"', text)]
