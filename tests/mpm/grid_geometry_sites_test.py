#!/usr/bin/env python3
"""No run-time site picks a grid geometry by name (issue 54; docs/extending.md "A grid geometry").

  grid_geometry_sites_test.py SOURCE_DIR

A geometry's terms live in its struct in mpm/scene/grid_geometry.hpp. The code outside that file
reads them through the catalogue: a struct member at compile time (GeometryOf<G>, a shape's
OnGrid), facts(g) or the GridSpec accessors that read it, or visit_geometry(g, f). This fails,
naming file:line, on the spellings that branch on one geometry instead:
- an enumerator, GridGeometry::three_d (or any other), one of the header's names for one geometry
  (kAxisymmetric, kPlaneStrain: the tests' shape arguments), or a geometry's struct by name
  (AxisymmetricGrid::kId == g); kDefaultGeometry, the catalogue's first line, is allowed;
- a switch on a geometry, or a geometry cast to an integer (an index into a hand-made table);
- a string literal that is a geometry's name, in mpm/, commands/ and python/bindings/ (the reader
  takes the names from the catalogue).
Scanned: mpm/, commands/, campaigns/ (C++ only; a campaign's "axisymmetric" is a scene's name)
and python/bindings/, with // comments removed. Not scanned: tests/, which name geometries on
purpose. Not forbidden: planar(), dimensions(), is_domain_face(), which read the catalogue. A
determined author can get past a pattern; review does the rest.
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), "..", ".."))
HOME = "mpm/scene/grid_geometry.hpp"
NAMES = ("3d", "axisymmetric", "plane_strain")
RULES = [
    (re.compile(r"\bGridGeometry::\w+"), "names a geometry's enumerator"),
    (re.compile(r"\b(?:kAxisymmetric|kPlaneStrain|ThreeDGrid|AxisymmetricGrid|PlaneStrainGrid)\b"),
     "names one geometry of the catalogue"),
    (re.compile(r"\bswitch\s*\([^)]*geometry\b", re.I), "switches on a geometry"),
    (re.compile(r"\b(?:int|static_cast<int>|std::size_t|static_cast<std::size_t>)\s*\(\s*"
                r"[\w.()]*geometry\s*\)", re.I), "casts a geometry to an index"),
]
NAME_RULE = (re.compile(r'"(?:%s)"' % "|".join(NAMES)), "compares with a geometry's name")
WHERE = ("a member of the geometry's struct (mpm/scene/grid_geometry.hpp), read through "
         "facts(g), GeometryOf<G> or visit_geometry(g, f), or a phase's `if constexpr` on "
         "Shape::kHoop / NZ")


def sources():
    for top, exts, names_too in (("mpm", (".cpp", ".hpp"), True),
                                 ("commands", (".cpp", ".hpp"), True),
                                 ("campaigns", (".cpp", ".hpp"), False),
                                 ("python/bindings", (".cpp", ".hpp"), True)):
        for folder, _, files in os.walk(os.path.join(ROOT, top)):
            for f in sorted(files):
                if f.endswith(exts):
                    path = os.path.join(folder, f)
                    yield os.path.relpath(path, ROOT), names_too


def strip_comment(line):
    # Outside string literals only (a "//" inside a string stays).
    out, quoted, i = [], False, 0
    while i < len(line):
        c = line[i]
        if c == '"' and (i == 0 or line[i - 1] != "\\"):
            quoted = not quoted
        if not quoted and line.startswith("//", i):
            break
        out.append(c)
        i += 1
    return "".join(out)


def main():
    found, scanned = [], 0
    for rel, names_too in sources():
        if rel == HOME:
            continue
        scanned += 1
        with open(os.path.join(ROOT, rel), encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                code = strip_comment(line)
                for rule, what in RULES + ([NAME_RULE] if names_too else []):
                    m = rule.search(code)
                    if m:
                        found.append(f"{rel}:{n}: {what}: {m.group(0)}")
    if scanned < 100:
        print(f"FAIL: only {scanned} files scanned under {ROOT}: wrong source directory?")
        return 1
    if found:
        print("FAIL: run-time sites that pick a grid geometry by name:")
        for f in found:
            print("  " + f)
        print("A geometry's term goes in " + WHERE + ".")
        return 1
    print(f"OK: {scanned} files; no site outside {HOME} names a grid geometry")
    return 0


if __name__ == "__main__":
    sys.exit(main())
