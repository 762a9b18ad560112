#!/usr/bin/python3
"""Checks a rixgrade results.json: expect_grade.py RESULTS [--fail CHECK]... [--pass-all] [--output-mentions TEXT] [--same-as OTHER_RESULTS]"""
import json
import sys


def main(argv):
    results = json.load(open(argv[1]))
    by_check = {t["name"].split(": ")[-1]: t for t in results["tests"]}
    problems = []
    args = argv[2:]
    while args:
        flag = args.pop(0)
        if flag == "--fail":
            check = args.pop(0)
            if by_check[check]["status"] != "failed":
                problems.append(f"{check} should fail but passed")
        elif flag == "--pass-all":
            problems += [f"{name} should pass: {t['output'][:300]}" for name, t in by_check.items() if t["status"] != "passed"]
        elif flag == "--pass":
            check = args.pop(0)
            if by_check[check]["status"] != "passed":
                problems.append(f"{check} should pass: {by_check[check]['output'][:300]}")
        elif flag == "--output-mentions":
            text = args.pop(0).replace("_", " ")
            if not any(text in t["output"] for t in results["tests"]):
                problems.append(f"no check output mentions '{text}'")
        elif flag == "--same-as":
            # Every check's status, points and message (numbers included) must repeat exactly.
            other = json.load(open(args.pop(0)))
            strip = lambda r: [(t["name"], t["status"], t["score"], t["output"]) for t in r["tests"]]
            if strip(results) != strip(other):
                problems.append("two gradings of the same submission differ")
    print(f"score {results['score']} / {results['max_score']}")
    for p in problems:
        print("PROBLEM:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
