#!/usr/bin/env python3
"""`pointdriver run` into a place where no file can be made says why (the system's reason), not
that the CSV is too large: a read-only file system reports its free space as what is left of it
(0 on /sys, little on a small tmpfs), which the size estimate took for a full disk (exit 4,
"refusing to start: the CSV would take an estimated 0.8814 MB ... may take only 0 MB", before).

  run_output_place_test.py POINTDRIVER SOURCE_DIR WORK_DIR CASE

The shipped uniaxial-stress path (2000 steps, a CSV of about 0.88 MB), then:
  sysfs                  -o /sys/p.csv (free space 0, no file can be made there, by root
                         either): exit 3 and one line "pointdriver run: cannot write /sys/p.csv:
                         cannot open /sys/p.csv.tmp (REASON)"
  read_only_file_system  -o DIR/p.csv on a 64 KiB tmpfs mounted read-only in a mount namespace
                         of its own (`unshare -m` as root, `unshare -rm` as a user): exit 3 and
                         "(Read-only file system)"; skipped (77) where no namespace can be made
"""
import os
import shutil
import subprocess
import sys


def one_line(stderr):
    assert stderr.count("\n") == 1, repr(stderr)
    return stderr.rstrip("\n")


def main(exe, source, work, case):
    work = os.path.join(work, case)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    path = os.path.join(source, "data", "paths", "uniaxial_stress_1000.json")
    if case == "sysfs":
        done = subprocess.run([exe, "run", path, "-o", "/sys/p.csv"], capture_output=True,
                              text=True)
        print(done.stderr)
        assert done.returncode == 3, f"exit {done.returncode}, expected 3"
        line = one_line(done.stderr)
        assert line.startswith("pointdriver run: cannot write /sys/p.csv: cannot open "
                               "/sys/p.csv.tmp (") and line.endswith(")"), line
    elif case == "read_only_file_system":
        mount_point = os.path.join(work, "read_only")
        os.makedirs(mount_point)
        unshare = ["unshare", "-m"] if os.geteuid() == 0 else ["unshare", "-rm"]
        probe = subprocess.run(unshare + ["sh", "-c", 'mount -t tmpfs -o ro,size=64k none "$1"',
                                          "sh", mount_point], capture_output=True, text=True)
        if probe.returncode != 0:
            print(f"no private read-only mount here ({probe.stderr.strip()}): skipped")
            sys.exit(77)
        csv = os.path.join(mount_point, "p.csv")
        done = subprocess.run(unshare + ["sh", "-c", 'mount -t tmpfs -o ro,size=64k none "$1" '
                                         '&& shift && exec "$@"', "sh", mount_point,
                                         exe, "run", path, "-o", csv],
                              capture_output=True, text=True)
        print(done.stderr)
        assert done.returncode == 3, f"exit {done.returncode}, expected 3"
        assert one_line(done.stderr) == (f"pointdriver run: cannot write {csv}: cannot open "
                                         f"{csv}.tmp (Read-only file system)"), done.stderr
        assert os.listdir(mount_point) == [], os.listdir(mount_point)  # the real directory
    else:
        sys.exit(f"unknown case {case}")
    print("OK:", case)


if __name__ == "__main__":
    main(*sys.argv[1:5])
