#!/usr/bin/env python3
"""Summary of runs from their time-series.csv, as quoted in doc/.

Usage: summarize-run.py <output directory> [<output directory> ...]

Per run: steps, retried steps (column rejected_steps), solves (column
multiplier_iterations of implicit global multipliers, else one per step),
Newton and Krylov iterations in all, the range of dt, the largest relative
area and volume errors of every vesicle, and the last row's time, centroids,
inclination angles, global multipliers and energies (the columns present).
Plain Python: no numpy needed.
"""
import csv
import os
import sys


def read(directory):
    path = os.path.join(directory, "time-series.csv")
    if not os.path.isfile(path):
        sys.exit("no time-series.csv in " + directory)
    with open(path) as f:
        rows = [r for r in csv.DictReader(f)]
    if not rows:
        sys.exit("time-series.csv of " + directory + " has no rows")
    return rows


def column_sum(rows, name, default_per_row=None):
    if name not in rows[0]:
        return None if default_per_row is None else default_per_row * len(rows)
    return sum(float(r[name]) for r in rows)


def summarize(directory):
    rows = read(directory)
    names = rows[0].keys()
    lines = [directory]
    steps = len(rows)
    retried = column_sum(rows, "rejected_steps")
    solves = column_sum(rows, "multiplier_iterations", 1)
    newton = column_sum(rows, "newton_iterations")
    krylov = column_sum(rows, "krylov_iterations")
    counts = "  steps %d" % steps
    if retried is not None:
        counts += " (%d retried)" % retried
    counts += ", solves %d" % solves
    if newton is not None:
        counts += ", Newton %d" % newton
    if krylov is not None:
        counts += ", Krylov %d" % krylov
    lines.append(counts)
    if "dt" in names:
        dts = [float(r["dt"]) for r in rows]
        lines.append("  dt %.3g to %.3g" % (min(dts), max(dts)))
    errors = []
    for name in names:
        if name.startswith("area_error_") or name.startswith("volume_error_"):
            largest = max(abs(float(r[name])) for r in rows)
            errors.append("%s %.2e" % (name, largest))
    if errors:
        lines.append("  largest |error|: " + ", ".join(errors))
    last = rows[-1]
    shown = [n for n in names
             if n == "t" or n.split("_")[0] in ("x", "y", "theta")
             or n.startswith("lambda_g_") or n.endswith("_energy")]
    lines.append("  last row: " + ", ".join(
        "%s %.6g" % (n, float(last[n])) for n in shown))
    return "\n".join(lines)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    print("\n".join(summarize(d) for d in sys.argv[1:]))
