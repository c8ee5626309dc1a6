#!/usr/bin/env python3
"""`pointdriver run` (and `batch`, SIGINT) interrupted by Ctrl-C (SIGINT) or SIGTERM mid-run: one line naming the
signal, exit 128 + the signal (130, 143), no OUT.csv.tmp left behind and the previous OUT.csv
untouched (issue 52's trial: a 5e7-step run left 210 MB of OUT.csv.tmp in 2 s, without a word).

  interrupted_path_test.py POINTDRIVER SOURCE_DIR WORK_DIR"""
import os
import shutil
import signal
import subprocess
import sys
import time

# One leg of 5e6 steps (2.2 GB of CSV were it run, about 10 s): it is still running when the
# signal comes, and its estimate fits the free space of a small disk (5e7 steps, 22 GB, was
# refused before it started on a disk with 11 GB free, and the test failed for the disk).
LONG = ('{"legs": [{"duration": 2e-4, "steps": 5000000, "velocity_gradient": {"xx": 1000}, '
        '"stress": {"yy": 0, "zz": 0}}]}')


def main(pointdriver, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    path = os.path.join(source, "data", "paths", "uniaxial_stress_1000.json")
    out = os.path.join(work, "p.csv")
    with open(out, "w") as f:
        f.write("previous\n")
    failures = []
    for sig, code, name in ((signal.SIGINT, 130, "SIGINT"), (signal.SIGTERM, 143, "SIGTERM")):
        p = subprocess.Popen([pointdriver, "run", path, "-o", out, "--set", LONG],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 60
        # Rows are being written once the temporary has grown past its header.
        while time.time() < deadline and p.poll() is None:
            if os.path.exists(out + ".tmp") and os.path.getsize(out + ".tmp") > 100000:
                break
            time.sleep(0.05)
        p.send_signal(sig)
        try:
            _, err = p.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            p.kill()
            failures.append(f"{name}: still running 60 s after the signal")
            continue
        want = f"pointdriver run: interrupted by {name} after "
        if p.returncode != code or not err.startswith(want) or err.count("\n") != 1:
            failures.append(f"{name}: exit {p.returncode}, stderr {err!r}; want {code} and "
                            f"one line starting {want!r}")
        if os.path.exists(out + ".tmp"):
            failures.append(f"{name}: {out}.tmp left behind ({os.path.getsize(out + '.tmp')} B)")
        with open(out) as f:
            if f.read() != "previous\n":
                failures.append(f"{name}: the previous {out} was replaced")
    # pointdriver batch the same (the second trial: exit 130 without a word, the run's CSV and
    # batch_summary.csv left as .tmp), with the same leg.
    batch = os.path.join(work, "batch")
    p = subprocess.Popen([pointdriver, "batch", "--paths", path, "--out", batch, "--set",
                          LONG],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 60
    while time.time() < deadline and p.poll() is None:
        tmps = [f for f in os.listdir(batch)] if os.path.isdir(batch) else []
        if any(f.endswith(".csv.tmp") and os.path.getsize(os.path.join(batch, f)) > 100000
               for f in tmps):
            break
        time.sleep(0.05)
    p.send_signal(signal.SIGINT)
    try:
        _, err = p.communicate(timeout=60)
        want = "pointdriver batch: interrupted by SIGINT; no summary written"
        if p.returncode != 130 or not err.startswith(want) or err.count("\n") != 1:
            failures.append(f"batch: exit {p.returncode}, stderr {err!r}; want 130 and one line "
                            f"starting {want!r}")
        left = sorted(os.listdir(batch))
        if left:
            failures.append(f"batch: files left in {batch}: {left} (want none: the interrupted "
                            "run's CSV and the summary discarded)")
    except subprocess.TimeoutExpired:
        p.kill()
        failures.append("batch: still running 60 s after SIGINT")
    if failures:
        sys.exit("FAIL:\n" + "\n".join(failures))
    print("OK: SIGINT and SIGTERM stop pointdriver run with 130 and 143, batch with 130, no "
          "temporary left")


if __name__ == "__main__":
    main(*sys.argv[1:4])
