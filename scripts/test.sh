#!/usr/bin/env bash
# Quick start, part 2: set up, build, and run every test; then the sanitizer
# build (AddressSanitizer + UndefinedBehaviorSanitizer) and the tests that run
# under it in CI time (scripts/sanitize.sh --full runs all of them there).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
(cd build && ctest --output-on-failure --parallel "$(nproc)")
scripts/sanitize.sh
