#!/usr/bin/env python3
"""The README's list of RIB requests matches the scene builder's table, and
every request the table handles is in the parser's list of RIB request names
(renderer/src/parse/RequestNames.cpp, which the typo hints search).

    check_readme_requests.py <course root>

Every request renderer/src/scene/SceneBuilder.cpp handles is named (in
backquotes) in the README's "What the renderer supports" section, and every
request-like name in its RIB and Geometry bullets is one the builder handles.
Prints each mismatch; exits 1 if there is one.
"""
import os
import re
import sys

# Named in the README but handled outside the table (they close what the table opens)
# or not requests at all (a light plugin name, an API call).
NOT_IN_TABLE = {"ArchiveEnd", "ObjectEnd", "PxrMeshLight", "GetPrimVar"}


def main():
    root = sys.argv[1]
    with open(os.path.join(root, "renderer/src/scene/SceneBuilder.cpp")) as f:
        handled = re.findall(r'\{"(\w+)", &SceneBuilder::', f.read())
    with open(os.path.join(root, "README.md")) as f:
        readme = f.read()
    section = readme[readme.index("## What the renderer supports"):readme.index("## What accuracy costs")]
    named = set(re.findall(r"`([A-Za-z][A-Za-z0-9]*)", section)) | set(re.findall(r"/`?([A-Za-z][A-Za-z0-9]*)`", section))
    bullets = section[section.index("- **RIB**"):section.index("- **Lights**")]
    problems = [f"README.md does not name the request {n}, which the scene builder handles"
                for n in handled if n not in named]
    with open(os.path.join(root, "renderer/src/parse/RequestNames.cpp")) as f:
        names = f.read()
    table = names[names.index("kRequests = {"):names.index("};", names.index("kRequests = {"))]
    listed = set(re.findall(r'"(\w+)"', table))
    problems += [f"RequestNames.cpp does not list {n}, which the scene builder handles"
                 for n in handled if n not in listed]
    for name in sorted(set(re.findall(r"`([A-Z][A-Za-z0-9]+)", bullets))):
        if name not in handled and name not in NOT_IN_TABLE:
            problems.append(f"README.md names {name} as a request, but the scene builder has no such request")
    for p in problems:
        print(p)
    print(f"{len(handled)} requests handled, {len(problems)} mismatches with the README")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
