#!/usr/bin/python3
# The result figure of a vesicle-hydrodynamics run (spec 4.12), from its
# output directory: (a) the zero level sets of all vesicles at a few steps
# with the centroid trajectories, (b) the membrane tension lambda_i and the
# pressure p along each membrane (arc length) at the last sampled step,
# (c) the largest tension on each membrane at every sampled step, (d) the
# inclination angles, (e) the relative area and volume errors, (f) the
# energies, (g) the global multipliers and (h) the separation of each pair
# of vesicles (spec 4.12: horizontal and vertical distance of the
# centroids, and the smallest distance between their zero level sets at
# the sampled steps) against t. Reads tension-<step>.csv (the membrane
# samples) and time-series.csv. Runs Debian's interpreter with
# python3-matplotlib (installed by tools/setup.sh):
#   /usr/bin/python3 tools/plot-vesicles.py out.png output/hd4b-doublet-shear [STEP,STEP,...]
# Without steps: the first, the last and up to three sampled steps between.
# A run continued from a checkpoint in another directory: give the parts in
# order joined by '+' (DIR1+DIR2); the rows of a later part replace those of
# the earlier ones from its first step on.
import csv
import glob
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 3:
    sys.exit("usage: plot-vesicles.py OUT.png DIR[+DIR...] [STEP,STEP,...]")
target, directories = sys.argv[1], sys.argv[2].split("+")
samples = {}
series = []
for directory in directories:
    for f in glob.glob(os.path.join(directory, "tension-*.csv")):
        samples[int(re.search(r"tension-(\d+)\.csv$", f).group(1))] = f
    series_file = os.path.join(directory, "time-series.csv")
    if os.path.exists(series_file):
        rows = list(csv.DictReader(open(series_file)))
        if rows:
            first = int(float(rows[0]["step"]))
            series = [r for r in series if int(float(r["step"])) < first] + rows
if not samples:
    sys.exit("no tension-*.csv in " + sys.argv[2] +
             " (set 'Write membrane samples = true' and a VTU interval)")
steps = sorted(samples)
if len(sys.argv) > 3:
    chosen = [int(s) for s in sys.argv[3].split(",")]
    missing = [s for s in chosen if s not in samples]
    if missing:
        sys.exit("no tension file for step(s) " + ", ".join(map(str, missing)))
else:
    k = len(steps)
    chosen = sorted({steps[round(i * (k - 1) / 4)] for i in range(5)})
n = 0
while series and ("x_" + str(n + 1)) in series[0]:
    n += 1


def read_samples(name):
    """{(vesicle, piece): columns} of one tension file."""
    pieces = {}
    for row in csv.DictReader(open(name)):
        key = (int(row["vesicle"]), int(row["piece"]))
        p = pieces.setdefault(key, {c: [] for c in ("s", "x", "y", "lambda", "p")})
        for c in p:
            p[c].append(float(row[c]))
    return pieces


def time_of(step):
    for row in series:
        if int(float(row["step"])) == step:
            return float(row["t"])
    return 0.0 if step == 0 else math.nan


def gap(a, b):
    """Smallest distance between two sampled closed curves (points)."""
    best = math.inf
    for xa, ya in zip(a["x"], a["y"]):
        for xb, yb in zip(b["x"], b["y"]):
            best = min(best, (xa - xb) ** 2 + (ya - yb) ** 2)
    return math.sqrt(best)


def membranes(pieces):
    """{vesicle: all its samples} (the pieces of one vesicle joined)."""
    joined = {}
    for (vesicle, piece), p in sorted(pieces.items()):
        j = joined.setdefault(vesicle, {c: [] for c in p})
        for c in p:
            j[c] += p[c]
    return joined


fig, ax = plt.subplots(2, 4, figsize=(21, 9))
colours = plt.cm.viridis([i / max(len(chosen) - 1, 1) for i in range(len(chosen))])
for colour, step in zip(colours, chosen):
    for (vesicle, piece), p in sorted(read_samples(samples[step]).items()):
        label = f"t = {time_of(step):.3g}" if (vesicle, piece) == (1, 0) else None
        ax[0, 0].plot(p["x"], p["y"], color=colour, lw=1.2, label=label)
for i in range(1, n + 1):
    ax[0, 0].plot([float(r[f"x_{i}"]) for r in series],
                  [float(r[f"y_{i}"]) for r in series], "--", color="grey", lw=0.8)
