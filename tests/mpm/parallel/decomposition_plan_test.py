#!/usr/bin/env python3
"""`mpm check --ranks N` (mpm/parallel/decomposition_plan.cpp, docs/mpi.md).

The recommended grid (50 x 20 x 20 cells, one field, MUSL) cut 2 x 2 x 1 on 4 ranks: a box's
stored nodes are its cells and 3 halo layers each side within [-1, cells + 1], so an x-low box
stores 22 x 15 x 23 nodes and sends 3 layers x (15 x 23 + 22 x 23) nodes x 88 B = 224 664 B per
step, an x-high box 38 x 15 x 23 and 3 x (15 x 23 + 38 x 23) x 88 B = 321 816 B (what the MPI
test measures a run sending). Then its "least_loaded_split" (every split's boxes balanced per axis,
then their boundaries refined, mpm/parallel/split_search.hpp) against counts made another way:
it must weigh every split of N that leaves each split axis at least 3 cells per box (enumerated
here), its busiest box must hold no more particles than the busiest box of any of those splits
balanced per axis only (each counted by `mpm check` with that split set, particles assigned to
boxes one by one), and `mpm check` with solver.ranks_per_axis "least_loaded" must make those
boxes and count that busiest box particle by particle.

  decomposition_plan_test.py MPM SCENE RANKS
"""
import json
import subprocess
import sys


def plan(mpm, scene, ranks, split=None):
    cmd = [mpm, "check", scene, "--ranks", str(ranks)]
    if split:
        cmd += ["--set", json.dumps({"solver": {"ranks_per_axis": split}})]
    done = subprocess.run(cmd, capture_output=True, text=True)
    assert done.returncode == 0, (cmd, done.stderr)
    text = done.stdout
    report = json.loads(text)["report"]
    return report["decomposition"]


def known_split(mpm, scene):
    p = plan(mpm, scene, 4, [2, 2, 1])
    halo = p["halo_bytes_sent_per_step [B]"]
    assert (halo["min"], halo["max"]) == (224664.0, 321816.0), p
    # 2 neighbours x 2 exchanges (the P2G sums and the re-map momentum), one message each
    assert p["halo_messages_sent_per_step"]["max"] == 4 and p["empty_ranks"] == 0, p
    print(f"2 x 2 x 1 on 4 ranks: {halo['min']:.0f} and {halo['max']:.0f} B per step, by hand too")


def main(mpm, scene, ranks):
    known_split(mpm, scene)
    automatic = plan(mpm, scene, ranks)
    resolved = subprocess.run([mpm, "check", scene], capture_output=True, text=True).stdout
    cells = json.loads(resolved)["resolved"]["grid"]["cells"]
    splits = []
    for px in range(ranks, 0, -1):
        for py in range(ranks // px, 0, -1):
            if ranks % px or (ranks // px) % py:
                continue
            p = [px, py, ranks // px // py]
            if all(p[d] == 1 or cells[d] >= 3 * p[d] for d in range(3)):
                splits.append(p)
    busiest = {tuple(p): plan(mpm, scene, ranks, p)["particles_per_rank"]["max"] for p in splits}
    best = automatic["least_loaded_split"]
    print(f"{len(splits)} splits of {ranks} ranks, busiest box per split: {busiest}")
    print(f"least loaded: {best}")
    assert best["splits_searched"] == len(splits), (best, splits)
    assert best["particles_per_rank_max"] <= min(busiest.values()), (best, busiest)
    assert best["particles_per_rank_max"] <= automatic["particles_per_rank"]["max"]
    chosen = plan(mpm, scene, ranks, "least_loaded")
    print(f"with \"least_loaded\": {chosen['boxes']}, busiest {chosen['particles_per_rank']['max']}")
    assert chosen["boxes"] == best["boxes"], (chosen, best)
    assert chosen["particles_per_rank"]["max"] == best["particles_per_rank_max"], (chosen, best)
    print("OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]))
