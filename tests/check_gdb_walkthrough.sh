#!/bin/sh
# Chapter 7's gdb walkthrough, as the chapter prints it: the starter built as
# Debug, a pending breakpoint in Diffuse::EvaluateSample, then
# `print shadingCtx->numPts` and `print Ln[0]` must show values (they did not
# while the API classes' debug information lived only in the renderer).
#   check_gdb_walkthrough.sh <course root> <rixrender> <scratch folder>
set -eu
root=$1 rixrender=$2 work=$3
cmake -S "$root/starter" -B "$work" -DBXDFLAB_ROOT="$root" -DCMAKE_BUILD_TYPE=Debug > /dev/null
cmake --build "$work" --target buggydiffuse > /dev/null
cd "$root"
gdb -batch -ex "set breakpoint pending on" -ex "break Diffuse::EvaluateSample" -ex run \
    -ex "print shadingCtx->numPts" -ex "print Ln[0]" \
    --args "$rixrender" --threads 1 --spp 1 --plugin-path "$work/plugins" scenes/ch07/buggydiffuse.rib \
    -o "$work/x.exr" 2>&1
