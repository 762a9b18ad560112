#!/usr/bin/env python3
"""Renders one file of the real-world RIB corpus (../shared/compat) the way a
user would, from its own folder, small and fast, and checks the outcome that
tests/compat/corpus.json expects for it:

  "renders"  exit status 0, every frame's image finite, lit or black as "lit" says,
             and each of "warnings" (regular expressions) among the messages;
  "error"    exit status 1 with a message matching "error" (a located one).

An entry marked "heavy" is left out of the sanitizer build's run (tests/CMakeLists.txt).

Usage: check_corpus_file.py RIXRENDER CORPUS_ROOT MANIFEST ID OUTPUT_DIR
"""
import glob
import json
import os
import re
import subprocess
import sys


def main():
    rixrender, root, manifest, ident, out_dir = sys.argv[1:6]
    entries = {e["id"]: e for e in json.load(open(manifest))}
    entry = entries[ident]
    scene = os.path.join(root, entry["file"])
    run_from = os.path.join(root, entry.get("runFrom", os.path.dirname(entry["file"])))
    os.makedirs(out_dir, exist_ok=True)
    for old in glob.glob(os.path.join(out_dir, ident + "*")):
        os.remove(old)
    image = os.path.join(out_dir, ident + ".exr")
    stats = os.path.join(out_dir, ident + ".json")
    command = [rixrender, "--quiet", "--spp", "1", "--resolution-scale", str(entry.get("scale", 0.25)),
               "--threads", "1", "-o", image, "--stats-json", stats, os.path.relpath(scene, run_from)]
    done = subprocess.run(command, cwd=run_from, capture_output=True, text=True, timeout=600)
    messages = done.stderr
    problems = []
    expect = entry.get("expect", "renders")
    if expect == "error":
        if done.returncode != 1:
            problems.append(f"expected exit status 1, got {done.returncode}")
        if not re.search(entry["error"], messages):
            problems.append(f"no message matches {entry['error']!r}")
    else:
        if done.returncode != 0:
            problems.append(f"exit status {done.returncode}")
        frames = sorted(glob.glob(os.path.join(out_dir, ident + "*.json")))
        if done.returncode == 0 and not frames:
            problems.append("no stats were written")
        for frame in frames:
            s = json.load(open(frame))
            if s["nonfinite_samples"] or s["invalid_pdf_samples"]:
                problems.append(f"{os.path.basename(frame)}: {s['nonfinite_samples']} non-finite and "
                                f"{s['invalid_pdf_samples']} invalid-pdf samples")
            lit = s["image"]["lit_fraction"]
            if entry.get("lit", True) and lit < entry.get("minLit", 0.001):
                problems.append(f"{os.path.basename(frame)}: the image is black (lit fraction {lit:.4f})")
            if not entry.get("lit", True) and lit > 0:
                problems.append(f"{os.path.basename(frame)}: expected a black image, lit fraction {lit:.4f}")
        for pattern in entry.get("warnings", []):
            if not re.search(pattern, messages):
                problems.append(f"no warning matches {pattern!r}")
    if "Assertion" in messages or "Sanitizer" in messages:
        problems.append("the renderer crashed")
    print(f"{ident} ({entry['file']}): {'ok' if not problems else 'FAILED'}")
    for p in problems:
        print("  " + p)
    if problems:
        print("--- rixrender said ---\n" + messages[-4000:])
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
