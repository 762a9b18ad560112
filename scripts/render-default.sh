#!/usr/bin/env bash
# Quick start, part 1: set up, build, and render the showcase scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p out
build/bin/rixrender scenes/showcase.rib -o out/showcase.png
echo "Open out/showcase.png to see the render."
