#!/usr/bin/python3
# One point per case of a sweep (tools/run-sweep.sh): the final value of a
# time-series.csv column, or the ratio of two, against the swept value.
# Runs Debian's interpreter with python3-matplotlib:
#   /usr/bin/python3 tools/plot-sweep.py out.png "sigma_in / sigma_out" \
#       extent_y/extent_x 0.25=output/x/case-0.3_1.2 4=output/x/case-1.2_0.3 ...
# A case named reference=DIR (e.g. a field-free run) is drawn as a dashed
# horizontal line instead of a point.
# Also prints the table it plots (value, final t, steps, the column(s)).
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 5:
    sys.exit("usage: plot-sweep.py OUT.png XLABEL COLUMN[/COLUMN] VALUE=DIR ...")
target, xlabel, column = sys.argv[1:4]
names = column.split("/")
points = []
reference = None


def final_value(directory):
    with open(directory + "/time-series.csv") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit("no rows in " + directory + "/time-series.csv")
    last = rows[-1]
    y = float(last[names[0]])
    if len(names) == 2:
        y /= float(last[names[1]])
    return y, float(last["t"]), len(rows)


for case in sys.argv[4:]:
    value, _, directory = case.partition("=")
    if value == "reference":
        reference = final_value(directory)
        continue
    points.append((float(value),) + final_value(directory))
points.sort()
print("%-10s %-10s %-6s %s" % ("value", "final t", "steps", column))
for x, y, t, n in points:
    print("%-10g %-10.4g %-6d %.5f" % (x, t, n, y))
if reference:
    print("%-10s %-10.4g %-6d %.5f" % ("reference", reference[1], reference[2], reference[0]))
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot([p[0] for p in points], [p[1] for p in points], "o-")
ax.set_xscale("log")
ax.set_xlabel(xlabel)
ax.set_ylabel(column + " (final)")
if reference:
    ax.axhline(reference[0], color="grey", ls="--", label="reference (field-free)")
    ax.legend()
ax.grid(True, which="both", lw=0.3)
fig.tight_layout()
fig.savefig(target, dpi=120)
