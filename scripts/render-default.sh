#!/usr/bin/env bash
# Quick start, part 1: set up, build, and render the default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p out
build/bin/rixrender scenes/ch06/diffuse.rib -o out/ch06-diffuse.png
echo "Open out/ch06-diffuse.png to see the render."
