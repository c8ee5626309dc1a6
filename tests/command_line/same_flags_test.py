#!/usr/bin/env python3
"""Every program and command accepts the same flags (support/command_line.hpp): --version and
--help exit 0 (3 when stdout cannot be written: > /dev/full), a command's --help ends with its
own exit codes, an unknown option is a usage error (1), --out=DIR works as --out DIR, --quiet
leaves stdout empty (also that of a Python child drawing figures), a malformed --set (also one that is no JSON object, '[1]', and a truncated
one holding 1e999) is a usage error wherever a JSON file is read, and a --set number no double
holds (-1e400) is an input error (2) naming the patch and the key.

  same_flags_test.py BIN_DIR SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys


def main(bin_dir, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    data = os.path.join(source, "data")
    material = os.path.join(data, "materials", "al6061_t6.json")
    path = os.path.join(data, "paths", "uniaxial_stress_1000.json")
    check = os.path.join(data, "fits", "al6061_t6_check_quasi_static.json")
    scene = os.path.join(data, "scenes", "verification", "rigid_translation.json")
    short = '{"time": {"max_time": 1e-6}, "output": {"snapshots": false}}'
    # (name, command words, valid arguments with {out} for the output, takes --set)
    commands = [
        ("material_check", ["material_check"], [material], False, True),
        ("material_keys", ["material_check"], ["--keys", "--format", "json"], False, False),
        ("run", ["pointdriver", "run"], [path, "--out={out}.csv"], True, True),
        ("verify", ["pointdriver", "verify"], ["--case", "elastic_uniaxial", "--out={out}"],
         True, False),
        ("batch", ["pointdriver", "batch"], ["--paths", path, "--out={out}", "--no-csv"], True,
         True),
        ("check", ["pointdriver", "check"], [check, "--out={out}", "--no-figures"], True, True),
        ("cards", ["pointdriver", "cards"], [material, "--out={out}"], True, True),
        ("mpm_check", ["mpm", "check"], [scene, "--set", short], False, True),
        ("mpm_run", ["mpm", "run"], [scene, "--out={out}", "--threads", "1", "--set", short],
         True, True),
        ("mpm_keys", ["mpm", "keys"], ["--format", "json"], False, False),
        # Commands that draw through a Python child: its stdout is silenced too (it printed
        # "wrote ..." under --quiet before).
        ("mpm_plot", ["mpm", "plot"], [os.path.join(work, "mpm_run"), "--out={out}.png"], False,
         False),
        ("plot", ["pointdriver", "plot"],
         [os.path.join(work, "run.csv"), "--x", "time", "--y", "stress_xx", "--out={out}.png"],
         False, False),
        ("check_figures", ["pointdriver", "check"], [check, "--out={out}"], True, True),
    ]
    failures = []

    def run(words, args):
        exe = os.path.join(bin_dir, words[0])
        return subprocess.run([exe] + words[1:] + args, capture_output=True, text=True, cwd=work,
                              timeout=120)

    def malformed_set(name, words, args):
        """A --set that is no merge patch: a usage error (1), before anything is read."""
        found = []
        for patch, expected in (("{bad", "--set: invalid JSON"),
                                ('{"a": 1e999', "--set: invalid JSON"),  # exit 2 before
                                ("[1]", "--set: expected a JSON object, a merge patch such as "
                                        "'{\"key\": value}', got array [1]")):
            r = run(words, args + ["--set", patch])
            if r.returncode != 1 or expected not in r.stderr:
                found.append(f"{name}: --set {patch} exit {r.returncode}: {r.stderr[-200:]!r}")
        return found

    def help_to_a_full_stdout(name, words):
        """--help > /dev/full: exit 3 with the reason (exit 0 before)."""
        with open("/dev/full", "w") as full:
            exe = os.path.join(bin_dir, words[0])
            r = subprocess.run([exe] + words[1:] + ["--help"], stdout=full, stderr=subprocess.PIPE,
                               text=True, timeout=60)
        if r.returncode != 3 or "cannot write the standard output" not in r.stderr:
            return [f"{name}: --help > /dev/full exit {r.returncode}: {r.stderr[-200:]!r}"]
        return []

    def number_beyond_double(name, words, args):
        """A --set number no double holds: exit 2 naming the patch and the key (SIGABRT before)."""
        r = run(words, args + ["--set", '{"a": 1}', "--set", '{"x": [0, -1e400]}'])
        patch = args.count("--set") + 2
        expected = (f"--set patch {patch}: /x/1: the number -1e400 is beyond the range of a "
                    "double (magnitude at most 1.8e308)")
        if r.returncode != 2 or expected not in r.stderr:
            return [f"{name}: --set 1e400 exit {r.returncode}: {r.stderr[-200:]!r}"]
        return []

    for name, words, valid, writes, takes_set in commands:
        out = os.path.join(work, name)
        args = [a.replace("{out}", out) for a in valid]
        program = words[0]
        r = run(words, ["--version"])
        if r.returncode != 0 or not r.stdout.startswith(program):
            failures.append(f"{name}: --version exit {r.returncode}, stdout {r.stdout!r}")
        r = run(words, ["--help"])
        if r.returncode != 0 or "--quiet" not in r.stdout or "--version" not in r.stdout:
            failures.append(f"{name}: --help exit {r.returncode} or lacks --quiet/--version")
        # The command's own footer: one list of exit codes, not the whole program's text (every
        # mpm command printed what `run` writes and what `plot` and `keys` do).
        if r.stdout.count("Exit codes:") != 1 or (name not in ("mpm_run", "run")
                                                   and "history.csv" in r.stdout):
            failures.append(f"{name}: --help footer is not the command's: {r.stdout[-400:]!r}")
        failures += help_to_a_full_stdout(name, words)
        r = run(words, args + ["--no-such-flag"])
        if r.returncode != 1 or "--no-such-flag" not in r.stderr:
            failures.append(f"{name}: unknown option exit {r.returncode}: {r.stderr[-200:]!r}")
        if takes_set:
            failures += malformed_set(name, words, args)
            failures += number_beyond_double(name, words, args)
        r = run(words, args + ["--quiet"])
        if r.returncode != 0 or r.stdout != "":
            failures.append(f"{name}: --quiet exit {r.returncode}, stdout {r.stdout[:200]!r}")
        if writes and not os.path.exists(out if not name == "run" else out + ".csv"):
            failures.append(f"{name}: --out={out} wrote nothing there")
    # Commands above that are slow to run when valid: only the --set check.
    config = os.path.join(data, "fits", "al6061_t6_room_temperature.json")
    for name, words, args in [
            ("fit", ["pointdriver", "fit"], [config, "--out", os.path.join(work, "fit")]),
            ("convergence", ["pointdriver", "convergence"],
             ["--quick", "--no-plots", "--out", os.path.join(work, "convergence")]),
            ("mpm_study", ["mpm", "study"],
             [os.path.join(data, "scenes", "sphere_cylinder"), "--out",
              os.path.join(work, "study")])]:
        failures += number_beyond_double(name, words, args)
        failures += malformed_set(name, words, args)
    # A repeatable option takes one value per occurrence (--y a --y b): its help says `--y COL`;
    # `COL ...` promised `--y a b`, which read b as a file (issue 52's trial).
    r = run(["pointdriver", "plot"], ["--help"])
    if "--y COL ..." in r.stdout or "--set JSON ..." in r.stdout or "--y COL " not in r.stdout:
        failures.append(f"pointdriver plot --help: repeatable options shown as lists: "
                        f"{[line for line in r.stdout.splitlines() if '--y' in line]}")
    for words in (["material_check"], ["pointdriver"], ["mpm"]):  # the programs' own --help
        failures += help_to_a_full_stdout(words[0], words)
    if failures:
        sys.exit("FAIL:\n" + "\n".join(failures))
    print(f"OK: {len(commands)} commands take --version, --help, --quiet, --out=DIR, --set")


if __name__ == "__main__":
    main(*sys.argv[1:4])
