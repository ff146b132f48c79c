#!/usr/bin/python3
"""The 2D bending-flow runs against the sharp-interface minimiser (issue 16,
item 1): for each output directory, the stationary (last) row of its
time-series.csv, and the sharp minimiser of tools/sharp-vesicle.py at the
reduced area and length measured on the run's zero level set.

  /usr/bin/python3 tools/sharp-limit-table.py DIR...

Prints a Markdown table: eps, h, E_B / kappa, extents through the centre,
zero-level-set length, reduced area, and the sharp E_B and extents of a
curve with that reduced area and length.
"""
import csv
import importlib.util
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location(
    "sharp_vesicle", os.path.join(here, "sharp-vesicle.py"))
sharp = importlib.util.module_from_spec(spec)
spec.loader.exec_module(sharp)


def setting(prm, name):
    """Last value of 'set NAME = ...' in a parameter file."""
    value = None
    for line in open(prm):
        m = re.match(r"\s*set\s+%s\s*=\s*(.*)" % re.escape(name), line)
        if m:
            value = m.group(1).split("#")[0].strip()
    return value


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    print("| eps | h | steps | E_B/kappa | extents x, y | zero-set length | "
          "reduced area | sharp E_B/kappa | sharp extents |")
    print("|---|---|---|---|---|---|---|---|---|")
    for d in sys.argv[1:]:
        rows = list(csv.DictReader(open(os.path.join(d, "time-series.csv"))))
        if not rows or "contour_reduced_area" not in rows[-1]:
            sys.exit("sharp-limit-table: %s: no 2D time series with the "
                     "zero-level-set columns" % d)
        last = rows[-1]
        prm = [f for f in os.listdir(d) if f.endswith(".prm")]
        eps = h = float("nan")
        if prm:
            p = os.path.join(d, prm[0])
            lo = [float(x) for x in setting(p, "Lower corner").split(",")]
            hi = [float(x) for x in setting(p, "Upper corner").split(",")]
            n = [int(x) for x in setting(p, "Elements").split(",")]
            h = (hi[0] - lo[0]) / n[0]
            eps = float(setting(p, "Epsilon over h")) * h
        chi = float(last["contour_reduced_area"])
        length = float(last["contour_length"])
        ref = sharp.solve_curve(16, chi)
        scale = length / (2 * math.pi)
        print("| %.4g | %.4g | %s | %.4f | %.4f, %.4f | %.5f | %.5f | %.4f | "
              "%.4f, %.4f |"
              % (eps, h, last["step"], float(last["bending_energy"]),
                 float(last["extent_x"]), float(last["extent_y"]), length,
                 chi, ref["energy"] / scale, ref["extent_long"] * scale,
                 ref["extent_short"] * scale))


if __name__ == "__main__":
    main()
