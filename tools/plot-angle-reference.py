#!/usr/bin/python3
# The inclination angles theta_i(t) of a vesicle-hydrodynamics run in shear
# (spec 4.12) against the sharp-interface reference of
# tools/vesicle-shear-bim.py (unbounded shear, equal viscosities), in the
# strain gamma_dot t, with the reference's steady angle as a line. Used for
# HD3 in doc/hydrodynamics.md. Several output directories are read in order
# and joined by step (a run continued from a checkpoint into a new
# directory); a later directory's rows replace an earlier one's.
#   /usr/bin/python3 tools/plot-angle-reference.py out.png SHEAR_RATE \
#       BIM_HISTORY.csv[:LABEL[:STRAIN_FACTOR]] [...] -- DIR [DIR ...]
# A reference's strain is multiplied by STRAIN_FACTOR (default 1): a run of
# the reference with the local gradient of the study's flow (shear rate
# gamma_local) is drawn against the study's strain with the factor
# SHEAR_RATE / gamma_local. Also prints the last angles and their change
# over the last 10 % of the run.
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 6 or "--" not in sys.argv[4:]:
    sys.exit("usage: plot-angle-reference.py OUT.png SHEAR_RATE BIM_HISTORY.csv[:LABEL[:FACTOR]]"
             " [...] -- DIR [DIR ...]")
target, shear_rate = sys.argv[1], float(sys.argv[2])
separator = sys.argv.index("--", 3)
references, directories = sys.argv[3:separator], sys.argv[separator + 1:]
rows = {}
for directory in directories:
    path = os.path.join(directory, "time-series.csv")
    if not os.path.exists(path):
        sys.exit("no time-series.csv in " + directory)
    with open(path) as f:
        for r in csv.DictReader(f):
            rows[int(r["step"])] = r
series = [rows[k] for k in sorted(rows)]
vesicles = sorted(int(k.split("_")[1]) for k in series[0] if k.startswith("theta_"))
strain = [shear_rate * float(r["t"]) for r in series]
curves = []
for spec in references:
    parts = spec.split(":")
    label = parts[1] if len(parts) > 1 else "sharp interface, unbounded shear (BIM)"
    factor = float(parts[2]) if len(parts) > 2 else 1.0
    with open(parts[0]) as f:
        curves.append((label, [(factor * float(r["gamma_dot_t"]), float(r["theta"]))
                               for r in csv.DictReader(f)]))

fig, ax = plt.subplots(figsize=(7, 4.2))
for i in vesicles:
    ax.plot(strain, [float(r[f"theta_{i}"]) for r in series], label=f"phase field, vesicle {i}",
            lw=2 if i == vesicles[0] else 1, ls="-" if i == vesicles[0] else "--")
for (label, bim), style in zip(curves, ["k:", "k-.", "k--"]):
    ax.plot([t for t, _ in bim], [a for _, a in bim], style, lw=1, label=label)
    ax.axhline(bim[-1][1], color="k", lw=0.4)
ax.set_xlabel(r"$\dot\gamma\, t$")
ax.set_ylabel(r"$\theta$ (rad)")
ax.set_xlim(0, max(max(strain), 1.0))
ax.legend()
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(target, dpi=120)

last = series[-1]
tail = series[int(0.9 * (len(series) - 1))]
for i in vesicles:
    a, b = float(last[f"theta_{i}"]), float(tail[f"theta_{i}"])
    print(f"vesicle {i}: theta = {a:.4f} rad = {a / math.pi:.4f} pi at gamma_dot t = "
          f"{strain[-1]:.2f}; change over the last 10 %: {a - b:+.2e}")
for label, bim in curves:
    print(f"{label}: steady theta = {bim[-1][1]:.4f} rad = {bim[-1][1] / math.pi:.4f} pi")
