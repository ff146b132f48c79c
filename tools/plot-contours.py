#!/usr/bin/python3
# Zero-level contours of phi in the plane containing the field axis (spec
# 3.11), one curve per section-*.csv that the willmore-flow study writes
# with every VTU output, coloured from the first (light) to the last (dark)
# output. Runs Debian's interpreter with python3-matplotlib:
#   /usr/bin/python3 tools/plot-contours.py output/electric-field-2d contours.png
#   /usr/bin/python3 tools/plot-contours.py DIR1 DIR2 ... out.png   (last
#       section of each directory, labelled with its name: a sweep)
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_section(name):
    with open(name) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array(rows[1:], dtype=float)
    a, b = np.unique(data[:, 0]), np.unique(data[:, 1])
    phi = data[:, 2].reshape(len(b), len(a))
    return header, a, b, phi


if len(sys.argv) < 3:
    sys.exit("usage: plot-contours.py OUTPUT_DIR [OUTPUT_DIR ...] out.png")
dirs, target = sys.argv[1:-1], sys.argv[-1]
fig, ax = plt.subplots(figsize=(7, 6))
if len(dirs) == 1:
    files = sorted(glob.glob(os.path.join(dirs[0], "section-*.csv")))
    if not files:
        sys.exit("no section-*.csv in " + dirs[0] + " (set 'VTU interval' > 0)")
    cmap = plt.get_cmap("viridis")
    for i, name in enumerate(files):
        header, a, b, phi = read_section(name)
        step = int(os.path.basename(name)[8:13])
        ax.contour(a, b, phi, levels=[0], colors=[cmap(i / max(1, len(files) - 1))])
        ax.plot([], [], color=cmap(i / max(1, len(files) - 1)), label="step %d" % step)
    ax.set_title(dirs[0])
else:
    cmap = plt.get_cmap("coolwarm")
    for i, d in enumerate(dirs):
        files = sorted(glob.glob(os.path.join(d, "section-*.csv")))
        if not files:
            sys.exit("no section-*.csv in " + d)
        header, a, b, phi = read_section(files[-1])
        colour = cmap(i / max(1, len(dirs) - 1))
        ax.contour(a, b, phi, levels=[0], colors=[colour])
        ax.plot([], [], color=colour, label=os.path.basename(d.rstrip("/")))
ax.set_xlabel(header[0])
ax.set_ylabel(header[1] + " (field axis when the field is along " + header[1] + ")")
ax.set_aspect("equal")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=7, loc="upper right")
fig.tight_layout()
fig.savefig(target, dpi=100)
