#!/usr/bin/python3
# Zero-level contours of phi in the plane containing the field axis (spec
# 3.11), one curve per section-*.csv that the willmore-flow study writes
# with every VTU output, coloured from the first (light) to the last (dark)
# output. Runs Debian's interpreter with python3-matplotlib:
#   /usr/bin/python3 tools/plot-contours.py output/electric-field-2d contours.png
#   /usr/bin/python3 tools/plot-contours.py DIR1 DIR2 ... out.png   (last
#       section of each directory, labelled with its name: a sweep)
#   /usr/bin/python3 tools/plot-contours.py "no field, t = 20=output/a@60" \
#       "50 kV/m, t = 20=output/b@80" out.png
#       (LABEL=DIR@STEP: the section written at that step, with a label;
#       runs compared at equal times)
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
# Bounding box of the inside (phi < 0) over all drawn sections: the plot
# is cropped to it, so that sub-micron differences stay visible in a box
# several times the vesicle's size.
box = [np.inf, -np.inf, np.inf, -np.inf]


def grow_box(a, b, phi):
    inside = phi < 0
    if inside.any():
        A, B = np.meshgrid(a, b)
        box[0], box[1] = min(box[0], A[inside].min()), max(box[1], A[inside].max())
        box[2], box[3] = min(box[2], B[inside].min()), max(box[3], B[inside].max())


if len(dirs) == 1:
    files = sorted(glob.glob(os.path.join(dirs[0], "section-*.csv")))
    if not files:
        sys.exit("no section-*.csv in " + dirs[0] + " (set 'VTU interval' > 0)")
    cmap = plt.get_cmap("viridis")
    for i, name in enumerate(files):
        header, a, b, phi = read_section(name)
        step = int(os.path.basename(name)[8:13])
        grow_box(a, b, phi)
        ax.contour(a, b, phi, levels=[0], colors=[cmap(i / max(1, len(files) - 1))])
        ax.plot([], [], color=cmap(i / max(1, len(files) - 1)), label="step %d" % step)
    ax.set_title(dirs[0])
else:
    # An ordered sweep (plain directories) in a diverging map; labelled
    # runs (LABEL=DIR@STEP) in distinct colours.
    labelled = any("=" in entry for entry in dirs)
    cmap = plt.get_cmap("tab10" if labelled else "coolwarm")
    for i, entry in enumerate(dirs):
        label, _, d = entry.rpartition("=")
        d, _, step = d.partition("@")
        label = label or os.path.basename(d.rstrip("/"))
        if step:
            name = os.path.join(d, "section-%05d.csv" % int(step))
            if not os.path.exists(name):
                sys.exit("no " + name + " (sections are written every 'VTU interval' steps)")
        else:
            files = sorted(glob.glob(os.path.join(d, "section-*.csv")))
            if not files:
                sys.exit("no section-*.csv in " + d)
            name = files[-1]
        header, a, b, phi = read_section(name)
        colour = cmap(i % 10) if labelled else cmap(i / max(1, len(dirs) - 1))
        grow_box(a, b, phi)
        ax.contour(a, b, phi, levels=[0], colors=[colour])
        ax.plot([], [], color=colour, label=label)
ax.set_xlabel(header[0])
ax.set_ylabel(header[1] + " (field axis when the field is along " + header[1] + ")")
if np.isfinite(box).all():
    margin = 0.1 * max(box[1] - box[0], box[3] - box[2])
    ax.set_xlim(max(a[0], box[0] - margin), min(a[-1], box[1] + margin))
    ax.set_ylim(max(b[0], box[2] - margin), min(b[-1], box[3] + margin))
ax.set_aspect("equal")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=7, loc="center")  # inside the vesicle, where no curve runs
fig.tight_layout()
fig.savefig(target, dpi=100)
