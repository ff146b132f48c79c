#!/usr/bin/python3
# Several runs on common axes: one panel per time-series.csv column against
# t, one curve per run. Used to set a field run beside its field-free
# control (doc/electromechanics.md, 3D). Runs Debian's interpreter with
# python3-matplotlib (installed by tools/setup.sh):
#   /usr/bin/python3 tools/plot-runs.py out.png extent_x,extent_y,bending_energy \
#       "no field=output/field-free-3d-deflated" "50 kV/m=output/electric-field-sweep-3d-deflated"
# COLUMN:log draws that panel on a logarithmic axis. A run keeps its colour
# in every panel. A column missing from a run's file (older runs) is left
# out of its panel;
# nan entries (rows written before a column existed) are not drawn.
# Also prints each run's last row of the chosen columns.
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 4:
    sys.exit("usage: plot-runs.py OUT.png COLUMN[,COLUMN...] LABEL=DIR ...")
target, runs = sys.argv[1], sys.argv[3:]
columns = [c.split(":")[0] for c in sys.argv[2].split(",")]
logarithmic = [c.endswith(":log") for c in sys.argv[2].split(",")]
fig, axes = plt.subplots(1, len(columns), figsize=(5 * len(columns), 4), squeeze=False)
for number, run in enumerate(runs):
    label, _, directory = run.partition("=")
    if not directory:
        sys.exit("a run is LABEL=DIR, got '" + run + "'")
    name = os.path.join(directory, "time-series.csv")
    if not os.path.exists(name):
        sys.exit("no time-series.csv in " + directory)
    rows = list(csv.DictReader(open(name)))
    if not rows:
        sys.exit(name + " has no rows")
    last = []
    for ax, column in zip(axes[0], columns):
        if column not in rows[0]:
            last.append(column + "=-")
            continue
        points = [(float(r["t"]), float(r[column])) for r in rows]
        points = [p for p in points if not math.isnan(p[1])]
        ax.plot([p[0] for p in points], [p[1] for p in points], "-", label=label,
                color="C%d" % (number % 10))
        last.append("%s=%.6g" % (column, points[-1][1]) if points else column + "=nan")
    print("%-20s t=%-10.5g steps=%-5s %s" % (label, float(rows[-1]["t"]), rows[-1]["step"],
                                             " ".join(last)))
for ax, column, log in zip(axes[0], columns, logarithmic):
    if log:
        ax.set_yscale("log")
    ax.set_xlabel("t (normalised)")
    ax.set_ylabel(column)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(target, dpi=110)
