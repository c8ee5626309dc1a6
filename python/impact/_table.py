"""Named columns with units: what a path run returns and what a run's history.csv holds."""
import csv
import os

import numpy as np

from ._impact import InputError


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
    columns, units = {}, {}
    for cell, values in named_columns.items():
        name, unit = split_header(cell)
        columns[name], units[name] = np.asarray(values), unit
    return Table(columns, units, **info)


def read_history(directory):
    """history.csv of a run directory as a Table (``time`` [s], energies [J], momentum [kg m/s],
    the gauges' observables in their units; in plane strain per metre of thickness, [J/m],
    [(kg m/s)/m]: the units are the header's, in ``units``). A last row cut short (a run killed
    while writing it) is left out."""
    file = os.path.join(os.fspath(directory), "history.csv")
    if not os.path.isfile(file):  # a device or a FIFO in its place would be read without end
        raise InputError(f"{file}: expected the history.csv file mpm run writes, found "
                         + ("nothing" if not os.path.lexists(file) else "no regular file"))
    with open(file, newline="") as f:
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
