#!/usr/bin/python3
# Plots a willmore-flow time-series.csv: bending energy, area and volume
# errors and the level-set extents against time, into one PNG; with an
# electric field also the flexoelectric and dielectric energies and the
# total (each minus its initial value: the electrolyte term carries a large
# shape-independent part). Runs
# Debian's interpreter with python3-matplotlib (installed by tools/setup.sh):
#   /usr/bin/python3 tools/plot-time-series.py output/willmore-circle-2d/time-series.csv out.png
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
t = [float(r["t"]) for r in rows]
ELECTRIC_TERMS = ("flexoelectric_energy", "membrane_dielectric_energy",
                  "electrolyte_dielectric_energy")
electric = [c for c in ELECTRIC_TERMS if c in rows[0]]
if electric:
    electric.append("total_energy")
fig, ax = plt.subplots(1, 4 if electric else 3, figsize=(20 if electric else 15, 4))
ax[0].plot(t, [float(r["bending_energy"]) for r in rows], "o-", ms=3)
ax[0].set_ylabel("bending energy / kappa")
for name in ("area_error", "volume_error"):
    ax[1].plot(t, [float(r[name]) for r in rows], "o-", ms=3, label=name)
ax[1].set_ylabel("A/A0 - 1, V/V0 - 1")
ax[1].legend()
for name in [c for c in rows[0] if c.startswith("extent_")]:
    ax[2].plot(t, [float(r[name]) for r in rows], "o-", ms=3, label=name)
ax[2].set_ylabel("extent of the zero level set")
ax[2].legend()
if electric:
    for name in ["bending_energy"] + electric:
        v = [float(r[name]) for r in rows]
        ax[3].plot(t, [x - v[0] for x in v], "o-", ms=2, label=name)
    ax[3].set_ylabel("energy - initial value (units of kappa)")
    ax[3].legend(fontsize=7)
for a in ax:
    a.set_xlabel("t")
    a.set_xscale("symlog", linthresh=max(min(t), 1e-12))
    a.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
