#!/usr/bin/python3
"""Plots a rixconverge folder: relMSE against samples per pixel and against
render time, log-log, one line per variant (mean over repeats)."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(folder):
    rows = defaultdict(lambda: defaultdict(list))
    with open(f"{folder}/convergence.csv") as f:
        for row in csv.DictReader(f):
            rows[row["variant"]][int(row["spp"])].append((float(row["seconds"]), float(row["relmse"])))
    for x_axis, name, label in (("spp", "error_vs_spp", "samples per pixel"), ("time", "error_vs_time", "render time (s)")):
        fig, ax = plt.subplots(figsize=(6, 4.2))
        for variant, by_spp in rows.items():
            spps = sorted(by_spp)
            errors = [sum(e for _, e in by_spp[s]) / len(by_spp[s]) for s in spps]
            # Time as rixconverge's table counts it: the fastest of the repeats.
            xs = spps if x_axis == "spp" else [min(t for t, _ in by_spp[s]) for s in spps]
            ax.loglog(xs, errors, marker="o", label=variant)
        if x_axis == "spp":
            # The Monte Carlo rate: error proportional to 1/spp.
            first = min(rows.values(), key=lambda r: min(r))
            s0 = min(first)
            e0 = sum(e for _, e in first[s0]) / len(first[s0])
            spps = sorted(first)
            ax.loglog(spps, [e0 * s0 / s for s in spps], "k--", linewidth=0.8, label="slope -1")
        ax.set_xlabel(label)
        ax.set_ylabel("relMSE")
        ax.grid(True, which="both", linewidth=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(f"{folder}/{name}.png", dpi=110)
        fig.savefig(f"{folder}/{name}.svg")
        plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1])
