#!/usr/bin/env bash
# The sanitizer build: the renderer, plugins and tests built with
# AddressSanitizer and UndefinedBehaviorSanitizer into build-sanitize/, then
# tests run there. Any memory error, leak or undefined behaviour fails a test.
# Renderer cases tagged [heavy] and corpus files marked heavy take minutes
# here; they are left to the release build (the script says how many).
#   scripts/sanitize.sh          the subset scripts/test.sh runs (ctest label "sanitize")
#   scripts/sanitize.sh --full   every test but the [heavy] renderer cases
# Run scripts/setup.sh first (scripts/test.sh does).
set -euo pipefail
cd "$(dirname "$0")/.."

cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBXDFLAB_SANITIZE=ON -DBXDFLAB_FUZZ=OFF > /dev/null
# Stop at the first report, with a stack trace.
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

if [ "${1:-}" = "--full" ]; then
  cmake --build build-sanitize --parallel
  cd build-sanitize
  ctest --output-on-failure --parallel "$(nproc)"
else
  # Only what the subset runs: the renderer's test program (with the plugins it
  # loads), the fuzz replay and rixrender.
  cmake --build build-sanitize --parallel --target rixtests rib_fuzz_replay rixrender
  cd build-sanitize
  ctest -L sanitize --output-on-failure --parallel "$(nproc)"
fi
cases=$(bin/rixtests "[heavy]" --list-test-names-only | grep -c . || true)
files=$(ctest -N -L heavy | grep -c "Test *#" || true)
echo "sanitize: left to the release build's ctest, for taking minutes under the sanitizers:" \
     "renderer cases tagged [heavy]: $cases; corpus files marked heavy: $files"
