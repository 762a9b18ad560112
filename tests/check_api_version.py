#!/usr/bin/python3
"""Fails when the Rix headers change and RIX_PLUGIN_API_VERSION is not
reconsidered: the renderer refuses plugins built against another version,
which only protects students whose stale builds would otherwise crash if the
number moves whenever a class layout or virtual table does.

    check_api_version.py REPOSITORY_ROOT            check
    check_api_version.py REPOSITORY_ROOT --record   after deciding (bump if the ABI changed)

The fingerprint ignores comments and whitespace, so documentation edits pass.
"""
import hashlib
import re
import sys
from pathlib import Path

RECORD = Path("tests/rix-api-version.txt")


def fingerprint(root):
    text = ""
    folder = root / "renderer/include/rix"
    for header in sorted(list(folder.rglob("*.h")) + list(folder.rglob("*.hpp"))):
        code = re.sub(r"/\*.*?\*/", " ", header.read_text(), flags=re.S)
        code = re.sub(r"//[^\n]*", " ", code)
        text += header.relative_to(folder).as_posix() + ":" + " ".join(code.split()) + "\n"
    return hashlib.sha256(text.encode()).hexdigest()


def version(root):
    match = re.search(r"#define RIX_PLUGIN_API_VERSION (\d+)", (root / "renderer/include/rix/RiTypesHelper.h").read_text())
    return int(match.group(1))


def main(root, record):
    root = Path(root).resolve()
    now = f"{version(root)} {fingerprint(root)}"
    if record:
        (root / RECORD).write_text(now + "\n")
        print(f"recorded {now}")
        return 0
    recorded = (root / RECORD).read_text().strip()
    if recorded == now:
        print(f"Rix API version {version(root)}: the headers are as recorded")
        return 0
    old_version = int(recorded.split()[0])
    print(f"the Rix headers changed since {RECORD} was recorded (version {old_version}, now {version(root)}).\n"
          "If the change alters a class layout, a virtual function or a signature, increase\n"
          "RIX_PLUGIN_API_VERSION in renderer/include/rix/RiTypesHelper.h; then run\n"
          f"  tests/check_api_version.py . --record")
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], "--record" in sys.argv[2:]))
