#!/usr/bin/env bash
# Builds autograder.zip for Gradescope: setup.sh (installs the Debian packages
# and builds the course), run_autograder (grades /autograder/submission into
# /autograder/results/results.json) and the course itself (this checkout's
# committed files). Upload the zip as the assignment's autograder.
#   scripts/gradescope-bundle.sh [OUTPUT.zip]
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:-autograder.zip}")
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
cp autograder/gradescope/setup.sh autograder/gradescope/run_autograder "$stage/"
git archive --format=tar.gz -o "$stage/bxdflab.tar.gz" HEAD
(cd "$stage" && python3 -m zipfile -c "$out" setup.sh run_autograder bxdflab.tar.gz)
echo "wrote $out"
