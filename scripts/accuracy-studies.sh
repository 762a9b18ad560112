#!/usr/bin/env bash
# Regenerates every accuracy-versus-time study the chapters show, into
# chapters/figures/studies/: for each study a convergence.csv, a table.md and
# error-vs-spp / error-vs-time plots. Run scripts/setup.sh first.
set -euo pipefail
cd "$(dirname "$0")/.."
out=chapters/figures/studies
converge=build/bin/rixconverge
spp=1,2,4,8,16,32,64
mkdir -p "$out"

# Chapter 4: uniform against cosine-weighted hemisphere sampling of a diffuse surface.
$converge scenes/ch04/estimators.rib --spp $spp --repeats 3 --out $out/ch04-uniform-vs-cosine \
  --variant cosine='Bxdf "diffuse" "white" "color diffuseColor" [0.9 0.9 0.9] "int samplingMode" [0]
                    Bxdf "diffuse" "floor" "color diffuseColor" [0.5 0.5 0.5] "int samplingMode" [0]' \
  --variant uniform='Bxdf "diffuse" "white" "color diffuseColor" [0.9 0.9 0.9] "int samplingMode" [1]
                     Bxdf "diffuse" "floor" "color diffuseColor" [0.5 0.5 0.5] "int samplingMode" [1]'

# Chapters 6 and 8: cosine sampling against importance sampling, narrower and narrower lobes.
for gloss in 10 100 1000; do
  $converge scenes/studies/glossy.rib --spp $spp --repeats 3 --out $out/ch06-phong-n$gloss \
    --variant importance="Bxdf \"specular\" \"glossy\" \"float gloss\" [$gloss] \"int samplingMode\" [1]" \
    --variant cosine="Bxdf \"specular\" \"glossy\" \"float gloss\" [$gloss] \"int samplingMode\" [0]"
done
for alpha in 0.3 0.1 0.03; do
  $converge scenes/studies/glossy.rib --spp $spp --repeats 3 --out $out/ch08-ward-a$alpha \
    --variant walter="Bxdf \"ward\" \"glossy\" \"float uRoughness\" [$alpha] \"float vRoughness\" [$alpha] \"int samplingMode\" [1]" \
    --variant cosine="Bxdf \"ward\" \"glossy\" \"float uRoughness\" [$alpha] \"float vRoughness\" [$alpha] \"int samplingMode\" [0]"
done

# Chapter 9: GGX sampled by cosine, by its distribution of normals, and by the normals the viewer sees.
for alpha in 0.3 0.1; do
  ggx="Bxdf \"ggx\" \"glossy\" \"float uRoughness\" [$alpha] \"float vRoughness\" [$alpha] \"int samplingMode\""
  $converge scenes/studies/glossy.rib --spp $spp --repeats 3 --out $out/ch09-ggx-a$alpha \
    --variant visible="$ggx [2]" --variant normals="$ggx [1]" --variant cosine="$ggx [0]"
done

# Chapters 4 and 6: light sampling, Bxdf sampling and MIS (after Veach).
$converge scenes/studies/veach.rib --spp $spp --repeats 3 --out $out/ch06-light-bxdf-mis \
  --variant MIS='Integrator "PxrDirectLighting" "i" "int numLightSamples" [1] "int numBxdfSamples" [1]' \
  --variant light='Integrator "PxrDirectLighting" "i" "int numLightSamples" [1] "int numBxdfSamples" [0]' \
  --variant bxdf='Integrator "PxrDirectLighting" "i" "int numLightSamples" [0] "int numBxdfSamples" [1]'

# Direct lighting against path tracing: what each bounce costs and changes.
$converge scenes/showcase.rib --res 240x100 --spp 1,2,4,8,16,32 --repeats 2 --out $out/ch04-bounces \
  --variant paths-10='Integrator "PxrPathTracer" "i" "int maxPathLength" [10]' \
  --variant paths-3='Integrator "PxrPathTracer" "i" "int maxPathLength" [3]' \
  --variant paths-2='Integrator "PxrPathTracer" "i" "int maxPathLength" [2]' \
  --variant direct='Integrator "PxrDirectLighting" "i"'

# Adaptive sampling: every pixel alike against pixels that stop once their value is certain enough
# (PixelVariance); each count is then the most a pixel takes.
$converge scenes/showcase.rib --res 240x100 --spp 4,8,16,32,64,128,256 --repeats 2 --out $out/ch04-adaptive \
  --variant every-pixel='PixelVariance 0' \
  --variant pv-0.01='PixelVariance 0.01' \
  --variant pv-0.003='PixelVariance 0.003' \
  --variant pv-0.001='PixelVariance 0.001'

echo "studies written to $out"

# The bench: shading overhead against raw Embree, thread scaling, cost scaling.
build/bin/rixbench > $out/bench.txt
echo "bench written to $out/bench.txt"

# Against Blender's Cycles on the chapter-6 scene (about three minutes; it says
# "skipped" when Blender is not installed).
bench/vs-cycles.sh --out out/vs-cycles > $out/vs-cycles.txt
echo "Cycles comparison written to $out/vs-cycles.txt"

# The appendix that collects the headline numbers.
python3 tools/accuracy_appendix.py $out > chapters/appendix-accuracy-cost.md
echo "wrote chapters/appendix-accuracy-cost.md"
