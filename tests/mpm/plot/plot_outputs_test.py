#!/usr/bin/env python3
"""`mpm plot` writes its figure whole or not at all, under the name it prints, and ends with one
line and a documented exit code when it cannot (docs/mpm.md#mpm-plot-run, docs/reliability.md).

  plot_outputs_test.py MPM SOURCE_DIR WORK_DIR CASE

The shipped rigid translation (2e-5 s, no snapshots) is run once per case, then `mpm plot`:
  name_without_suffix  --out DIR/fig: exit 1, one line naming it and the suffixes; neither
                       DIR/fig nor DIR/fig.png is made (matplotlib wrote fig.png and the script
                       printed "wrote DIR/fig", exit 0, before)
  full_device          --out DIR/full.png, a link to /dev/full: exit 3 and exactly the line
                       "mpm plot: cannot write DIR/full.png: No space left on device" (exit 0
                       and "wrote", before)
  file_size_limit      a figure drawn, then again under a 4 KiB file-size limit (RLIMIT_FSIZE,
                       as `ulimit -f`): exit 3, one line with "File too large"; the previous
                       figure byte for byte, no .tmp
  unwritable_place     --out /proc/x/fig.png: exit 3, one line with the system's reason (exit 2,
                       input error, before)
  stdout_full          stdout on /dev/full: exit 3, exactly "mpm plot: cannot write the standard
                       output (No space left on device)"; the figure is written (a traceback,
                       before)
  stdout_closed        stdout a pipe whose reader has gone (`| head` after head ended): exit
                       141 and nothing on stderr (a traceback, before)
Without matplotlib the figure cannot be drawn: exit 77 (CTest: skipped).
"""
import json
import os
import resource
import shutil
import subprocess
import sys


def plot(mpm, args, code, **kw):
    done = subprocess.run([mpm, "plot"] + args, stderr=subprocess.PIPE, text=True, **kw)
    assert done.returncode == code, (f"mpm plot {' '.join(args)} exited {done.returncode}, "
                                     f"expected {code}\n{done.stderr}")
    return done


def one_line(stderr):
    assert stderr.count("\n") == 1 and "Traceback" not in stderr, repr(stderr)
    return stderr.rstrip("\n")


def file_size_limit(size):
    return lambda: resource.setrlimit(resource.RLIMIT_FSIZE, (size, resource.RLIM_INFINITY))


def main(mpm, source, work, case):
    work = os.path.join(work, case)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    python = os.environ.get("IMPACT_PYTHON") or "/usr/bin/python3"
    if subprocess.run([python, "-c", "import matplotlib"], capture_output=True).returncode != 0:
        print("no matplotlib: mpm plot cannot draw; skipped")
        sys.exit(77)
    scene = os.path.join(source, "data", "scenes", "verification", "rigid_translation.json")
    run = os.path.join(work, "run")
    patch = {"time": {"max_time": 2e-5}, "output": {"snapshots": False}}
    subprocess.run([mpm, "run", scene, "--out", run, "--threads", "1", "--quiet", "--set",
                    json.dumps(patch)], check=True)
    out = subprocess.PIPE

    if case == "name_without_suffix":
        figure = os.path.join(work, "fig")
        done = plot(mpm, [run, "--out", figure], 1, stdout=out)
        assert one_line(done.stderr).endswith(
            f"mpm plot: {figure}: expected a figure name ending in .png, .pdf, .svg"), done.stderr
        assert sorted(os.listdir(work)) == ["run"], os.listdir(work)
        # A directory is named as one (the second trial of issue 52: "expected a figure name").
        done = plot(mpm, [run, "--out", work], 1, stdout=out)
        assert one_line(done.stderr).endswith(
            f"mpm plot: {work}: a directory; expected a figure file name ending in .png, .pdf, "
            f".svg (e.g. {os.path.join(work, 'run.png')})"), done.stderr
    elif case == "full_device":
        figure = os.path.join(work, "full.png")
        os.symlink("/dev/full", figure)
        done = plot(mpm, [run, "--out", figure], 3, stdout=out)
        assert one_line(done.stderr) == (f"mpm plot: cannot write {figure}: No space left on "
                                         "device"), done.stderr
        assert "wrote" not in done.stdout, done.stdout
        assert sorted(os.listdir(work)) == ["full.png", "run"], os.listdir(work)
    elif case == "file_size_limit":
        figure = os.path.join(work, "fig.png")
        plot(mpm, [run, "--out", figure], 0, stdout=out)
        with open(figure, "rb") as f:
            before = f.read()
        done = plot(mpm, [run, "--out", figure], 3, stdout=out, preexec_fn=file_size_limit(4096))
        assert one_line(done.stderr) == f"mpm plot: cannot write {figure}: File too large", \
            done.stderr
        with open(figure, "rb") as f:
            assert f.read() == before, "the previous figure changed"
        assert sorted(os.listdir(work)) == ["fig.png", "run"], os.listdir(work)
    elif case == "unwritable_place":
        done = plot(mpm, [run, "--out", "/proc/x/fig.png"], 3, stdout=out)
        assert one_line(done.stderr).startswith("mpm plot: cannot write /proc/x/fig.png: "), \
            done.stderr
    elif case == "stdout_full":
        with open("/dev/full", "w") as full:
            done = plot(mpm, [run], 3, stdout=full)
        assert one_line(done.stderr) == ("mpm plot: cannot write the standard output (No space "
                                         "left on device)"), done.stderr
        assert os.path.getsize(os.path.join(run, "run.png")) > 10000
    elif case == "stdout_closed":
        read_end, write_end = os.pipe()
        os.close(read_end)
        done = plot(mpm, [run], 141, stdout=write_end)
        os.close(write_end)
        assert done.stderr == "", done.stderr
        assert os.path.getsize(os.path.join(run, "run.png")) > 10000
    else:
        sys.exit(f"unknown case {case}")
    print("OK:", case)


if __name__ == "__main__":
    main(*sys.argv[1:5])
