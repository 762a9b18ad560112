#!/usr/bin/python3
"""Checks the chapters and the README the way a reader would use them:
every shell block marked ```sh test runs (from the repository root, in
chapter order) and succeeds, and every image and local file they link exists.

    check_chapters.py REPOSITORY_ROOT
"""
import re
import subprocess
import sys
from pathlib import Path

FENCE = re.compile(r"^```sh test\n(.*?)^```", re.S | re.M)
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def documents(root):
    yield root / "README.md"
    yield from sorted((root / "chapters").glob("ch*/README.md"))
    yield from sorted((root / "chapters").glob("appendix-*.md"))


def main(root):
    root = Path(root).resolve()
    failures = 0
    commands = 0
    for doc in documents(root):
        text = doc.read_text()
        for target in LINK.findall(text):
            if "://" in target or target.startswith("#"):
                continue
            path = (doc.parent / target.split("#")[0]).resolve()
            if not path.exists():
                print(f"{doc.relative_to(root)}: link to missing {target}")
                failures += 1
        for block in FENCE.findall(text):
            commands += 1
            result = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", block], cwd=root,
                                    capture_output=True, text=True)
            if result.returncode != 0:
                print(f"{doc.relative_to(root)}: this block failed (exit {result.returncode}):\n{block}")
                print(result.stdout[-2000:], result.stderr[-2000:])
                failures += 1
    print(f"{commands} command blocks run; {failures} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
