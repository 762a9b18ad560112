#!/usr/bin/env bash
# Makes your own copy of the exercises, outside the repository, and builds it:
#   scripts/new-workspace.sh [folder]      (default: ../my-bxdflab)
# You edit the files there; the repository's starter/ stays as it is, so its
# tests stay green and chapter 7's "before" pictures keep their planted bugs.
# Render with your plugins:   build/bin/rixrender --plugin-path <folder>/build/plugins ...
# Grade them:                 build/bin/rixgrade --submission <folder> --chapter 6
# Check them while you work:  (cd <folder>/build && ctest)
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
build=1
if [[ "${1:-}" == "--no-build" ]]; then build=0; shift; fi
target="${1:-$repo/../my-bxdflab}"
target="$(realpath -m "$target")"
case "$target/" in
  "$repo"/*) echo "new-workspace: $target is inside the repository; choose a folder outside it" >&2; exit 1 ;;
esac
mkdir -p "$target"
if [[ -n "$(ls -A "$target")" ]]; then
  echo "new-workspace: $target is not empty; your work is never overwritten (choose a new folder)" >&2
  exit 1
fi
cp -r "$repo/starter/." "$target/"
cat > "$target/WORKSPACE.md" <<NOTE
Your BxdfLab exercises, copied from $repo/starter.
Build:   cmake -S . -B build -DBXDFLAB_ROOT=$repo && cmake --build build
Render:  $repo/build/bin/rixrender --plugin-path $target/build/plugins <scene.rib>
Check:   (cd build && ctest)
Grade:   $repo/build/bin/rixgrade --submission $target --chapter N
NOTE
echo "new-workspace: copied the exercises to $target"
if (( build )); then
  generator=()
  command -v ninja > /dev/null && generator=(-G Ninja)
  cmake -S "$target" -B "$target/build" "${generator[@]}" -DBXDFLAB_ROOT="$repo" > /dev/null
  cmake --build "$target/build" --parallel "${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}"
  echo "new-workspace: built; render with --plugin-path $target/build/plugins"
fi
