#!/usr/bin/env python3
"""How often the autograder's checks are wrong, measured.

    bench/grader_rates.py [--build build] [--seeds 300] [--mutant-seeds 20] [--jobs 2] [--out out/grader-rates]

False fails: every reference solution and every correct variant of
autograder/tests/variants.json is checked under --seeds different streams of
the checker's own random numbers (rixcheck --seed); each failure of a correct
plugin is a false fail. Misses: every mutant is checked under --mutant-seeds
streams; a run where the check that names its bug passes is a miss. The checks
are labkit's, the same code rixgrade runs on a sandboxed plugin.

Writes rates.csv and rates.md to --out and prints the tables.
"""
import argparse
import collections
import concurrent.futures
import json
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))


def manifests():
    found = {}
    for chapter in sorted(os.listdir(os.path.join(ROOT, "starter"))):
        folder = os.path.join(ROOT, "starter", chapter)
        if not os.path.isdir(folder):
            continue
        for exercise in sorted(os.listdir(folder)):
            path = os.path.join(folder, exercise, "exercise.json")
            if os.path.exists(path):
                m = json.load(open(path))
                found[m["plugin"]] = m
    return found


def check_once(build, plugin, folder, seed):
    """{check: passed} for one rixcheck run."""
    run = subprocess.run([os.path.join(build, "bin/rixcheck"), "--plugin", plugin, "--plugin-dir", folder, "--seed",
                          str(seed)], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, errors="replace")
    verdicts = {}
    for line in run.stdout.splitlines():
        m = re.match(r"(PASS|FAIL|N/A ) \S+ (\S+):", line)
        if m:
            verdicts[m.group(2)] = m.group(1) != "FAIL"
    return verdicts


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--seeds", type=int, default=300)
    parser.add_argument("--mutant-seeds", type=int, default=20)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", default=os.path.join(ROOT, "out/grader-rates"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    exercises = manifests()
    # Integrators are graded by rendering only (rixgrade), which this measurement does not cover.
    variants = [v for v in json.load(open(os.path.join(ROOT, "autograder/tests/variants.json")))["variants"]
                if exercises.get(v["plugin"], {}).get("kind", "bxdf") != "integrator"]
    solutions = os.path.join(args.build, "plugins/solutions")

    correct = [("solution " + p, p, solutions) for p in exercises if exercises[p].get("kind", "bxdf") == "bxdf"
               or p == "sampling"]
    correct += [("variant " + v["name"], v["plugin"], os.path.join(args.build, "plugins/variants", v["name"]))
                for v in variants if v["kind"] == "correct"]
    mutants = [v for v in variants if v["kind"] == "mutant"]

    jobs = []
    for label, plugin, folder in correct:
        for seed in range(1, args.seeds + 1):
            jobs.append(("correct", label, plugin, folder, seed))
    for v in mutants:
        for seed in range(1, args.mutant_seeds + 1):
            jobs.append(("mutant", "mutant " + v["name"], v["plugin"], os.path.join(args.build, "plugins/variants", v["name"]),
                         seed))
    falseFails = collections.defaultdict(lambda: [0, 0])   # (label, check) -> [fails, runs]
    byCheck = collections.defaultdict(lambda: [0, 0])      # check -> [fails, runs] over all correct plugins
    caught = collections.defaultdict(lambda: [0, 0])       # mutant -> [runs where its named check failed, runs]
    done = 0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(check_once, args.build, p, f, s): (kind, label, p, s) for kind, label, p, f, s in jobs}
        for future in concurrent.futures.as_completed(futures):
            kind, label, plugin, seed = futures[future]
            verdicts = future.result()
            if kind == "correct":
                for check, passed in verdicts.items():
                    falseFails[(label, check)][1] += 1
                    byCheck[check][1] += 1
                    if not passed:
                        falseFails[(label, check)][0] += 1
                        byCheck[check][0] += 1
                        print(f"false fail: {label} {check} seed {seed}", flush=True)
            else:
                v = next(v for v in mutants if "mutant " + v["name"] == label)
                named = v["fail"][0]
                if named in verdicts:
                    caught[label][1] += 1
                    caught[label][0] += not verdicts[named]
                else:
                    # The named check is the grader's render (not in rixcheck): the first rixcheck check listed.
                    others = [c for c in v["fail"] if c in verdicts]
                    if others:
                        caught[label][1] += 1
                        caught[label][0] += not verdicts[others[0]]
            done += 1
            if done % 100 == 0:
                print(f"{done} / {len(jobs)} runs", flush=True)

    lines = ["| check | false fails | runs | rate |", "|---|---|---|---|"]
    for check, (fails, runs) in sorted(byCheck.items()):
        lines.append(f"| {check} | {fails} | {runs} | {fails / runs:.2e} |")
    lines += ["", "| correct plugin | check | false fails / runs |", "|---|---|---|"]
    for (label, check), (fails, runs) in sorted(falseFails.items()):
        if fails:
            lines.append(f"| {label} | {check} | {fails} / {runs} |")
    lines += ["", "| mutant | bug | caught by | runs caught |", "|---|---|---|---|"]
    for v in mutants:
        label = "mutant " + v["name"]
        hit, runs = caught[label]
        lines.append(f"| {v['name']} | {v['bug']} | {v['fail'][0]} | {hit} / {runs} |")
    table = "\n".join(lines) + "\n"
    print(table)
    open(os.path.join(args.out, "rates.md"), "w").write(table)
    with open(os.path.join(args.out, "rates.csv"), "w") as f:
        f.write("kind,plugin,check,failures,runs\n")
        for (label, check), (fails, runs) in sorted(falseFails.items()):
            f.write(f"correct,{label},{check},{fails},{runs}\n")
        for label, (hit, runs) in sorted(caught.items()):
            f.write(f"mutant,{label},named,{hit},{runs}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
