"""read_run: a run directory read back (history with units, summary, status, scene, snapshots with
positions and fields), on one rank and, when the build has MPI, on two."""
import json
import os
import subprocess

import numpy as np
import pytest

import impact

V = np.array([30.0, -20.0, 10.0])  # the shipped block's velocity [m/s]


def translation(data, max_time=4e-5):
    """The shipped rigid translation (a 20 mm block of 6061-T6 at V on a free grid), snapshots
    every 1e-5 s with the fields read_run converts."""
    return {"extends": data("scenes", "verification", "rigid_translation.json"),
            "time": {"max_time": max_time},
            "output": {"interval": 1e-5, "snapshots": True,
                       "fields": ["velocity", "stress", "id", "failed", "plastic_strain"]}}


def test_read_run_of_a_rigid_translation(data, workdir):
    """Each snapshot holds every particle once (by id), at its seed position + V t to 1e-12 of
    the grid's extent, moving at V, stress-free; the history is history.csv with units."""
    impact.run_scene(translation(data), out="run", threads=1)
    run = impact.read_run("run")
    assert run.status["status"] == "completed" and run.summary["status"] == "completed"
    assert run.scene["time"]["max_time"] == 4e-5
    h = run.history
    assert h.units["time"] == "s" and h.units["kinetic_energy"] == "J"
    assert h.units["momentum_x"] == "kg m/s" and h.units["energy_error"] == "-"
    mass = run.summary["mass [kg]"]
    np.testing.assert_allclose(h["momentum_x"], V[0] * mass, rtol=1e-12)
    # Snapshots at the first step at or after 0, 1, 2, 3, 4 x 1e-5 s (and at the end), in time
    # order, as the .pvd lists them; a step is at most max_time / (steps - 1) (constant dt, the
    # last one cut to end at max_time).
    times = np.array([s.time for s in run.snapshots])
    due = np.array([0.0, 1e-5, 2e-5, 3e-5, 4e-5])
    dt = run.summary["time [s]"] / (run.summary["steps"] - 1)
    assert len(times) == 5 and times[0] == 0.0 and times[-1] == 4e-5
    assert np.all(times >= due - 1e-18) and np.all(times - due < dt), (times, dt)
    first, last = run.snapshots[0], run.snapshots[-1]
    assert first.step == 0 and last.step > 0 and last.pieces == 1
    n = run.summary["particles"]
    f = last.fields
    assert first.positions.shape == (n, 3) and f["velocity"].shape == (n, 3)
    assert f["stress"].shape == (n, 3, 3) and f["id"].dtype == np.int64
    assert f["failed"].dtype == bool and not f["failed"].any()
    assert f.units["velocity"] == "m/s" and f.units["stress"] == "Pa"
    assert sorted(f["id"]) == list(range(n))
    x0 = first.positions[np.argsort(first.fields["id"])]
    x1 = last.positions[np.argsort(f["id"])]
    extent = 0.06  # the grid's [m]
    assert np.max(np.abs(x1 - x0 - V * last.time)) < 1e-12 * extent
    np.testing.assert_allclose(f["velocity"], np.tile(V, (n, 1)), rtol=1e-12)
    # Stress-free up to round-off: K = 66.4 GPa times strain increments of a few 1e-16 per step,
    # over 99 steps, is below 1e-3 Pa (measured 1.7e-6 Pa).
    assert np.max(np.abs(f["stress"])) < 1e-3
    assert np.array_equal(f["stress"], np.transpose(f["stress"], (0, 2, 1)))
    assert "Run('run', completed" in repr(run)


