#!/usr/bin/env python3
"""Outputs on a full disk, and runs too large to fit (docs/reliability.md, "Outputs").

A full disk is stood in for without root: a file-size limit (RLIMIT_FSIZE, as `ulimit -f`, with
SIGXFSZ ignored so that the write fails with EFBIG instead of killing the program) or /dev/full
(every write fails with ENOSPC). Each case runs the program once normally, then under the limit,
and checks the exit code, the message (the file and the reason), that every file of the first run
is byte for byte what it was and that no `.tmp` is left.

  outputs_test.py BIN_DIR SOURCE_DIR WORK_DIR CASE
"""
import json
import os
import resource
import shutil
import signal
import subprocess
import sys


def limited(fsize=None, address_space=None, ignore_sigxfsz=True):
    """A preexec_fn: the limits for the child only (SIGXFSZ ignored: inherited across exec)."""
    def apply():
        if ignore_sigxfsz:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        if fsize is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (fsize, resource.RLIM_INFINITY))
        if address_space is not None:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, resource.RLIM_INFINITY))
    return apply


def run(cmd, code, stdout=subprocess.PIPE, **kw):
    done = subprocess.run(cmd, stdout=stdout, stderr=subprocess.PIPE, text=True, **kw)
    print("$", " ".join(cmd), "->", done.returncode, "\n" + done.stderr.strip()[-1500:])
    assert done.returncode == code, f"exit {done.returncode}, expected {code}"
    return done


def snapshot(directory):
    files = {}
    for root, _, names in os.walk(directory):
        for n in names:
            p = os.path.join(root, n)
            with open(p, "rb") as f:
                files[os.path.relpath(p, directory)] = f.read()
    return files


def same_files(directory, before):
    after = snapshot(directory)
    assert after == before, (sorted(before), sorted(after),
                             [k for k in before if before[k] != after.get(k)])
    assert not any(k.endswith(".tmp") for k in after), sorted(after)


def cards_full_disk(bin_dir, source, work):
    """pointdriver cards --out DIR at a 512-byte file-size limit: both card files stay as the
    first run wrote them (the .k is about 1 kB)."""
    out = os.path.join(work, "cards")
    material = os.path.join(source, "data", "materials", "al6061_t6.json")
    cmd = [os.path.join(bin_dir, "pointdriver"), "cards", material, "--out", out]
    run(cmd, 0)
    before = snapshot(out)
    assert sorted(before) == ["al6061_t6.inp", "al6061_t6.k"] and all(before.values())
    done = run(cmd + ["--set", '{"density": 2710}'], 3, preexec_fn=limited(fsize=512))
    assert "cannot write " + os.path.join(out, "al6061_t6.") in done.stderr, done.stderr
    assert "(File too large)" in done.stderr, done.stderr
    assert "wrote" not in done.stdout, done.stdout
    same_files(out, before)


def fit_full_disk(bin_dir, source, work):
    """pointdriver fit at a 1 kB file-size limit: fit_report.json (about 7 kB) fails; the fitted
    material and the report of the first run stay. One data series, 20 steps: 0.5 s a fit."""
    out = os.path.join(work, "fit")
    config = os.path.join(source, "data", "fits", "al6061_t6_room_temperature.json")
    quick = ('{"data": [{"glob": "data/experiments/al6061_t6/cad_298K_*.csv"}], '
             '"driver": {"steps": 20}}')
    cmd = [os.path.join(bin_dir, "pointdriver"), "fit", config, "--out", out, "--no-figures",
           "--quiet", "--set", quick]
    run(cmd, 0, cwd=source)
    before = snapshot(out)
    assert "fit_report.json" in before and len(before) == 2, sorted(before)
    done = run(cmd, 3, cwd=source, preexec_fn=limited(fsize=1024))
    assert "pointdriver fit: cannot write " + os.path.join(out, "fit_report.json") in done.stderr
    same_files(out, before)


