#!/usr/bin/env bash
# Regenerates every figure the chapters show (renders, lobe plots,
# sample-vs-pdf pictures) with the project's own tools, into chapters/figures/.
# The accuracy studies have their own script: scripts/accuracy-studies.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
fig=chapters/figures
bin=build/bin
starter=build/plugins/starter
mkdir -p $fig out
render() { $bin/rixrender --quiet "$@"; }

render scenes/ch01/first.rib -o $fig/ch01-first.png
render --plugin-path $starter scenes/ch02/hello.rib -o $fig/ch02-hello.png
render scenes/ch04/estimators.rib --spp 4 -o $fig/ch04-estimators-cosine-4spp.png
sed 's/"int samplingMode" \[0\]/"int samplingMode" [1]/' scenes/ch04/estimators.rib > out/estimators-uniform.rib
render out/estimators-uniform.rib --spp 4 -o $fig/ch04-estimators-uniform-4spp.png
for channel in Ngn Nn dPdu UV; do
  sed "s/\"string viewchannel\" \[\"Ngn\"\]/\"string viewchannel\" [\"$channel\"]/" scenes/ch05/context.rib > out/context-$channel.rib
  render out/context-$channel.rib -o $fig/ch05-context-$channel.png
done
for model in emissive diffuse specular plastic; do render scenes/ch06/$model.rib -o $fig/ch06-$model.png; done
render scenes/showcase.rib -o $fig/showcase.png
$bin/rixlobe specular --params '"float gloss" [20]' --theta 45 --polar $fig/ch06-lobe-phong-polar.png --sphere $fig/ch06-lobe-phong-sphere.png
$bin/rixlobe plastic --params '"float gloss" [20]' --theta 45 --polar $fig/ch06-lobe-plastic-polar.png --sphere ''
render --plugin-path $starter scenes/ch07/validate.rib -o $fig/ch07-validate-buggy.png
render scenes/ch07/validate.rib -o $fig/ch07-validate-fixed.png
render scenes/ch07/debug.rib -o $fig/ch07-debug-nn.png
$bin/rixwarp buggydiffuse --plugin-path $starter --theta 40 --out $fig/ch07-warp-buggy.png || true
$bin/rixwarp diffuse --theta 40 --out $fig/ch08-warp-cosine.png
$bin/rixwarp diffuse --params '"int samplingMode" [1]' --theta 40 --out $fig/ch08-warp-uniform.png
$bin/rixwarp ward --params '"float uRoughness" [0.3] "float vRoughness" [0.1]' --theta 40 --out $fig/ch08-warp-ward.png
$bin/rixlobe ward --params '"float uRoughness" [0.3] "float vRoughness" [0.1]' --theta 40 --polar $fig/ch08-lobe-ward-polar.png --sphere $fig/ch08-lobe-ward-sphere.png
render scenes/ch08/ward_teapot.rib -o $fig/ch08-ward.png
render scenes/ch08/ward_teapot_swapped.rib -o $fig/ch08-ward-swapped.png
render scenes/ch08/wood.rib -o $fig/ch08-wood.png
sed 's/^Rotate -30 1 0 0/Rotate -18 1 0 0/; s/^Translate 0 -2.2 0/Translate 0 -1.2 0/; s|textures/|../scenes/ch08/textures/|' \
  scenes/ch08/wood.rib > out/wood-view2.rib
render out/wood-view2.rib -o $fig/ch08-wood-view2.png
render scenes/ch05/texture.rib -o $fig/ch05-texture.png
render scenes/ch09/ggx_spheres.rib -o $fig/ch09-ggx.png
render scenes/ch09/ggx_vs_ward.rib -o $fig/ch09-ggx-vs-ward.png
$bin/rixlobe ggx --params '"float uRoughness" [0.3] "float vRoughness" [0.3]' --theta 60 --polar $fig/ch09-lobe-ggx-polar.png --sphere ''
for mode in 1 2; do
  $bin/rixwarp ggx --params "\"float uRoughness\" [0.3] \"float vRoughness\" [0.3] \"int samplingMode\" [$mode]" \
    --theta 85 --out $fig/ch09-warp-ggx-mode$mode.png
done
render scenes/ch10/glass_spheres.rib -o $fig/ch10-glass.png
render scenes/ch10/furnace.rib -o $fig/ch10-furnace.png
$bin/rixwarp glass --params '"float roughness" [0.3]' --sphere --theta 130 --out $fig/ch10-warp-glass.png
for scene in mis_light mis_bxdf mis; do
  render scenes/ch11/$scene.rib --spp 4 -o $fig/ch11-${scene//_/-}-4spp.png
done
render scenes/ch11/box.rib -o $fig/ch11-box.png
echo "figures written to $fig"
