#!/usr/bin/env python3
"""The zero level sets of a 2D vesicle run: enclosed area, length and reduced
area 4 pi A / P^2 per vesicle, from the membrane samples tension-<step>.csv
(the polygons of the zero level set that the program writes with 'Write
membrane samples = true'), at the first and the last sample step of each run
directory, and the relative change of A and P between them.

Usage: zero-set.py <output directory> [<output directory> ...]

Each closed piece of a vesicle's zero set is a polygon (its samples in
order); A is the shoelace area, P the polygon length, summed over the
pieces. The polygon vertices lie on the cell faces crossed by the zero set
(about one per element), so A and P carry the chord error of that polygon,
O(h^2) relative. Plain Python: no numpy needed.
"""
import csv
import glob
import math
import os
import sys


def measure(path):
    pieces = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            key = (row["vesicle"], row["piece"])
            pieces.setdefault(key, []).append((float(row["x"]),
                                               float(row["y"])))
    result = {}
    for (vesicle, _), points in pieces.items():
        twice_area, length = 0.0, 0.0
        for i, (x0, y0) in enumerate(points):
            x1, y1 = points[(i + 1) % len(points)]
            twice_area += x0 * y1 - x1 * y0
            length += math.hypot(x1 - x0, y1 - y0)
        area, total = result.get(vesicle, (0.0, 0.0))
        result[vesicle] = (area + abs(twice_area) / 2, total + length)
    return result


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for directory in sys.argv[1:]:
        files = sorted(glob.glob(os.path.join(directory, "tension-*.csv")))
        if not files:
            sys.exit("no tension-*.csv in " + directory +
                     " (set Write membrane samples = true)")
        if len(files) == 1:
            print("%s: one sample step only (%s): no change to report" %
                  (directory, os.path.basename(files[0])))
        first, last = measure(files[0]), measure(files[-1])
        for vesicle in sorted(first, key=int):
            steps = [(files[0], first)]
            if len(files) > 1:
                steps.append((files[-1], last))
            for name, values in steps:
                area, length = values.get(vesicle, (0.0, 0.0))
                reduced = 4 * math.pi * area / length**2 if length else 0
                print("%s %s vesicle %s: A %.5f P %.5f reduced area %.5f" %
                      (directory, os.path.basename(name), vesicle, area,
                       length, reduced))
            if vesicle in last and len(files) > 1:
                (a0, p0), (a1, p1) = first[vesicle], last[vesicle]
                print("%s vesicle %s: A changed by %+.3e, P by %+.3e "
                      "(relative)" % (directory, vesicle, a1 / a0 - 1,
                                      p1 / p0 - 1))


if __name__ == "__main__":
    main()