ax[0, 0].set_aspect("equal")
# A 3D run samples the section of each membrane by the plane z = z_i.
three_d = bool(series) and "z_1" in series[0]
ax[0, 0].set_title("zero level sets and centroid paths"
                   + (" (sections z = z_i)" if three_d else ""))
ax[0, 0].legend(fontsize=8)

last = read_samples(samples[steps[-1]])
for (vesicle, piece), p in sorted(last.items()):
    if piece == 0:
        ax[0, 1].plot(p["s"], p["lambda"], label=f"lambda_{vesicle}")
        ax[0, 1].plot(p["s"], p["p"], ":", label=f"p on membrane {vesicle}")
ax[0, 1].set_xlabel("arc length s (counter-clockwise from the rightmost point)")
ax[0, 1].set_title(f"tension and pressure, t = {time_of(steps[-1]):.3g}")
ax[0, 1].legend(fontsize=8)

# Peak tension and gaps at every sampled step.
sampled_t, peak, gaps = [], {}, {}
for step in steps:
    m = membranes(read_samples(samples[step]))
    sampled_t.append(time_of(step))
    for i in range(1, n + 1):
        peak.setdefault(i, []).append(max(m[i]["lambda"]) if i in m else math.nan)
        for j in range(i + 1, n + 1):
            gaps.setdefault((i, j), []).append(
                gap(m[i], m[j]) if i in m and j in m else math.nan)
for i in range(1, n + 1):
    ax[0, 2].plot(sampled_t, peak[i], "o-", ms=3, label=f"max lambda_{i}")
ax[0, 2].set_title("largest membrane tension (sampled steps)")

t = [float(r["t"]) for r in series]
for i in range(1, n + 1):
    ax[0, 3].plot(t, [float(r[f"theta_{i}"]) for r in series], label=f"theta_{i}")
    ax[1, 0].plot(t, [float(r[f"area_error_{i}"]) for r in series], label=f"area {i}")
    ax[1, 0].plot(t, [float(r[f"volume_error_{i}"]) for r in series], ":",
                  label=f"volume {i}")
ax[0, 3].set_title("inclination angle (rad)")
ax[1, 0].set_title("relative area and volume errors")
for c in ("kinetic_energy", "bending_energy", "interaction_energy"):
    if series and c in series[0]:
        ax[1, 1].plot(t, [float(r[c]) for r in series], label=c.replace("_", " "))
ax[1, 1].set_yscale("symlog", linthresh=1e-8)
ax[1, 1].set_title("energies")
if series and "lambda_g_1" in series[0]:
    for i in range(1, n + 1):
        ax[1, 2].plot(t, [float(r[f"lambda_g_{i}"]) for r in series], label=f"lambda_g_{i}")
        ax[1, 2].plot(t, [float(r[f"lambda_v_{i}"]) for r in series], ":",
                      label=f"lambda_v_{i}")
ax[1, 2].set_title("global multipliers (H13)")
for i in range(1, n + 1):
    for j in range(i + 1, n + 1):
        ax[1, 3].plot(t, [float(r[f"x_{j}"]) - float(r[f"x_{i}"]) for r in series],
                      label=f"x_{j} - x_{i}")
        ax[1, 3].plot(t, [float(r[f"y_{j}"]) - float(r[f"y_{i}"]) for r in series],
                      "--", label=f"y_{j} - y_{i}")
        ax[1, 3].plot(sampled_t, gaps[(i, j)], "o", ms=3,
                      label=f"gap between membranes {i}, {j}")
ax[1, 3].set_title("separation of the centroids; gap of the zero level sets"
                   if n > 1 else "(one vesicle: no separation)")
for a in (ax[0, 2], ax[0, 3], ax[1, 0], ax[1, 1], ax[1, 2], ax[1, 3]):
    a.set_xlabel("t")
    if a.get_legend_handles_labels()[0]:
        a.legend(fontsize=8)
fig.tight_layout()
fig.savefig(target, dpi=100)
print("wrote", target, "from", len(chosen), "sampled steps of", sys.argv[2])
for (i, j), g in gaps.items():
    finite = [(v, tt) for v, tt in zip(g, sampled_t) if not math.isnan(v)]
    if finite:
        v, tt = min(finite)
        print(f"smallest sampled gap between membranes {i} and {j}: {v:.4g} at t = {tt:.4g}")
