#!/usr/bin/env python3
"""The Rix headers a Bxdf includes stay light to compile.

    check_header_weight.py <c++ compiler> <rix include folder> <most lines>

Every source of every student plugin includes RixBxdf.h and
RixShadingUtils.h, so what they pull in is paid on each compile, in each
student's edit loop and in each grading build. Preprocessed, the two must
stay within <most lines>; when they do not, this prints the standard
headers they include, largest first, so the new one stands out.
"""
import subprocess
import sys
import tempfile
from pathlib import Path


def preprocess(compiler, folder, source, *flags):
    return subprocess.run([compiler, "-std=c++17", *flags, "-I", folder, str(source)],
                          capture_output=True, text=True, check=True)


def main(compiler, folder, most):
    with tempfile.TemporaryDirectory() as scratch:
        source = Path(scratch) / "bxdf.cpp"
        source.write_text('#include "RixBxdf.h"\n#include "RixShadingUtils.h"\n')
        lines = preprocess(compiler, folder, source, "-E").stdout.count("\n")
        print(f"RixBxdf.h and RixShadingUtils.h preprocess to {lines} lines (at most {most})")
        if lines <= most:
            return 0
        # -H prints each included file with one dot per level of nesting: keep
        # the standard headers a Rix header includes itself.
        tree = preprocess(compiler, folder, source, "-fsyntax-only", "-H").stderr.splitlines()
        parents, direct = [str(source)], set()
        for line in tree:
            dots, _, path = line.partition(" ")
            if not dots or set(dots) != {"."}:
                continue
            depth = len(dots)
            parents[depth:] = [path]
            if Path(parents[depth - 1]).parent.resolve() == Path(folder).resolve() and \
                    Path(path).parent.resolve() != Path(folder).resolve():
                direct.add(path)
        weights = []
        for header in direct:
            single = Path(scratch) / "one.cpp"
            single.write_text(f'#include "{header}"\n')
            weights.append((preprocess(compiler, folder, single, "-E").stdout.count("\n"), header))
        print("standard headers the Rix headers include, with their own lines:")
        for count, header in sorted(weights, reverse=True):
            print(f"  {count:7d}  {header}")
        return 1


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2], int(sys.argv[3])))
