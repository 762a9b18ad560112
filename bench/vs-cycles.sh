#!/usr/bin/env bash
# bench/vs-cycles.sh: the chapter-6 scene (scenes/ch06/diffuse.rib) rendered by
# rixrender and by Blender's Cycles, compared by error per unit of time.
#
#   bench/vs-cycles.sh [--spp N] [--ref-spp N] [--threads N] [--runs N] [--out DIR]
#
# Each renderer is measured against its own converged reference (different
# seed, --ref-spp samples), so neither is judged by the other's bias. The two
# references must agree in mean within 2%, or the scenes are not the same and
# the comparison stops. Times are the best of --runs: rixrender's is the whole
# process (start-up, RIB, plugins, BVH, image written); Cycles' is its render
# call (scene sync, BVH, image written) without Blender's own start-up.
# The error metric is rixdiff's relMSE. Needs a build (scripts/setup.sh) and
# Blender (apt-get install blender; another one through BLENDER=/path).
# It prints ratios; it asserts nothing but the references' agreement.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

spp=64 ref_spp=512 threads=2 runs=3 out=$root/out/vs-cycles
usage() { sed -n '5p' "$0" | sed 's/^# */usage: /' >&2; exit 1; }
while [ $# -gt 0 ]; do
  case "$1" in
    --spp) spp=$2; shift 2 ;;
    --ref-spp) ref_spp=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "vs-cycles: unknown argument '$1'" >&2; usage ;;
  esac
done
for n in "$spp" "$ref_spp" "$threads" "$runs"; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "vs-cycles: '$n' is not a positive whole number" >&2; usage; }
done

blender=${BLENDER:-blender}
if ! command -v "$blender" > /dev/null; then
  echo "vs-cycles: skipped: Blender is not installed (apt-get install blender, or set BLENDER=/path/to/blender)"
  exit 0
fi
rixrender=$root/build/bin/rixrender rixdiff=$root/build/bin/rixdiff
for tool in "$rixrender" "$rixdiff"; do
  [ -x "$tool" ] || { echo "vs-cycles: $tool is missing: build first (scripts/setup.sh)" >&2; exit 1; }
done
scene=$root/scenes/ch06/diffuse.rib
mkdir -p "$out"

# rixrender: the reference, then the timed renders.
"$rixrender" --quiet --spp "$ref_spp" --seed 1 --threads "$threads" "$scene" -o "$out/rix-ref.exr" 2> "$out/rix-ref.log"
rix_best=
for _ in $(seq "$runs"); do
  start=$(date +%s.%N)
  "$rixrender" --quiet --spp "$spp" --seed 0 --threads "$threads" "$scene" -o "$out/rix.exr" 2> "$out/rix.log"
  seconds=$(echo "$start $(date +%s.%N)" | awk '{ printf "%.4f", $2 - $1 }')
  rix_best=$(echo "$seconds ${rix_best:-$seconds}" | awk '{ print ($1 < $2 ? $1 : $2) }')
done

# Cycles: the same, inside one Blender process.
"$blender" -b --factory-startup -noaudio --python "$root/bench/cycles_ch06.py" -- \
  "$out/cycles" "$spp" "$ref_spp" "$threads" "$runs" > "$out/cycles.log" 2>&1 ||
  { echo "vs-cycles: Blender failed; its output is in $out/cycles.log" >&2; exit 1; }
cycles_best=$(awk '/^render seconds/ { if (best == "" || $3 < best) best = $3 } END { print best }' "$out/cycles.log")
[ -n "$cycles_best" ] || { echo "vs-cycles: Blender rendered nothing; see $out/cycles.log" >&2; exit 1; }
cycles_version=$("$blender" --version 2> /dev/null | head -1)

# One metric for everything: rixdiff's relMSE (and its means).
field() { awk -v name="$2" 'index($0, name) == 1 { print $NF }' <<< "$1"; }
refs=$("$rixdiff" "$out/cycles-ref.exr" "$out/rix-ref.exr")
rix=$("$rixdiff" "$out/rix.exr" "$out/rix-ref.exr")
cycles=$("$rixdiff" "$out/cycles.exr" "$out/cycles-ref.exr")

awk -v cm="$(field "$refs" "mean A")" -v rm="$(field "$refs" "mean B")" -v refrel="$(field "$refs" "relMSE")" \
    -v rt="$rix_best" -v re="$(field "$rix" "relMSE")" -v ct="$cycles_best" -v ce="$(field "$cycles" "relMSE")" \
    -v spp="$spp" -v ref="$ref_spp" -v threads="$threads" -v runs="$runs" -v version="$cycles_version" '
BEGIN {
  printf "scene scenes/ch06/diffuse.rib, 800x700, %d spp (references %d spp), %d threads, best of %d\n", spp, ref, threads, runs
  gap = (cm - rm) / rm; if (gap < 0) gap = -gap
  printf "references: rixrender mean %.6f, %s mean %.6f: they differ by %.3f%% (limit 2%%); relMSE between them %.3g\n", rm, version, cm, 100 * gap, refrel
  if (gap > 0.02) { print "vs-cycles: the references disagree: the two scenes are not the same, so nothing is compared"; exit 1 }
  printf "\n%-14s %10s %12s %14s\n", "", "seconds", "relMSE", "relMSE x s"
  printf "%-14s %10.3f %12.4g %14.4g\n", "rixrender", rt, re, re * rt
  printf "%-14s %10.3f %12.4g %14.4g\n", "Cycles", ct, ce, ce * ct
  printf "\nCycles / rixrender: time %.2fx, relMSE %.2fx, relMSE x time %.2fx (target >= 5)\n", ct / rt, ce / re, (ce * ct) / (re * rt)
}'
