#!/usr/bin/python3
"""Figure of the 2D electric resolution study (doc/validation.md, section 5).

Left: |E_DM| (membrane dielectric energy (E7), first row of each run's
time-series.csv) against eps, with the 1/eps^2 law through eps = 1.
Right: the aspect ratio extent_y / extent_x over time of each run.

usage: /usr/bin/python3 tools/plot-electric-resolution.py OUT.png \
         --initial EPS:LABEL=DIR ... --runs LABEL=DIR ...
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(directory):
    with open(directory + "/time-series.csv") as f:
        return list(csv.DictReader(f))


def main():
    if len(sys.argv) < 4 or "--runs" not in sys.argv:
        sys.exit(__doc__)
    out = sys.argv[1]
    split = sys.argv.index("--runs")
    initial = sys.argv[3:split] if sys.argv[2] == "--initial" else []
    runs = sys.argv[split + 1:]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))

    series = {}
    for item in initial:
        eps_label, directory = item.split("=", 1)
        eps, label = eps_label.split(":", 1)
        series.setdefault(label, []).append(
            (float(eps), -float(rows(directory)[0]["membrane_dielectric_energy"])))
    for label, points in series.items():
        points.sort()
        left.loglog([p[0] for p in points], [p[1] for p in points], "o-",
                    label=label)
    if series:
        reference = max(max(p[1] for p in pts if p[0] == 1.0)
                        for pts in series.values() if any(p[0] == 1.0 for p in pts))
        eps = [0.25, 1.0]
        left.loglog(eps, [reference / e**2 for e in eps], "k--",
                    label="1 / eps^2")
    left.set_xlabel("eps (um)")
    left.set_ylabel("-E_DM at the initial shape (kappa)")
    left.legend()
    left.grid(True, which="both", alpha=0.3)

    for item in runs:
        label, directory = item.split("=", 1)
        r = rows(directory)
        right.plot([float(x["t"]) for x in r],
                   [float(x["extent_y"]) / float(x["extent_x"]) for x in r],
                   label=label)
    right.set_xscale("symlog", linthresh=1.0)
    right.set_xlabel("t")
    right.set_ylabel("extent_y / extent_x (field along y)")
    right.legend(fontsize=8)
    right.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
