#!/usr/bin/python3
# The membrane tension of a vesicle-hydrodynamics run against the sharp
# inextensible membrane of tools/vesicle-shear-bim.py, both in the viscous
# scale mu gamma_dot R_0 (doc/hydrodynamics.md, HD3). The phase field's
# tension is its local multiplier plus the uniform tension of the global
# area multiplier: lambda_i(s) + (2 sqrt2 / 3) lambda_g,i, since
# delta_eps of (H12b) integrates to 1 across the tanh profile and the
# diffuse area of (H12c) to (2 sqrt2 / 3) times the perimeter.
#   /usr/bin/python3 tools/plot-tension-reference.py out.png VISCOUS_SCALE \
#       BIM_PROFILE.csv RUN_DIR STEP [VESICLE]
# VISCOUS_SCALE = mu gamma_dot R_0 of the run (HD3: (1 / Re) 5 0.863 = 863).
# Prints the mean, minimum and maximum of both in the viscous scale.
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 6:
    sys.exit("usage: plot-tension-reference.py OUT.png VISCOUS_SCALE BIM_PROFILE.csv RUN_DIR STEP"
             " [VESICLE]")
target, scale, profile, directory, step = (sys.argv[1], float(sys.argv[2]), sys.argv[3],
                                           sys.argv[4], int(sys.argv[5]))
vesicle = int(sys.argv[6]) if len(sys.argv) > 6 else 1
with open(os.path.join(directory, "time-series.csv")) as f:
    row = [r for r in csv.DictReader(f) if int(r["step"]) == step]
if not row:
    sys.exit(f"step {step} is not in {directory}/time-series.csv")
lambda_g = float(row[0][f"lambda_g_{vesicle}"])
samples = os.path.join(directory, f"tension-{step:05d}.csv")
with open(samples) as f:
    rows = [r for r in csv.DictReader(f) if int(r["vesicle"]) == vesicle and int(r["piece"]) == 0]
s_pf = [float(r["s"]) for r in rows]
length_pf = s_pf[-1] + math.hypot(float(rows[0]["x"]) - float(rows[-1]["x"]),
                                  float(rows[0]["y"]) - float(rows[-1]["y"]))
uniform = 2 * math.sqrt(2) / 3 * lambda_g
sigma_pf = [(float(r["lambda"]) + uniform) / scale for r in rows]
with open(profile) as f:
    bim = list(csv.DictReader(f))
s_bim = [float(r["s"]) for r in bim]
length_bim = s_bim[-1] + math.hypot(float(bim[0]["x"]) - float(bim[-1]["x"]),
                                    float(bim[0]["y"]) - float(bim[-1]["y"]))
sigma_bim = [float(r["sigma_over_viscous_scale"]) for r in bim]

fig, ax = plt.subplots(figsize=(7, 4.2))
ax.plot([s / length_bim for s in s_bim], sigma_bim, "k-", label="sharp, inextensible (BIM)")
ax.plot([s / length_pf for s in s_pf], sigma_pf, label=r"phase field: $\lambda + (2\sqrt{2}/3)\lambda_g$")
ax.plot([s / length_pf for s in s_pf], [float(r["lambda"]) / scale for r in rows], ":",
        label=r"phase field: $\lambda$ alone")
ax.set_xlabel("arc length / perimeter (counter-clockwise from the rightmost point)")
ax.set_ylabel(r"tension / ($\mu\dot\gamma R_0$)")
ax.legend()
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(target, dpi=120)
for name, values in (("sharp", sigma_bim), ("phase field", sigma_pf)):
    print(f"{name}: mean {sum(values) / len(values):.3f}, min {min(values):.3f}, "
          f"max {max(values):.3f} (viscous scale)")
