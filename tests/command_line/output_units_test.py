#!/usr/bin/env python3
"""Every number a program writes names its unit (issue 52, item 8 and the second trial): a CSV
column carries "[unit]" in its header, a JSON number carries it in its key or in the document's
"units" block; a quantity that does not exist is empty (CSV) or null (JSON), not a -1 sentinel.

- pointdriver batch: batch_summary.csv, a path that does not fail: its failure time is empty;
- pointdriver run: summary.json's failure_time [s] is null for the same path;
- pointdriver verify --case elastic_uniaxial: verification.csv's numeric columns have units;
- mpm check: every number of "report" without a unit in its key is in report["units"];
- mpm run: every top-level number of summary.json without a unit in its key is in "units".

  output_units_test.py BIN_DIR SOURCE_DIR WORK_DIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys

# Columns that hold names or text, not numbers.
TEXT_COLUMNS = {"path", "material", "failure cause", "error", "case", "quantity", "pass"}


def run(cmd, cwd):
    done = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd, timeout=600)
    assert done.returncode == 0, (cmd, done.returncode, done.stderr[-2000:])
    return done.stdout


def unitless_columns(header):
    return [c for c in header if "[" not in c and c not in TEXT_COLUMNS]


def unitless_numbers(document, units):
    return sorted(k for k, v in document.items()
                  if isinstance(v, (int, float)) and not isinstance(v, bool) and "[" not in k
                  and k not in units)


def main(bin_dir, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    pointdriver, mpm = os.path.join(bin_dir, "pointdriver"), os.path.join(bin_dir, "mpm")
    path = os.path.join(source, "data", "paths", "uniaxial_stress_1000.json")
    failures = []

    run([pointdriver, "batch", "--paths", path, "--out", "batch", "--no-csv"], work)
    with open(os.path.join(work, "batch", "batch_summary.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if unitless_columns(rows[0]):
        failures.append(f"batch_summary.csv: columns without a unit {unitless_columns(rows[0])}")
    if rows[0]["failure cause"] != "none" or rows[0]["failure time [s]"] != "":
        failures.append(f"batch_summary.csv: a run that did not fail has failure cause "
                        f"{rows[0]['failure cause']!r}, failure time {rows[0]['failure time [s]']!r}"
                        " (want none and an empty cell)")

    run([pointdriver, "run", path, "-o", "run/uniaxial.csv"], work)
    with open(os.path.join(work, "run", "uniaxial.summary.json")) as f:
        summary = json.load(f)
    missing = unitless_numbers(summary, summary.get("units", {}))
    if missing:
        failures.append(f"pointdriver run summary.json: numbers without a unit {missing}")
    if summary["failure_time [s]"] is not None:
        failures.append(f"pointdriver run summary.json: failure_time [s] = "
                        f"{summary['failure_time [s]']} for a run that did not fail (want null)")

    run([pointdriver, "verify", "--case", "elastic_uniaxial", "--out", "verify"], work)
    with open(os.path.join(work, "verify", "verification.csv"), newline="") as f:
        header = next(csv.reader(f))
    if unitless_columns(header):
        failures.append(f"verification.csv: columns without a unit {unitless_columns(header)}")

    scene = os.path.join(source, "data", "scenes", "verification", "rigid_translation.json")
    report = json.loads(run([mpm, "check", scene], work))["report"]
    missing = unitless_numbers(report, report.get("units", {}))
    if missing:
        failures.append(f"mpm check report: numbers without a unit {missing}")

    run([mpm, "run", scene, "--out", "mpm_run", "--threads", "1"], work)
    with open(os.path.join(work, "mpm_run", "summary.json")) as f:
        summary = json.load(f)
    missing = unitless_numbers(summary, summary.get("units", {}))
    if missing:
        failures.append(f"mpm run summary.json: numbers without a unit {missing}")
    for name, obj in summary["objects"].items():
        missing = unitless_numbers(obj, summary["units"])
        if missing:
            failures.append(f"mpm run summary.json objects/{name}: numbers without a unit {missing}")

    for f in failures:
        print("FAIL:", f)
    if failures:
        sys.exit(1)
    print("OK: batch, run, verify, mpm check and mpm run name the unit of every number")


if __name__ == "__main__":
    main(*sys.argv[1:4])
