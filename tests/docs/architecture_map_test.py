#!/usr/bin/env python3
"""docs/architecture.md, the map, against the build it describes.

  architecture_map_test.py SOURCE_DIR

Asserted, each from the files the build reads (no build needed):
- the libraries table: every target's project links in its CMakeLists.txt are exactly the row's
  `links` column, and each target's links are rows above it (the table is bottom up);
- the layer lists: each library's line equals its `set(<lib>_layers ...)` list, and every
  folder of that library with a CMakeLists.txt is a layer;
- every repository path the page names in backticks exists, and every relative link resolves;
- README.md links the map before any other page of docs/.
Fails naming the row, the list or the path that differs.
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), "..", ".."))
MAP = os.path.join(ROOT, "docs", "architecture.md")
# Where each project target is defined (the CMakeLists.txt that calls add_library /
# add_executable for it).
TARGET_FILES = {
    "models": "models/CMakeLists.txt",
    "impact_command_line": "CMakeLists.txt",
    "material_check": "tools/CMakeLists.txt",
    "pointdriver_core": "pointdriver/CMakeLists.txt",
    "pointdriver": "pointdriver/CMakeLists.txt",
    "mpm_core": "mpm/CMakeLists.txt",
    "mpm": "commands/CMakeLists.txt",
    "mpm_campaigns": "campaigns/CMakeLists.txt",
    "impact_python": "python/CMakeLists.txt",
}
problems = []


def cmake_text(rel):
    text = open(os.path.join(ROOT, rel)).read()
    return re.sub(r"#[^\n]*", "", text)  # comments out


def project_links(target):
    """The project targets `target` links, from every target_link_libraries(target ...)."""
    text = cmake_text(TARGET_FILES[target])
    links = set()
    for m in re.finditer(r"target_link_libraries\(\s*" + re.escape(target) + r"\s+([^)]*)\)", text):
        for word in re.split(r"\s+", m.group(1)):
            word = re.sub(r"^\$<BUILD_INTERFACE:(.*)>$", r"\1", word)
            if word in TARGET_FILES:
                links.add(word)
    return links


def main():
    page = open(MAP).read()
    # The libraries table: | `dir/` | `target` | what | links |
    rows = re.findall(r"^\| `([\w/]+)` \| `(\w+)` \| [^|]*\| ([^|]*)\|$", page, re.M)
    if len(rows) < len(TARGET_FILES):
        problems.append(f"libraries table: {len(rows)} rows, expected one per target "
                        f"({', '.join(sorted(TARGET_FILES))})")
    seen = []
    for directory, target, links_cell in rows:
        if target not in TARGET_FILES:
            problems.append(f"libraries table: `{target}` is no project target")
            continue
        listed = set(re.findall(r"`(\w+)`", links_cell))
        actual = project_links(target)
        if listed != actual:
            problems.append(f"libraries table, `{target}`: links {sorted(listed)}, its "
                            f"{TARGET_FILES[target]} links {sorted(actual)}")
        above = actual - set(seen)
        if above:
            problems.append(f"libraries table, `{target}`: links {sorted(above)}, which are not "
                            "rows above it (the table is bottom up)")
        if not TARGET_FILES[target].startswith(directory) and directory != "support/":
            problems.append(f"libraries table, `{target}`: defined in {TARGET_FILES[target]}, "
                            f"not under `{directory}`")
        seen.append(target)
    # The layer lists.
    block = re.search(r"```\n(models .*?)```", page, re.S)
    if not block:
        problems.append("no layer block (a fenced block whose first line starts with 'models')")
    else:
        for line in block.group(1).strip().splitlines():
            lib, *layers = line.split()
            m = re.search(r"set\(" + lib + r"_layers\s+([^)]*)\)",
                          cmake_text(f"{lib}/CMakeLists.txt"))
            if not m:
                problems.append(f"{lib}/CMakeLists.txt has no set({lib}_layers ...)")
                continue
            built = m.group(1).split()
            if layers != built:
                problems.append(f"layers of {lib}: the map says {layers}, "
                                f"{lib}/CMakeLists.txt says {built}")
            folders = sorted(d for d in os.listdir(os.path.join(ROOT, lib))
                             if os.path.exists(os.path.join(ROOT, lib, d, "CMakeLists.txt")))
            missing = [d for d in folders if d not in built]
            if missing:
                problems.append(f"{lib}/: folders {missing} are not layers")
    # Every named path exists; every relative link resolves.
    for path in set(re.findall(r"`((?:models|support|tools|pointdriver|mpm|campaigns|python|"
                               r"commands|cmake|tests|docs|data)/[\w./-]*)`", page)):
        if not os.path.exists(os.path.join(ROOT, path)):
            problems.append(f"names `{path}`, which does not exist")
    for link in re.findall(r"\]\(([^)#:]+)(?:#[^)]*)?\)", page):
        if not os.path.exists(os.path.join(ROOT, "docs", link)):
            problems.append(f"links {link}, which does not exist")
    readme = open(os.path.join(ROOT, "README.md")).read()
    docs_links = re.findall(r"\]\((docs/[^)#]+)", readme)
    if not docs_links or docs_links[0] != "docs/architecture.md":
        problems.append("README.md: the first link into docs/ is "
                        f"{docs_links[0] if docs_links else 'missing'}, not docs/architecture.md")
    if problems:
        sys.exit("FAIL: docs/architecture.md differs from the build:\n  " + "\n  ".join(problems))
    print(f"docs/architecture.md: {len(rows)} libraries, their links and layers as the build has "
          "them; every path it names exists")


main()
