#!/usr/bin/env python3
"""The renderer's folders include one another only along the data flow.

    check_include_direction.py <course root>

renderer/src/ is folded by stage: core (shared basics), then
parse -> scene -> accel -> shade -> integrate -> render, then film (image
files in and out) and app (the command line). A file may include its own
folder and the folders before it, never one after it; only accel/ includes
Embree. Stock plugins see only
the public API (renderer/include/rix) and their own headers; the renderer
never includes the course's tools (labkit, autograder). Prints every edge
against the flow and exits 1 if there is one.
"""
import os
import re
import sys

ORDER = ["core", "parse", "scene", "accel", "shade", "integrate", "render", "film", "app"]
COURSE_FOLDERS = ["checks", "probe", "measure", "stats", "exercise", "image"]  # labkit's
INCLUDE = re.compile(r'^\s*#\s*include\s+[<"]([^">]+)[">]', re.M)


def includes(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    for m in INCLUDE.finditer(text):
        yield text.count("\n", 0, m.start()) + 1, m.group(1)


def sources(folder):
    for dirpath, _, names in os.walk(folder):
        for name in sorted(names):
            if name.endswith((".h", ".cpp")):
                yield os.path.join(dirpath, name)


def main():
    root = sys.argv[1]
    src = os.path.join(root, "renderer", "src")
    problems = []
    for stage in sorted(os.listdir(src)):
        if not os.path.isdir(os.path.join(src, stage)):
            continue
        if stage not in ORDER:
            problems.append(f"renderer/src/{stage}/: a folder the data-flow order does not name (add it to ORDER)")
            continue
        for path in sources(os.path.join(src, stage)):
            for line, target in includes(path):
                top = target.split("/")[0] if "/" in target else None
                where = f"{os.path.relpath(path, root)}:{line}"
                if target.startswith("embree") and stage != "accel":
                    problems.append(f"{where}: {stage}/ includes Embree ({target}); only accel/ may")
                elif top in COURSE_FOLDERS:
                    problems.append(f"{where}: the renderer includes the course's {target}")
                elif top in ORDER and ORDER.index(top) > ORDER.index(stage):
                    problems.append(f"{where}: {stage}/ includes {target}, a later stage")
    plugins = os.path.join(root, "renderer", "plugins")
    for path in sources(plugins):
        for line, target in includes(path):
            if "/" in target and target.split("/")[0] in ORDER + COURSE_FOLDERS:
                problems.append(f"{os.path.relpath(path, root)}:{line}: a plugin includes the renderer's {target}")
    for p in problems:
        print(p)
    checked = sum(1 for _ in sources(src)) + sum(1 for _ in sources(plugins))
    print(f"{checked} files checked, {len(problems)} includes against the data flow")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