def test_snapshot_stress_is_the_particle_paths_stress(data, workdir):
    """The shipped sliding block (wall friction on x-, gravity along -x) after 2e-5 s: all six
    stress components of the particle at the wall are distinct and non-zero; the last snapshot's
    stress of that particle (found by id at its seed position) equals, component by component,
    the last row of its particle path (paths/wall.csv, columns named stress_xy, ...) to 1e-12.
    This checks the VTU's component order (xx yy zz xy yz xz) as read_run maps it."""
    seed = [0.00013, 0.00413, 0.00313]  # nearest one particle, not equidistant to two [m]
    scene = {"extends": data("scenes", "verification", "sliding_block.json"),
             "time": {"max_time": 2e-5},
             "output": {"interval": 1e-5, "snapshots": True, "fields": ["stress", "id"],
                        "particle_paths": {"wall": {"object": "block", "position": seed}}}}
    run = impact.read_run(impact.run_scene(scene, out="run", threads=1)["directory"])
    path = run.paths["wall"]
    assert path.units["stress_xy"] == "Pa" and path["time"][-1] == run.snapshots[-1].time
    first, last = run.snapshots[0], run.snapshots[-1]
    pid = first.fields["id"][np.argmin(np.linalg.norm(first.positions - seed, axis=1))]
    stress = last.fields["stress"][np.flatnonzero(last.fields["id"] == pid)[0]]
    for (i, j), name in zip(((0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2)),
                            ("xx", "yy", "zz", "xy", "yz", "zx")):
        expected = path["stress_" + name][-1]
        # [Pa]: every component is there to be told apart (zx is the smallest, 477 Pa since the
        # wall's re-map holds what its step held; compared to 1e-12 relative below)
        assert abs(expected) > 1e2, name
        assert abs(stress[i, j] - expected) <= 1e-12 * abs(expected), (name, stress, expected)
    assert len({round(abs(path["stress_" + n][-1])) for n in ("xy", "yz", "zx")}) == 3


def test_snapshot_deformation_gradient_is_the_volume_change(data, workdir):
    """The sliding block after 2e-5 s with the tensors of its history in the snapshot (F and R,
    9 components each, docs/mpm.md#snapshot-fields): read back as (N, 3, 3); the volume is V0
    det F (V0 the first snapshot's volume, F = I there) to 1e-12, R is a rotation to 1e-9, and
    the units are the table's."""
    scene = {"extends": data("scenes", "verification", "sliding_block.json"),
             "time": {"max_time": 2e-5},
             "output": {"interval": 1e-5, "snapshots": True,
                        "fields": ["F", "R", "volume", "id", "porosity", "melted"]}}
    run = impact.read_run(impact.run_scene(scene, out="run", threads=1)["directory"])
    first, last = run.snapshots[0], run.snapshots[-1]
    assert last.fields["F"].shape == (len(last.positions), 3, 3)
    assert last.fields.units["F"] == "-" and last.fields.units["porosity"] == "-"
    assert last.fields["melted"].dtype == bool and not last.fields["melted"].any()
    assert np.array_equal(first.fields["F"], np.broadcast_to(np.eye(3), first.fields["F"].shape))
    order = np.argsort(last.fields["id"])
    assert np.array_equal(last.fields["id"][order], np.sort(first.fields["id"]))
    v0 = first.fields["volume"][np.argsort(first.fields["id"])]
    F = last.fields["F"][order]
    assert np.max(np.abs(F - np.eye(3))) > 1e-6  # the block has deformed
    assert np.allclose(last.fields["volume"][order], v0 * np.linalg.det(F), rtol=1e-12, atol=0)
    R = last.fields["R"]
    assert np.max(np.abs(np.einsum("nji,njk->nik", R, R) - np.eye(3))) < 1e-9


def test_history_units_are_the_headers_per_metre_in_plane_strain(workdir):
    """A plane-strain history labels its energies, momenta, masses and volumes per metre of
    thickness (`kinetic_energy [J/m]`, `momentum_x [(kg m/s)/m]`): the columns are named by
    what comes before " [" and keep the header's unit, as a 3D history's do."""
    os.makedirs("plane")
    with open(os.path.join("plane", "history.csv"), "w") as f:
        f.write("time [s],kinetic_energy [J/m],momentum_x [(kg m/s)/m],"
                "boundary_impulse_x [(N s)/m],outflow_mass [kg/m],energy_error [-]\n"
                "0,12.5,1.5,0,0,0\n1e-06,12.25,1.5,-0.25,0.001,1e-15\n")
    h = impact.read_run("plane").history
    assert list(h) == ["time", "kinetic_energy", "momentum_x", "boundary_impulse_x",
                       "outflow_mass", "energy_error"]
    assert h.units == {"time": "s", "kinetic_energy": "J/m", "momentum_x": "(kg m/s)/m",
                       "boundary_impulse_x": "(N s)/m", "outflow_mass": "kg/m",
                       "energy_error": "-"}
    assert list(h["kinetic_energy"]) == [12.5, 12.25] and h["outflow_mass"][1] == 0.001


