#!/usr/bin/env python3
"""What the checks miss: random one-token mutants of the Bxdf solutions.

    bench/mutation_sweep.py [--build build] [--only ggx] [--count 40] [--seed 1] [--jobs 2] [--ops math|names]

variants.json holds mutants written by hand, each a bug someone is likely to
make. This sweep makes mutants blindly instead: it changes one token of a
solution's source at a random place -- an operator (+ -, * /, < <=), a number
(times 1.1), a component (.x .y, [0] [1]), a clamp (max min), an index ([i] to
[0]) or, with --ops names, one name for a neighbour (V L, N Ng, fpdf rpdf,
uRoughness vRoughness) -- builds the plugin and runs every rixcheck check on it.
A mutant no check fails is a survivor, printed with its change. Many survivors
change nothing that can be seen (a tie at exactly zero, a value that is
overwritten); the others are where the checks are blind.

Prints one line per mutant and a table per exercise; writes nothing.
"""
import argparse
import concurrent.futures
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))

MATH_OPS = [
    (r" \+ ", " - "), (r" - ", " + "), (r" \* ", " / "), (r" / ", " * "),
    (r" < ", " <= "), (r" <= ", " < "), (r" > ", " >= "), (r" >= ", " > "),
    (r"\.x\b", ".y"), (r"\.y\b", ".x"), (r"\.z\b", ".x"), (r"\[0\]", "[1]"), (r"\[1\]", "[0]"),
    (r"\[i\]", "[0]"), (r"\bstd::fabs\(", "("), (r"\bRixMax\(", "RixMin("), (r"\bstd::sqrt\(", "("),
]
NAME_OPS = [
    (r"\bV\b", "L"), (r"\bL\b", "V"), (r"\bTX\b", "TY"), (r"\bTY\b", "TX"), (r"\.u\b", ".v"), (r"\.v\b", ".u"),
    (r"\bcosL\b", "cosV"), (r"\bcosV\b", "cosL"), (r"\bNdL\b", "NdV"), (r"\bNdV\b", "NdL"),
    (r"\bfpdf\b", "rpdf"), (r"\brpdf\b", "fpdf"), (r"\betaV\b", "etaL"), (r"\betaL\b", "etaV"),
    (r"\bm_Nn\b", "m_Ngn"), (r"\bm_Ngn\b", "m_Nn"), (r"\bN\b", "H"), (r"\bH\b", "N"),
    (r"\buRoughness\b", "vRoughness"), (r"\bvRoughness\b", "uRoughness"),
]
FLOAT_LITERAL = re.compile(r"(?<![\w.])(\d+\.\d*|\.\d+)f\b")


def exercises():
    """plugin -> (solution folder, its .cpp files) for every exercise rixcheck checks (not the integrators)."""
    found = {}
    for manifest in sorted(os.popen(f"find {ROOT}/starter -name exercise.json").read().split()):
        m = json.load(open(manifest))
        if m.get("kind") == "integrator":
            continue
        folder = os.path.join(ROOT, "solutions", os.path.relpath(os.path.dirname(manifest), os.path.join(ROOT, "starter")))
        if os.path.isdir(folder):  # a warm-up exercise is its own answer
            found[m["plugin"]] = (folder, sorted(f for f in os.listdir(folder) if f.endswith(".cpp")))
    return found


def places(lines, ops, literals):
    """Every (line, start, end, replacement) a mutation can change, comments left alone."""
    out = []
    for n, line in enumerate(lines):
        stripped = line.strip()
        if not stripped or stripped.startswith(("//", "#", "*", "/*")):
            continue
        code = line.split("//")[0]
        for pattern, replacement in ops:
            out += [(n, m.start(), m.end(), replacement) for m in re.finditer(pattern, code)]
        if literals:
            for m in FLOAT_LITERAL.finditer(code):
                value = float(m.group(1))
                text = f"{1.1 * value:.6g}" if value != 0 else "0.001"
                if "." not in text and "e" not in text:
                    text += ".0"
                out.append((n, m.start(), m.end(), text + "f"))
    return out


def run_mutant(args, plugin, folder, sources, source, lines, place, work):
    n, start, end, replacement = place
    mutated = list(lines)
    mutated[n] = mutated[n][:start] + replacement + mutated[n][end:]
    change = f"{source}:{n + 1}: {lines[n].strip()}  ==>  {mutated[n].strip()}"
    os.makedirs(os.path.join(work, "plugins"))
    for name in os.listdir(folder):
        shutil.copy(os.path.join(folder, name), work)
    open(os.path.join(work, source), "w").write("\n".join(mutated))
    built = subprocess.run(["c++", "-std=c++17", "-O1", "-fPIC", "-shared", "-fvisibility=hidden", "-w",
                            "-Wl,--no-undefined", f"-I{ROOT}/renderer/include/rix", f"-I{work}",
                            "-o", os.path.join(work, "plugins", plugin + ".so"),
                            *(os.path.join(work, s) for s in sources)],
                           capture_output=True, text=True)
    if built.returncode != 0:
        return "no build", [], change
    checked = subprocess.run([os.path.join(args.build, "bin", "rixcheck"), "--plugin", plugin, "--plugin-dir",
                              os.path.join(work, "plugins")], capture_output=True, text=True, timeout=900)
    failed = [line.split()[2].rstrip(":") for line in checked.stdout.splitlines() if line.startswith("FAIL")]
    return ("caught" if failed else "SURVIVED"), failed, change


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--only", help="one exercise's plugin (e.g. ggx)")
    parser.add_argument("--count", type=int, default=40, help="mutants per source file")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--ops", choices=["math", "names"], default="math")
    args = parser.parse_args()
    if not os.path.exists(os.path.join(args.build, "bin", "rixcheck")):
        sys.exit(f"mutation_sweep: {args.build}/bin/rixcheck is missing (build the project first)")

    ops = MATH_OPS if args.ops == "math" else NAME_OPS
    jobs = []
    for plugin, (folder, sources) in sorted(exercises().items()):
        if args.only and plugin != args.only:
            continue
        for source in sources:
            lines = open(os.path.join(folder, source)).read().split("\n")
            candidates = places(lines, ops, args.ops == "math")
            random.Random(f"{args.seed}:{plugin}:{source}").shuffle(candidates)
            jobs += [(plugin, folder, sources, source, lines, place) for place in candidates[:args.count]]
    if not jobs:
        sys.exit("mutation_sweep: no exercise matches")

    tally = {}
    with tempfile.TemporaryDirectory(prefix="mutants-") as scratch:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            futures = [pool.submit(run_mutant, args, *job, os.path.join(scratch, str(k))) for k, job in enumerate(jobs)]
            for (plugin, *_), future in zip(jobs, futures):
                verdict, failed, change = future.result()
                counts = tally.setdefault(plugin, {"caught": 0, "SURVIVED": 0, "no build": 0})
                counts[verdict] += 1
                print(f"{plugin:13} {verdict:9} {' '.join(failed):45} {change}", flush=True)

    print(f"\n{'exercise':13} {'mutants':>8} {'caught':>8} {'survived':>9} {'no build':>9}")
    for plugin, counts in sorted(tally.items()):
        print(f"{plugin:13} {sum(counts.values()):8} {counts['caught']:8} {counts['SURVIVED']:9} {counts['no build']:9}")


if __name__ == "__main__":
    main()
