#!/usr/bin/env python3
"""Every Markdown table committed under docs/ and data/ (and the README files) has a delimiter row
with as many cells as its header row: GitHub's renderer (GFM) shows a table whose delimiter row is
a cell short as plain text with pipes (issue 52: 16 results.md tables and two accuracy tables
did). The cells are split as GFM splits them: on `|` outside code spans, `\\|` kept as text, one
leading and one trailing pipe optional.

The campaign scripts write most of these tables (campaigns/taylor/taylor_report.py,
campaigns/study/*.py); their writers are tested on the committed outputs here and on fresh ones
in tests/mpm/taylor/taylor_data_test.py.

  markdown_tables_test.py [REPO]"""

import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
DELIMITER = re.compile(r"^\s*\|?\s*:?-+:?\s*(\|\s*:?-+:?\s*)*\|?\s*$")


def cells(line):
    """The cells of a table row (GFM: pipes inside code spans and escaped pipes are text)."""
    text = line.strip()
    out, cur, code, i = [], "", False, 0
    while i < len(text):
        c = text[i]
        if c == "\\" and i + 1 < len(text):
            cur += text[i:i + 2]
            i += 2
            continue
        if c == "`":
            code = not code
        if c == "|" and not code:
            out.append(cur)
            cur = ""
        else:
            cur += c
        i += 1
    out.append(cur)
    if text.startswith("|"):
        out = out[1:]
    if text.endswith("|") and not text.endswith("\\|"):
        out = out[:-1]
    return out


def problems(path):
    """[(line number, header cells, delimiter cells)] of the tables in one Markdown file."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    out, fence = [], False
    for i, line in enumerate(lines):
        if line.lstrip().startswith("```"):
            fence = not fence
            continue
        if fence or i == 0 or "|" not in line or "|" not in lines[i - 1]:
            continue
        if DELIMITER.match(line) and "-" in line:
            head, delim = len(cells(lines[i - 1])), len(cells(line))
            if head != delim:
                out.append((i + 1, head, delim))
    return out


def markdown_files(root):
    for top in ("docs", "data"):
        for base, dirs, files in os.walk(os.path.join(root, top)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(".md"):
                    yield os.path.join(base, name)
    for name in ("README.md", os.path.join("mpm", "README.md"),
                 os.path.join("pointdriver", "README.md")):
        if os.path.isfile(os.path.join(root, name)):
            yield os.path.join(root, name)


def self_check():
    """The splitter on rows whose cell counts are known by hand."""
    cases = [("| a | b | c |", 3), ("a | b", 2), ("| `x | y` | z |", 2), ("| a \\| b | c |", 2),
             ("|---|---|", 2), ("|---|---|---|", 3)]
    return [f"cells({row!r}) = {len(cells(row))}, expected {n}" for row, n in cases
            if len(cells(row)) != n]


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else ROOT
    failures = self_check()
    count = 0
    for path in markdown_files(root):
        count += 1
        for line, head, delim in problems(path):
            failures.append(f"{os.path.relpath(path, root)}:{line}: the delimiter row has {delim} "
                            f"cells, the header {head}")
    if count < 30:
        failures.append(f"only {count} Markdown files found under {root}/docs and /data")
    for f in failures:
        print(f"FAIL {f}")
    print(f"{count} Markdown files, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
