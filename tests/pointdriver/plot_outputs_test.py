#!/usr/bin/env python3
"""`pointdriver plot` writes its figure whole or not at all, under the name it prints, and ends
with one line and a documented exit code when it cannot (docs/pointdriver.md,
docs/reliability.md "Outputs").

  plot_outputs_test.py POINTDRIVER WORK_DIR CASE

On a small CSV written here (stress [Pa] against strain [-]):
  name_without_suffix  -o DIR/fig: exit 1, one line naming it and the suffixes; neither DIR/fig
                       nor DIR/fig.png is made (fig.png was written and "wrote DIR/fig" printed,
                       exit 0, before)
  full_device          -o DIR/full.png, a link to /dev/full: exit 3 and exactly the line
                       "pointdriver plot: cannot write DIR/full.png: No space left on device"
                       (exit 0 and "wrote", before)
  file_size_limit      a figure drawn, then again under a 4 KiB file-size limit: exit 3, one line
                       with "File too large"; the previous figure byte for byte, no .tmp (two
                       lines, exit 1, before)
  stdout_full          stdout on /dev/full: exit 3, exactly "pointdriver plot: cannot write the
                       standard output (No space left on device)", the figure written
  stdout_closed        stdout a pipe whose reader has gone: exit 141, nothing on stderr (a
                       traceback, before)
Without matplotlib: exit 77 (CTest: skipped).
"""
import os
import resource
import shutil
import subprocess
import sys


def plot(exe, csv, figure, code, **kw):
    done = subprocess.run([exe, "plot", csv, "--x", "strain", "--y", "stress", "-o", figure],
                          stderr=subprocess.PIPE, text=True, **kw)
    assert done.returncode == code, (f"pointdriver plot -o {figure} exited {done.returncode}, "
                                     f"expected {code}\n{done.stderr}")
    return done


def one_line(stderr):
    assert stderr.count("\n") == 1 and "Traceback" not in stderr, repr(stderr)
    return stderr.rstrip("\n")


def main(exe, work, case):
    work = os.path.join(work, case)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    python = os.environ.get("IMPACT_PYTHON") or "/usr/bin/python3"
    if subprocess.run([python, "-c", "import matplotlib"], capture_output=True).returncode != 0:
        print("no matplotlib: pointdriver plot cannot draw; skipped")
        sys.exit(77)
    csv = os.path.join(work, "run.csv")
    with open(csv, "w") as f:
        f.write("strain [-],stress [Pa]\n")
        for k in range(50):
            f.write(f"{k * 1e-3},{3e8 * (1 - 0.98 ** k)}\n")
    out = subprocess.PIPE
    if case == "name_without_suffix":
        figure = os.path.join(work, "fig")
        done = plot(exe, csv, figure, 1, stdout=out)
        assert one_line(done.stderr) == (f"pointdriver plot: {figure}: expected a figure name "
                                         "ending in .png, .pdf, .svg"), done.stderr
        assert sorted(os.listdir(work)) == ["run.csv"], os.listdir(work)
    elif case == "full_device":
        figure = os.path.join(work, "full.png")
        os.symlink("/dev/full", figure)
        done = plot(exe, csv, figure, 3, stdout=out)
        assert one_line(done.stderr) == (f"pointdriver plot: cannot write {figure}: No space "
                                         "left on device"), done.stderr
        assert "wrote" not in done.stdout, done.stdout
        assert sorted(os.listdir(work)) == ["full.png", "run.csv"], os.listdir(work)
    elif case == "file_size_limit":
        figure = os.path.join(work, "fig.png")
        plot(exe, csv, figure, 0, stdout=out)
        with open(figure, "rb") as f:
            before = f.read()
        limit = (4096, resource.RLIM_INFINITY)
        done = plot(exe, csv, figure, 3, stdout=out,
                    preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_FSIZE, limit))
        assert one_line(done.stderr) == f"pointdriver plot: cannot write {figure}: File too large"
        with open(figure, "rb") as f:
            assert f.read() == before, "the previous figure changed"
        assert sorted(os.listdir(work)) == ["fig.png", "run.csv"], os.listdir(work)
    elif case == "stdout_full":
        figure = os.path.join(work, "fig.png")
        with open("/dev/full", "w") as full:
            done = plot(exe, csv, figure, 3, stdout=full)
        assert one_line(done.stderr) == ("pointdriver plot: cannot write the standard output "
                                         "(No space left on device)"), done.stderr
        assert os.path.getsize(figure) > 10000
    elif case == "stdout_closed":
        figure = os.path.join(work, "fig.png")
        read_end, write_end = os.pipe()
        os.close(read_end)
        done = plot(exe, csv, figure, 141, stdout=write_end)
        os.close(write_end)
        assert done.stderr == "", done.stderr
        assert os.path.getsize(figure) > 10000
    else:
        sys.exit(f"unknown case {case}")
    print("OK:", case)


if __name__ == "__main__":
    main(*sys.argv[1:4])
