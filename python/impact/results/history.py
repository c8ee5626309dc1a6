"""Named columns with units: what a path run returns and what a run's history.csv holds.
``read_history`` gives NumPy columns with their units (a Table); ``history_rows`` and
``history_columns`` read the same file with the standard library alone, keyed by the header's
cells as written ("time [s]", "gauge_tip [m/s]")."""
import csv
import os

from .._errors import InputError


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


def split_header(cell):
    """'stress_xx [Pa]' -> ('stress_xx', 'Pa'): the name is what comes before " [", the unit what
    the brackets hold ('kinetic_energy [J/m]' -> ('kinetic_energy', 'J/m') in plane strain); a
    cell without a unit gets ''."""
    cell = cell.strip()
    if cell.endswith("]") and " [" in cell:
        name, unit = cell[:-1].split(" [", 1)
        return name, unit
    return cell, ""


def table(named_columns, **info):
    """A Table from {'name [unit]': values}."""
    import numpy as np
    columns, units = {}, {}
    for cell, values in named_columns.items():
        name, unit = split_header(cell)
        columns[name], units[name] = np.asarray(values), unit
    return Table(columns, units, **info)


def _history_file(directory):
    file = os.path.join(os.fspath(directory), "history.csv")
    if not os.path.isfile(file):  # a device or a FIFO in its place would be read without end
        raise InputError(f"{file}: expected the history.csv file mpm run writes, found "
                         + ("nothing" if not os.path.lexists(file) else "no regular file"))
    return file


def history_rows(directory):
    """(header, rows) of a run directory's history.csv: the header's cells as written, each row
    a list of floats. Empty lines, rows of another length than the header and rows that are not
    numbers (a last row cut short: a run killed while writing it) are left out. InputError when
    there is no such file."""
    with open(_history_file(directory), newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    if not rows:
        return [], []
    header, body = rows[0], []
    for row in rows[1:]:
        if len(row) != len(header):
            continue
        try:
            body.append([float(c) for c in row])
        except ValueError:
            continue
    return header, body


def history_columns(directory):
    """{header cell ("time [s]"): [float per row]} of a run directory's history.csv (as
    history_rows reads it), with the standard library alone."""
    header, rows = history_rows(directory)
    return {cell: [r[k] for r in rows] for k, cell in enumerate(header)}


def read_history(directory):
    """history.csv of a run directory as a Table (``time`` [s], energies [J], momentum [kg m/s],
    the gauges' observables in their units; in plane strain per metre of thickness, [J/m],
    [(kg m/s)/m]: the units are the header's, in ``units``). A last row cut short (a run killed
    while writing it) is left out."""
    import numpy as np
    with open(_history_file(directory), newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    if body:
        try:
            last = [float(c) for c in body[-1]]
        except ValueError:
            last = []
        if len(last) != len(header):
            body = body[:-1]
    columns = {cell: np.array([float(r[k]) for r in body]) for k, cell in enumerate(header)}
    return table(columns)
