#!/usr/bin/python3
# Plots a study's convergence.csv (error norms against h, one curve per
# degree, log-log) into a PNG. Runs Debian's own interpreter with
# python3-matplotlib (installed by tools/setup.sh):
#   /usr/bin/python3 tools/plot-convergence.py output/plate-with-hole/convergence.csv out.png [norm ...]
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
norms = sys.argv[3:] or [c for c in rows[0] if c not in ("degree", "cells", "dofs", "h")]
fig, axes = plt.subplots(1, len(norms), figsize=(5 * len(norms), 4), squeeze=False)
for ax, norm in zip(axes[0], norms):
    for p in sorted({int(r["degree"]) for r in rows}):
        sel = [r for r in rows if int(r["degree"]) == p]
        ax.loglog([float(r["h"]) for r in sel], [float(r[norm]) for r in sel], "o-", label=f"p = {p}")
    ax.set_xlabel("h")
    ax.set_ylabel(norm + " error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
