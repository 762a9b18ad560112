#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder's image: unpack the
# course, install its Debian packages, build what grading needs.
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
cd "$root/source"
rm -rf bxdflab && mkdir bxdflab && tar -xzf bxdflab.tar.gz -C bxdflab
cd bxdflab
scripts/setup.sh --grading-only