def stdout_full(bin_dir, source, work):
    """What goes to stdout, sent to /dev/full: exit 3 with the reason, not 0."""
    material = os.path.join(source, "data", "materials", "al6061_t6.json")
    scene = os.path.join(source, "data", "scenes", "verification", "rigid_translation.json")
    with open("/dev/full", "w") as full:
        for cmd in ([os.path.join(bin_dir, "material_check"), material],
                    [os.path.join(bin_dir, "pointdriver"), "cards", material],
                    [os.path.join(bin_dir, "mpm"), "check", scene, "--threads", "1"]):
            done = run(cmd, 3, stdout=full)
            assert "cannot write the standard output (No space left on device)" in done.stderr
        # One line under verify's own name: the figure script's "wrote" lines failed first, as
        # "pointdriver plot: cannot write the standard output" (the second trial of issue 52).
        done = run([os.path.join(bin_dir, "pointdriver"), "verify", "--out",
                    os.path.join(work, "verify_full")], 3, stdout=full)
        lines = done.stderr.strip().splitlines()
        assert lines == ["pointdriver verify: cannot write the standard output"] or (
            len(lines) == 1 and lines[0].startswith("pointdriver verify: cannot write the "
                                                    "standard output")), lines


def path_with(source, work, steps, checks=False):
    """The shipped uniaxial-stress path with `steps` steps (and a check reading the CSV back)."""
    with open(os.path.join(source, "data", "paths", "uniaxial_stress_1000.json")) as f:
        path = json.load(f)
    path["material"] = os.path.join(source, "data", "materials", "al6061_t6.json")
    path["legs"][0]["steps"] = steps
    if checks:
        path["checks"] = [{"column": "von_mises [Pa]", "value": 3e8, "rtol": 1.0}]
    name = os.path.join(work, f"path_{steps}{'_checked' if checks else ''}.json")
    with open(name, "w") as f:
        json.dump(path, f)
    return name


def run_refused_for_the_csv(bin_dir, source, work):
    """pointdriver run with 1e5 steps (a CSV of about 44 MB) at a 10 MB file-size limit, and 1e9
    steps (about 440 GB) at 100 GB: refused at once (exit 4) with the estimate; the previous CSV
    stays, nothing else is written."""
    out = os.path.join(work, "run")
    os.makedirs(out)
    csv = os.path.join(out, "p.csv")
    exe = os.path.join(bin_dir, "pointdriver")
    run([exe, "run", path_with(source, work, 100), "-o", csv], 0)
    before = snapshot(out)
    # Expected: the header line as written plus 100 001 rows of 440 B, to 4 digits.
    header = before["p.csv"].split(b"\n", 1)[0] + b"\n"
    expected = f"{(len(header) + 100001 * 440) / 1e6:.4g}"
    done = run([exe, "run", path_with(source, work, 100000), "-o", csv], 4,
               preexec_fn=limited(fsize=10_000_000), timeout=60)
    assert (f"refusing to start: the CSV would take an estimated {expected} MB" in done.stderr
            and "1e+05 rows of about 440 B" in done.stderr
            and csv + " may take only 10 MB" in done.stderr), done.stderr
    done = run([exe, "run", path_with(source, work, 1000000000), "-o", csv], 4,
               preexec_fn=limited(fsize=100_000_000_000), timeout=60)
    assert "the CSV would take an estimated 4.4e+05 MB (1e+09 rows" in done.stderr, done.stderr
    same_files(out, before)
    # Into a directory still to be made: the free space of its nearest existing ancestor, and a
    # refused run leaves no directory behind (it made it, before).
    new = os.path.join(work, "new", "deeper")
    done = run([exe, "run", path_with(source, work, 1000000000), "-o", os.path.join(new, "p.csv")],
               4, preexec_fn=limited(fsize=100_000_000_000), timeout=60)
    assert "the CSV would take an estimated 4.4e+05 MB (1e+09 rows" in done.stderr, done.stderr
    assert not os.path.exists(os.path.join(work, "new")), os.listdir(work)


def run_refused_for_memory(bin_dir, source, work):
    """pointdriver run with 1e7 steps and a check (which reads 2 columns of the CSV back: about
    320 MB) under a 200 MB address-space limit (ulimit -v): refused (exit 4) naming the memory."""
    out = os.path.join(work, "memory")
    os.makedirs(out)
    done = run([os.path.join(bin_dir, "pointdriver"), "run",
                path_with(source, work, 10000000, checks=True), "-o", os.path.join(out, "p.csv")],
               4, preexec_fn=limited(address_space=200_000_000), timeout=60)
    assert ("the run would hold an estimated 336 MB (program 16 MB + the checks reading back 2 "
            "columns of 1e+07 rows" in done.stderr), done.stderr
    assert os.listdir(out) == [], os.listdir(out)


