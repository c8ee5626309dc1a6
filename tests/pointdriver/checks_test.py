#!/usr/bin/env python3
"""Regression checks in path files and JUnit output (docs/pointdriver.md, "Checks").

  checks_test.py POINTDRIVER WORK_DIR

- tests/data/checks/elastic_uniaxial_stress.json: three checks against closed forms (sigma_xx =
  E eps at the end and halfway, sigma_yy = 0) pass: exit 0, JUnit with 3 cases and 0 failures.
- The same path with a wrong expected value (--set): exit 3, one JUnit failure whose message
  names the expected value.
- A reference CSV: the run against its own earlier output passes to 1e-12; with the strain rate
  raised by 1 % (so sigma_xx differs by 1 %) it fails: exit 3.
- Bad checks (both "value" and "reference"; a missing reference file) exit 2 naming /checks/0.
- `pointdriver verify --case ... --junit` and `pointdriver check ... --junit` write one case per
  check / curve, failures where the command reports them.
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
PATH = os.path.join(ROOT, "tests", "data", "checks", "elastic_uniaxial_stress.json")


def run(cmd, code):
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != code:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {done.returncode}, expected {code}\n"
                 f"{done.stdout}\n{done.stderr}")
    return done


def junit(file):
    suite = ET.parse(file).getroot().find("testsuite")
    cases = suite.findall("testcase")
    failed = [c for c in cases if c.find("failure") is not None]
    return suite, cases, failed


def main(pointdriver, work):
    os.makedirs(work, exist_ok=True)
    out, xml = os.path.join(work, "elastic.csv"), os.path.join(work, "elastic.xml")
    run([pointdriver, "run", PATH, "-o", out, "--junit", xml], 0)
    suite, cases, failed = junit(xml)
    assert len(cases) == 3 and not failed and suite.get("failures") == "0", (len(cases), failed)

    wrong = json.dumps({"checks": [{"name": "wrong", "column": "stress_xx [Pa]", "value": 1.5e8,
                                    "rtol": 1e-9}]})
    done = run([pointdriver, "run", PATH, "-o", os.path.join(work, "wrong.csv"), "--set", wrong,
                "--junit", xml], 3)
    assert "CHECK FAILED: wrong" in done.stdout, done.stdout
    _, cases, failed = junit(xml)
    assert len(cases) == 1 and len(failed) == 1, (cases, failed)
    assert "expected 150000000" in failed[0].find("failure").get("message")

    reference = json.dumps({"checks": [{"column": "stress_xx [Pa]", "reference": out,
                                        "rtol": 1e-12}]})
    run([pointdriver, "run", PATH, "-o", os.path.join(work, "same.csv"), "--set", reference], 0)
    faster = json.loads(reference)
    faster["legs"] = [{"duration": 2e-6, "steps": 20, "velocity_gradient": {"xx": 1010.0},
                       "stress": {"yy": 0.0, "zz": 0.0}}]
    done = run([pointdriver, "run", PATH, "-o", os.path.join(work, "faster.csv"), "--set",
                json.dumps(faster)], 3)
    assert "CHECK FAILED" in done.stdout and "worst at t = 2e-06 s" in done.stdout, done.stdout

    both = json.dumps({"checks": [{"column": "stress_xx [Pa]", "value": 1.0,
                                   "reference": out}]})
    done = run([pointdriver, "run", PATH, "-o", os.path.join(work, "bad.csv"), "--set", both], 2)
    assert "/checks/0" in done.stderr and "exactly one of" in done.stderr, done.stderr
    missing = json.dumps({"checks": [{"column": "stress_xx [Pa]", "reference": "nowhere.csv"}]})
    done = run([pointdriver, "run", PATH, "-o", os.path.join(work, "bad.csv"), "--set", missing],
               2)
    assert "/checks/0/reference" in done.stderr, done.stderr

    xml = os.path.join(work, "verify.xml")
    run([pointdriver, "verify", "--case", "elastic_uniaxial", "--out",
         os.path.join(work, "verify"), "--junit", xml], 0)
    suite, cases, failed = junit(xml)
    assert len(cases) >= 1 and not failed, (len(cases), failed)

    xml = os.path.join(work, "check.xml")
    run([pointdriver, "check", os.path.join(ROOT, "data/fits/al6061_t6_check_high_rate.json"),
         "--out", os.path.join(work, "check"), "--no-figures", "--junit", xml], 3)
    _, cases, failed = junit(xml)
    names = [c.get("name") for c in failed]
    assert "lee_298K_4000per_s" in names, names
    assert len(cases) > len(failed), (len(cases), len(failed))
    print(f"OK: check wrote {len(cases)} cases, {len(failed)} failed: {names}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