def test_snapshot_mass_and_volume_are_per_metre_in_plane_strain(data, workdir):
    """Two 6 x 8 mm blocks on a plane-strain grid: each particle is its area times 1 m of
    thickness, so the snapshot's volumes sum to 2 x 48e-6 m^2 x 1 m and its masses to the
    summary's mass per metre; read_run labels them m^3/m and kg/m (it said m^3 and kg)."""
    scene = {"extends": data("scenes", "verification", "contact_blocks.json"),
             "grid": {"geometry": "plane_strain", "lower": [0.0, 0.0], "upper": [0.02, 0.012],
                      "cells": [20, 12], "boundary": {"z-": None, "z+": None}},
             "objects": {"left": {"geometry": {"lower": [0.004, 0.002, -0.002],
                                               "upper": [0.010, 0.010, 0.002]},
                                  "particles_per_cell": [2, 2]},
                         "right": {"geometry": {"lower": [0.010, 0.002, -0.002],
                                                "upper": [0.016, 0.010, 0.002]},
                                   "particles_per_cell": [2, 2]}},
             "time": {"max_time": 1.0e-6},
             "output": {"snapshots": True, "interval": 1.0e-6, "fields": ["mass", "volume"]}}
    run = impact.read_run(impact.run_scene(scene, out="plane", threads=1)["directory"])
    f = run.snapshots[0].fields
    assert f.units["mass"] == "kg/m" and f.units["volume"] == "m^3/m", f.units
    np.testing.assert_allclose(f["volume"].sum(), 2 * 0.006 * 0.008, rtol=1e-12)
    np.testing.assert_allclose(f["mass"].sum(), run.summary["mass [kg/m]"], rtol=1e-12)
    three_d = impact.read_run(impact.run_scene(translation(data, 1e-5), out="3d",
                                               threads=1)["directory"])
    assert three_d.snapshots[0].fields.units["stress"] == "Pa"


def test_a_snapshot_the_collection_lists_but_is_gone_names_it(data, workdir):
    """A .vtu deleted after the run (or a run directory copied without it): read_run still reads
    the run; the snapshot's data raises InputError naming the file (a bare FileNotFoundError
    from open, before)."""
    impact.run_scene(translation(data), out="run", threads=1)
    run = impact.read_run("run")
    gone = run.snapshots[1].file
    os.remove(gone)
    run = impact.read_run("run")
    assert run.snapshots[0].positions.shape[1] == 3
    with pytest.raises(impact.InputError,
                       match=r"is missing, though the run's particles.pvd lists it"):
        run.snapshots[1].positions
    assert gone in str(pytest.raises(impact.InputError, lambda: run.snapshots[1].fields).value)


def test_read_run_of_a_directory_that_is_not_one(workdir):
    os.makedirs("empty")
    with pytest.raises(impact.InputError, match=r"^empty: expected a run directory"):
        impact.read_run("empty")


@pytest.mark.skipif(not os.environ.get("IMPACT_MPIEXEC"),
                    reason="the build has no MPI (CTest sets IMPACT_MPIEXEC and IMPACT_MPM)")
def test_read_run_of_two_ranks_equals_one_rank(data, workdir):
    """`mpirun -np 2 mpm run`: every snapshot is a .pvtu of two pieces; read_run joins them into
    every particle once, at the one-rank run's positions and velocities to 1e-12 of the extent
    and of |V| (the ranks differ only in the order of sums at the shared node planes)."""
    one = impact.read_run(impact.run_scene(translation(data), out="one", threads=1)["directory"])
    with open("scene.json", "w") as f:
        json.dump(translation(data), f)
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    subprocess.run([os.environ["IMPACT_MPIEXEC"], "-np", "2", "--oversubscribe",
                    os.environ["IMPACT_MPM"], "run", "scene.json", "--out", "two", "--threads",
                    "1"], env=env, check=True, capture_output=True)
    two = impact.read_run("two")
    assert two.summary["ranks"] == 2
    assert len(two.snapshots) == len(one.snapshots) == 5
    for a, b in zip(one.snapshots, two.snapshots):
        assert b.file.endswith(".pvtu") and b.pieces == 2 and a.time == b.time
        ia, ib = np.argsort(a.fields["id"]), np.argsort(b.fields["id"])
        assert np.array_equal(a.fields["id"][ia], b.fields["id"][ib])
        assert np.max(np.abs(a.positions[ia] - b.positions[ib])) < 1e-12 * 0.06
        assert np.max(np.abs(a.fields["velocity"][ia] - b.fields["velocity"][ib])) < 1e-12 * 40
    np.testing.assert_allclose(two.history["kinetic_energy"], one.history["kinetic_energy"],
                               rtol=1e-12)