def file_size_limit_as_a_shell_sets_it(bin_dir, source, work):
    """`ulimit -f` in a shell leaves SIGXFSZ at its default, which kills a program whose write
    passes the limit (exit 153, no word, a .tmp left). The programs ignore it themselves, so the
    write fails with EFBIG and is reported: exit 3 naming the file, no .tmp."""
    out = os.path.join(work, "cards")
    material = os.path.join(source, "data", "materials", "al6061_t6.json")
    done = run([os.path.join(bin_dir, "pointdriver"), "cards", material, "--out", out], 3,
               preexec_fn=limited(fsize=512, ignore_sigxfsz=False))
    assert "cannot write " + os.path.join(out, "al6061_t6.") in done.stderr, done.stderr
    assert not [f for f in os.listdir(out) if f.endswith(".tmp")], os.listdir(out)
    scene = os.path.join(source, "data", "scenes", "verification", "rigid_translation.json")
    run_dir = os.path.join(work, "mpm")
    done = run([os.path.join(bin_dir, "mpm"), "run", scene, "--out", run_dir, "--threads", "1"], 3,
               preexec_fn=limited(fsize=512, ignore_sigxfsz=False))
    assert "(File too large)" in done.stderr, done.stderr


def replay_of_a_failed_run_goes_with_the_next_success(bin_dir, source, work):
    """pointdriver run that fails leaves OUT.replay.json; a run into the same OUT that completes
    removes it (else the replay beside complete rows says the last run failed)."""
    path = os.path.join(source, "data", "paths", "uniaxial_stress_1000.json")
    out = os.path.join(work, "p.csv")
    leg = {"velocity_gradient": {"xx": 1000}, "stress": {"yy": 0, "zz": 0}}
    cmd = [os.path.join(bin_dir, "pointdriver"), "run", path, "-o", out, "--set"]
    failing = json.dumps({"legs": [dict(leg, duration=1, steps=2)]})  # strain 500 in 2 steps
    run(cmd + [failing], 3)
    assert os.path.isfile(os.path.join(work, "p.replay.json")), os.listdir(work)
    run(cmd + [json.dumps({"legs": [dict(leg, duration=1e-5, steps=10)]})], 0)
    assert not os.path.exists(os.path.join(work, "p.replay.json")), os.listdir(work)


def scene_in_the_output_directory(bin_dir, source, work):
    """mpm run DIR/scene.json --out DIR (or with output.directory DIR): the run would replace the
    user's scene with the resolved one (it did). Refused (exit 2), the scene byte for byte."""
    base = os.path.join(source, "data", "scenes", "verification", "rigid_translation.json")
    out = os.path.join(work, "run")
    os.makedirs(out)
    scene = os.path.join(out, "scene.json")
    text = json.dumps({"extends": base, "time": {"max_time": 1e-6}}) + "\n"
    with open(scene, "w") as f:
        f.write(text)
    mpm = os.path.join(bin_dir, "mpm")
    done = run([mpm, "run", scene, "--out", out, "--threads", "1"], 2)
    assert (f"{scene}: is {scene}, which the run replaces with the resolved scene (--out {out}): "
            "give the scene another name or the run another directory") in done.stderr, done.stderr
    text_in = {"extends": base, "time": {"max_time": 1e-6}, "output": {"directory": out}}
    with open(scene, "w") as f:
        f.write(json.dumps(text_in))
    done = run([mpm, "run", scene, "--threads", "1"], 2)
    assert f"(/output/directory {out})" in done.stderr, done.stderr
    with open(scene) as f:
        assert json.load(f) == text_in
    assert sorted(os.listdir(out)) == ["scene.json"], os.listdir(out)
    # Another directory is fine.
    run([mpm, "run", scene, "--out", os.path.join(work, "elsewhere"), "--threads", "1"], 0)


CASES = {f.__name__: f for f in (cards_full_disk, fit_full_disk, stdout_full,
                                 replay_of_a_failed_run_goes_with_the_next_success,
                                 file_size_limit_as_a_shell_sets_it,
                                 run_refused_for_the_csv, run_refused_for_memory,
                                 scene_in_the_output_directory)}

if __name__ == "__main__":
    bin_dir, source, work, case = sys.argv[1:5]
    work = os.path.join(work, case)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    CASES[case](bin_dir, source, work)
    print("OK:", case)
