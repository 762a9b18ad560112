#!/usr/bin/python3
"""Writes the "what accuracy costs" appendix from the studies' tables and the
bench output (both produced by scripts/accuracy-studies.sh)."""
import csv
import sys
from pathlib import Path


def table(folder, name):
    return (Path(folder) / name / "table.md").read_text().strip()


def tables(folder, captioned):
    """One study's table after another, each under its caption."""
    return "\n\n".join(f"{caption}:\n\n{table(folder, name)}" for caption, name in captioned)


def rmse_table(folder, name):
    """Each variant's RMSE at the largest sample count (over its seeds), the
    fastest render's seconds and the efficiency 1 / (RMSE^2 x seconds)."""
    with open(Path(folder) / name / "convergence.csv") as f:
        rows = list(csv.DictReader(f))
    largest = max(int(r["spp"]) for r in rows)
    lines = [f"| variant | RMSE at {largest} spp | seconds | efficiency 1/(RMSE^2 x s) | relative efficiency |",
             "|---|---|---|---|---|"]
    first = None
    for variant in dict.fromkeys(r["variant"] for r in rows):
        at = [r for r in rows if r["variant"] == variant and int(r["spp"]) == largest]
        mse = sum(float(r["rmse"]) ** 2 for r in at) / len(at)
        seconds = min(float(r["seconds"]) for r in at)
        efficiency = 1.0 / (mse * seconds)
        first = first or efficiency
        lines.append(f"| {variant} | {mse ** 0.5:.3e} | {seconds:.3f} | {efficiency:.3e} | {efficiency / first:.2f} |")
    return "\n".join(lines)


def main(folder):
    bench = (Path(folder) / "bench.txt").read_text().strip()
    cycles_file = Path(folder) / "vs-cycles.txt"
    cycles = cycles_file.read_text().strip() if cycles_file.exists() else "skipped: not measured"
    print(f"""# Appendix: what accuracy costs

Every number on this page comes from `scripts/accuracy-studies.sh`, which
runs `rixconverge` (error against a converged reference as samples double,
several seeds each) and `rixbench` on a 2-core machine. Run it again to
regenerate the page. relMSE is mean((x - r)^2 / (r^2 + 0.01)); efficiency is
1 / (relMSE x seconds) at the largest sample count, from the two columns
before it, higher is better; its range over the sample counts from 4 up shows
how much it moves with the count (it grows where the error falls faster than
1/spp) and with the machine's load; "relative" compares with the first row.

Our sampler is a scrambled Sobol' sequence, so errors usually fall faster
than the plain Monte Carlo rate (slope -1 in the log-log plots): smooth
integrands reach slopes near -1.5 or even -2. Strategies that make the
integrand rough (cosine sampling of a sharp lobe) fall back toward -1.

## Uniform or cosine-weighted directions (chapter 4)

A diffuse sphere on a floor under an even sky, sampled by its Bxdf only.
Both strategies converge to the same image; cosine sampling, whose density
follows the cos(theta) in the integrand, needs less time for the same error.

{table(folder, "ch04-uniform-vs-cosine")}

![relMSE against samples](figures/studies/ch04-uniform-vs-cosine/error_vs_spp.png)

## Cosine against importance sampling of glossy lobes (chapters 6 and 8)

The same scene with a Phong sphere (exponent n) and a Ward sphere
(roughness alpha). The narrower the lobe, the more cosine sampling wastes its
samples where the lobe is dark, and the larger the gap grows.

{tables(folder, [("Phong, n = 10", "ch06-phong-n10"), ("Phong, n = 100", "ch06-phong-n100"),
                  ("Phong, n = 1000", "ch06-phong-n1000"), ("Ward, alpha = 0.3", "ch08-ward-a0.3"),
                  ("Ward, alpha = 0.1", "ch08-ward-a0.1"), ("Ward, alpha = 0.03", "ch08-ward-a0.03")])}

![Ward, alpha = 0.03: relMSE against time](figures/studies/ch08-ward-a0.03/error_vs_time.png)

## Three ways to sample GGX (chapter 9)

The same scene with a GGX sphere. Sampling the distribution of normals puts
samples where D is large but ignores which normals the viewer can see: at
the sphere's silhouette, where the view grazes the surface, most of its
samples fall below the horizon and the few left carry large weights. The
normals the viewer sees give every sample a weight of at most 1.

{tables(folder, [("GGX, alpha = 0.3", "ch09-ggx-a0.3"), ("GGX, alpha = 0.1", "ch09-ggx-a0.1")])}

![GGX, alpha = 0.1: relMSE against time](figures/studies/ch09-ggx-a0.1/error_vs_time.png)

## Light sampling, Bxdf sampling and MIS (after Veach)

A glossy floor under a small and a large sphere light. Sampling the Bxdf
alone almost never finds the small light and is hopeless; sampling the
lights does well; multiple importance sampling is within a small factor of
the better strategy. (Here light sampling edges ahead of MIS: its stratified
samples in the lights' cones converge at slope -2, while the MIS mixture of
two strategies is less smooth for the Sobol' points. With independent random
numbers MIS would not lose.)

{table(folder, "ch06-light-bxdf-mis")}

![relMSE against time](figures/studies/ch06-light-bxdf-mis/error_vs_time.png)

## What a bounce costs (path tracing against direct lighting)

The showcase at 240 x 100 pixels. Each row is measured against a converged
path-traced reference, so direct lighting's error includes the light it
never computes (the floor lit by the glowing sphere, the reflections): it
stops improving however many samples it takes.

{table(folder, "ch04-bounces")}

## Adaptive sampling (PixelVariance)

The same showcase, path traced, with every pixel taking every sample against
pixels that stop once their relative variance (the variance of their value
over the value squared, as RenderMan measures it) is at most PixelVariance.
Each count is then the most a pixel takes, and the first test comes after its
square root. A pixel whose samples agree, or that is already as certain as
asked, stops there, and the samples go where the noise is. Each setting has a
floor: once most pixels have stopped, more samples allowed change little, so
the error falls more slowly with the count (the slope) while the time it
costs stays low:

{table(folder, "ch04-adaptive")}

The same renders measured by RMSE, which weighs every pixel's error alike:

{rmse_table(folder, "ch04-adaptive")}

![relMSE against time](figures/studies/ch04-adaptive/error_vs_time.png)

## The renderer's own costs

```
{bench}
```

## Against another renderer: Blender's Cycles

`bench/vs-cycles.sh` renders the chapter-6 scene in rixrender and in Cycles
(the same camera, sphere and disk light; direct lighting only). Each renderer
is measured against its own converged reference, and the two references must
agree in mean within 2% before anything is compared. Cycles meshes the
sphere; rixrender intersects it exactly. rixrender's time is its whole
process, Cycles' its render call without Blender's start-up.

```
{cycles}
```
""")


if __name__ == "__main__":
    main(sys.argv[1])
