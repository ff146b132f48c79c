#!/usr/bin/python3
"""Sharp-interface reference for the bending flow (issue 16, item 1).

Minimises the Helfrich bending energy (spec 3.1, H_sp = 0) of a closed
membrane at fixed area and enclosed volume, independently of the phase
field:

  curve         2D: a closed polygon of N equal segments (tangent angles the
                unknowns), length 2 pi, enclosed area chi pi (chi = 4 pi A /
                L^2 the reduced area); E_B / kappa = 1/2 int k^2 ds.
  axisymmetric  3D: the generating curve of a surface of revolution from
                pole to pole, N equal segments, area 4 pi, volume v 4 pi / 3
                (v the reduced volume); E_B / (8 pi kappa) with E_B =
                kappa/2 int (c1 + c2)^2 dA, c1 = dpsi/ds, c2 = sin(psi)/r.

Both are solved by SLSQP (scipy) from a spheroid (ellipse) of the same
reduced volume (area), at N, 2N and 4N segments, and extrapolated to
N -> infinity with the observed order (Richardson). Output: one line per
solve, then the extrapolated energy, extents and (3D) neck/bulb ratio.

  tools/sharp-vesicle.py curve --reduced-area 0.5367
  tools/sharp-vesicle.py axisymmetric --reduced-volume 0.69 --branch prolate
  tools/sharp-vesicle.py branches --csv output/sharp-branches.csv

Energies are scale-free in 3D; in 2D E_B scales as 1/length: a curve of
perimeter P has E_B = (2 pi / P) times the value printed.
"""
import argparse
import math
import sys

import numpy as np
from scipy.optimize import minimize


# --------------------------------------------------------------------------
# The tangent angle as a truncated Fourier series of the arc length; the
# integrals by the midpoint rule on a fine grid (cumulative sums for the
# positions), so the only discretisation parameters are the number of modes
# M (spectral convergence for smooth shapes) and the grid (second order,
# 1e-8 here).
GRID = 8000


class Curve:
    """2D closed curve of length 2 pi, symmetric about both axes (as the
    relaxed ellipse is), starting at the bottom on the symmetry axis:
    theta(s) = s + sum_j b_j sin(2 j s), j = 1..M (odd in s: mirror symmetry
    about the vertical axis; period pi: about the horizontal one). The
    symmetry also removes the sliding of the start point along the curve."""

    def __init__(self, modes, reduced_area):
        self.modes = modes
        self.area = reduced_area * math.pi
        self.s = (np.arange(GRID) + 0.5) * 2 * math.pi / GRID
        self.ds = 2 * math.pi / GRID
        k = 2 * np.arange(1, modes + 1)
        self.cos = np.cos(np.outer(k, self.s))
        self.sin = np.sin(np.outer(k, self.s))
        self.k = k

    def theta(self, b):
        return self.s + b @ self.sin

    def curvature(self, b):
        return 1 + (b * self.k) @ self.cos

    def positions(self, b):
        t = self.theta(b)
        return np.cumsum(np.cos(t)) * self.ds, np.cumsum(np.sin(t)) * self.ds

    def energy(self, b):
        return 0.5 * np.sum(self.curvature(b) ** 2) * self.ds

    def enclosed_area(self, b):
        t = self.theta(b)
        x, _ = self.positions(b)
        return np.sum(x * np.sin(t)) * self.ds  # int x dy

    def constraints(self):
        # closure holds by the symmetry; only the area is constrained
        return [{"type": "eq",
                 "fun": lambda b: self.enclosed_area(b) - self.area}]

    def ellipse_guess(self):
        """Coefficients of the tangent angle of the ellipse of this reduced
        area (long axis along x) at equal arc length from its bottom."""
        aspect = ellipse_aspect_for_reduced_area(self.area / math.pi)
        p = np.linspace(-math.pi / 2, 1.5 * math.pi, 40001)
        x, y = aspect * np.cos(p), np.sin(p)
        arc = np.concatenate(([0], np.cumsum(np.hypot(np.diff(x),
                                                      np.diff(y)))))
        tangent = np.unwrap(np.arctan2(np.gradient(y), np.gradient(x)))
        t = np.interp(self.s / (2 * math.pi) * arc[-1], arc, tangent)
        return 2 * (self.sin @ (t - self.s)) * self.ds / (2 * math.pi)

    def extents(self, b):
        """Extents along the two symmetry axes through the centre (as the
        phase-field runs measure them: a waist counts, not the bulbs)."""
        x, y = self.positions(b)
        n = len(x)
        return abs(x[3 * n // 4] - x[n // 4]), abs(y[n // 2] - y[0])


def ellipse_reduced_area(aspect):
    p = np.linspace(0, 2 * math.pi, 200001)
    perimeter = np.sum(np.hypot(np.diff(aspect * np.cos(p)),
                                np.diff(np.sin(p))))
    return 4 * math.pi * math.pi * aspect / perimeter**2


def ellipse_aspect_for_reduced_area(chi):
    lo, hi = 1.0, 100.0
    for _ in range(100):
        mid = math.sqrt(lo * hi)
        if ellipse_reduced_area(mid) > chi:
            lo = mid
        else:
            hi = mid
    return math.sqrt(lo * hi)


def solve_curve(modes, reduced_area, guess=None):
    c = Curve(modes, reduced_area)
    u0 = c.ellipse_guess() if guess is None else extend(guess, modes, 1)
    r = minimize(c.energy, u0, method="SLSQP", constraints=c.constraints(),
                 options={"maxiter": 1000, "ftol": 1e-12})
    check(r, "curve", modes)
    ex, ey = c.extents(r.x)
    return {"modes": modes, "energy": c.energy(r.x),
            "extent_long": max(ex, ey), "extent_short": min(ex, ey),
            "solution": r.x}


class Axisymmetric:
    """Generating curve from the south pole (r = 0) to the north pole,
    length L: psi(s) = pi s / L + sum_k a_k sin(k pi s / L), k = 1..M
    (psi(0) = 0 and psi(L) = pi, regular poles); unknowns (a, L). Up-down
    symmetric shapes (prolate, oblate about the equator) have only even k;
    all k are kept so that asymmetric minimisers are not excluded."""

    def __init__(self, modes, reduced_volume):
        self.modes = modes
        self.area = 4 * math.pi
        self.volume = reduced_volume * 4 * math.pi / 3
        self.x = (np.arange(GRID) + 0.5) / GRID  # s / L
        k = np.arange(1, modes + 1)
        self.sin = np.sin(np.outer(k, math.pi * self.x))
        self.cos = np.cos(np.outer(k, math.pi * self.x))
        self.k = k

    def fields(self, u):
        a, length = u[:-1], u[-1]
        psi = math.pi * self.x + a @ self.sin
        dpsi = (math.pi + (a * self.k * math.pi) @ self.cos) / length
        ds = length / GRID
        # r, z at the grid midpoints: the cumulative sum up to the previous
        # point plus half a step
        cr, sr = np.cos(psi) * ds, np.sin(psi) * ds
        r = np.cumsum(cr) - 0.5 * cr
        z = np.cumsum(sr) - 0.5 * sr
        return psi, dpsi, r, z, ds

    def energy(self, u):
        psi, dpsi, r, _, ds = self.fields(u)
        c2 = np.sin(psi) / r
        return np.sum((dpsi + c2) ** 2 * r) * ds / 8  # E_B / (8 pi kappa)

    def surface_area(self, u):
        _, _, r, _, ds = self.fields(u)
        return 2 * math.pi * np.sum(r) * ds

    def enclosed_volume(self, u):
        psi, _, r, _, ds = self.fields(u)
        return math.pi * np.sum(r * r * np.sin(psi)) * ds

    def end_radius(self, u):
        psi, _, _, _, ds = self.fields(u)
        return np.sum(np.cos(psi)) * ds

    def constraints(self):
        return [
            {"type": "eq", "fun": self.end_radius},
            {"type": "eq", "fun": lambda u: self.surface_area(u) - self.area},
            {"type": "eq",
             "fun": lambda u: self.enclosed_volume(u) - self.volume},
        ]

    def spheroid_guess(self, branch):
        """The spheroid of this reduced volume (axis along z)."""
        v = self.volume * 3 / (4 * math.pi)
        ratio = spheroid_ratio_for_reduced_volume(v, branch)  # c / a
        t = np.linspace(-math.pi / 2, math.pi / 2, 40001)
        r, z = np.cos(t), ratio * np.sin(t)
        arc = np.concatenate(([0], np.cumsum(np.hypot(np.diff(r),
                                                      np.diff(z)))))
        scale = math.sqrt(self.area / spheroid_area(1.0, ratio))
        tangent = np.unwrap(np.arctan2(np.gradient(z), np.gradient(r)))
        psi = np.interp(self.x * arc[-1], arc, tangent)
        a = 2 * (self.sin @ (psi - math.pi * self.x)) / GRID
        return np.concatenate((a, [arc[-1] * scale]))

    def shape(self, u):
        _, _, r, z, _ = self.fields(u)
        bulb = np.max(r)
        middle = r[GRID // 4: 3 * GRID // 4]
        neck = np.min(middle) if r[GRID // 2] < 0.999 * bulb else bulb
        return np.ptp(z), 2 * bulb, neck / bulb


def spheroid_area(a, ratio):
    c = ratio * a
    if abs(ratio - 1) < 1e-12:
        return 4 * math.pi * a * a
    if ratio > 1:
        e = math.sqrt(1 - (a / c) ** 2)
        return 2 * math.pi * a * a * (1 + c / (a * e) * math.asin(e))
    e = math.sqrt(1 - ratio**2)
    return 2 * math.pi * a * a * (1 + (1 - e * e) / e * math.atanh(e))


def spheroid_reduced_volume(ratio):
    area = spheroid_area(1.0, ratio)
    volume = 4 * math.pi * ratio / 3
    return volume / (4 * math.pi / 3 * (area / (4 * math.pi)) ** 1.5)


def spheroid_ratio_for_reduced_volume(v, branch):
    lo, hi = (1.0, 50.0) if branch == "prolate" else (0.02, 1.0)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        w = spheroid_reduced_volume(mid)
        if (w > v) == (branch == "prolate"):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def solve_axisymmetric(modes, reduced_volume, branch, guess=None):
    s = Axisymmetric(modes, reduced_volume)
    u0 = s.spheroid_guess(branch) if guess is None else np.concatenate(
        (extend(guess[:-1], modes, 1), [guess[-1]]))
    r = minimize(s.energy, u0, method="SLSQP", constraints=s.constraints(),
                 options={"maxiter": 1000, "ftol": 1e-12})
    check(r, "axisymmetric", modes)
    along, across, neck = s.shape(r.x)
    return {"modes": modes, "energy": s.energy(r.x), "extent_long": along,
            "extent_short": across, "neck_over_bulb": neck,
            "solution": r.x}


# --------------------------------------------------------------------------
def extend(coefficients, modes, blocks):
    """Coefficients of fewer modes padded with zeros to @p modes (per block
    of coefficients)."""
    old = len(coefficients) // blocks
    out = np.zeros(blocks * modes)
    for b in range(blocks):
        out[b * modes: b * modes + old] = coefficients[b * old: (b + 1) * old]
    return out


def check(result, what, modes):
    if not result.success:
        sys.exit(f"sharp-vesicle: the {what} minimisation with M = {modes} "
                 f"modes did not converge: {result.message}")


def refine(solver, m0, *args):
    rows, guess = [], None
    for m in (m0, 2 * m0, 4 * m0):
        row = solver(m, *args, guess=guess)
        guess = row["solution"]
        rows.append(row)
    return rows


def report(rows, keys):
    """Values at M, 2M, 4M modes; the last one with the change from the
    previous as its error bar (spectral convergence: the error of the last
    is far below that change)."""
    out = {}
    for row in rows:
        print("  M = %3d: " % row["modes"]
              + ", ".join("%s %.6f" % (k, row[k]) for k in keys))
    for k in keys:
        value, bar = rows[-1][k], abs(rows[-1][k] - rows[-2][k])
        out[k] = (value, bar)
        print("  %s = %.6f +- %.1e" % (k, value, bar))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    c = sub.add_parser("curve")
    g = c.add_mutually_exclusive_group(required=True)
    g.add_argument("--reduced-area", type=float)
    g.add_argument("--ellipse", type=float, nargs=2, metavar=("A", "B"),
                   help="the semi-axes of the initial ellipse: its reduced "
                        "area, and the results scaled to its perimeter")
    c.add_argument("--modes", type=int, default=8)
    a = sub.add_parser("axisymmetric")
    g = a.add_mutually_exclusive_group(required=True)
    g.add_argument("--reduced-volume", type=float)
    g.add_argument("--spheroid", type=float, nargs=2, metavar=("A", "C"),
                   help="equatorial and axial semi-axes of the initial "
                        "spheroid: its reduced volume and branch, and the "
                        "lengths scaled to its area")
    a.add_argument("--branch", choices=["prolate", "oblate"],
                   default="prolate")
    a.add_argument("--modes", type=int, default=8)
    b = sub.add_parser("branches")
    b.add_argument("--csv", required=True)
    b.add_argument("--plot", help="PNG of both branches (matplotlib)")
    b.add_argument("--modes", type=int, default=8)
    args = p.parse_args()

    if args.command == "curve":
        scale = 1.0
        if args.ellipse:
            a_, b_ = max(args.ellipse), min(args.ellipse)
            args.reduced_area = ellipse_reduced_area(a_ / b_)
            p = np.linspace(0, 2 * math.pi, 400001)
            perimeter = np.sum(np.hypot(np.diff(a_ * np.cos(p)),
                                        np.diff(b_ * np.sin(p))))
            scale = perimeter / (2 * math.pi)
            print("ellipse %g x %g: perimeter %.6f, area %.6f, reduced area "
                  "%.6f" % (a_, b_, perimeter, math.pi * a_ * b_,
                            args.reduced_area))
        if not 0 < args.reduced_area <= 1:
            sys.exit("sharp-vesicle: --reduced-area %g: must be in (0, 1]"
                     % args.reduced_area)
        print("2D, reduced area %.4f, perimeter 2 pi (E_B / kappa):"
              % args.reduced_area)
        out = report(refine(solve_curve, args.modes, args.reduced_area),
                     ["energy", "extent_long", "extent_short"])
        if scale != 1.0:
            print("scaled to the ellipse's perimeter: E_B / kappa = %.5f, "
                  "extents through the centre %.5f x %.5f"
                  % (out["energy"][0] / scale, out["extent_long"][0] * scale,
                     out["extent_short"][0] * scale))
    elif args.command == "axisymmetric":
        scale = 1.0
        if args.spheroid:
            a_, c_ = args.spheroid
            args.reduced_volume = spheroid_reduced_volume(c_ / a_)
            args.branch = "prolate" if c_ >= a_ else "oblate"
            area = spheroid_area(a_, c_ / a_)
            scale = math.sqrt(area / (4 * math.pi))
            print("spheroid %g (equator) x %g (axis): area %.6f, volume %.6f,"
                  " reduced volume %.6f"
                  % (a_, c_, area, 4 * math.pi * a_ * a_ * c_ / 3,
                     args.reduced_volume))
        if not 0 < args.reduced_volume <= 1:
            sys.exit("sharp-vesicle: --reduced-volume %g: must be in (0, 1]"
                     % args.reduced_volume)
        print("3D %s, reduced volume %.4f, area 4 pi (E_B / (8 pi kappa)):"
              % (args.branch, args.reduced_volume))
        out = report(refine(solve_axisymmetric, args.modes,
                            args.reduced_volume, args.branch),
                     ["energy", "extent_long", "extent_short",
                      "neck_over_bulb"])
        if scale != 1.0:
            print("scaled to the spheroid's area: E_B / kappa = %.4f, length "
                  "along the axis %.5f, largest width %.5f"
                  % (8 * math.pi * out["energy"][0],
                     out["extent_long"][0] * scale,
                     out["extent_short"][0] * scale))
    else:
        branches(args.csv, args.modes)
        if args.plot:
            plot_branches(args.csv, args.plot)


def branches(csv, modes):
    """The prolate and oblate branches E_B(v) / (8 pi kappa) by continuation
    in v from 0.98 down (each solve starts from the previous shape), at M
    and 2M modes (the difference is the error bar), and where they cross."""
    volumes = np.round(np.arange(0.98, 0.589, -0.01), 2)
    energies = {}
    with open(csv, "w") as f:
        f.write("branch,reduced_volume,energy_over_8pi_kappa,error_bar,"
                "extent_along_axis,extent_across,neck_over_bulb\n")
        for branch in ("prolate", "oblate"):
            coarse = fine = None
            for v in volumes:
                a = solve_axisymmetric(modes, v, branch, guess=coarse)
                b = solve_axisymmetric(2 * modes, v, branch, guess=fine)
                coarse, fine = a["solution"], b["solution"]
                energies[(branch, v)] = b["energy"]
                f.write("%s,%.2f,%.7f,%.1e,%.5f,%.5f,%.4f\n"
                        % (branch, v, b["energy"],
                           abs(b["energy"] - a["energy"]), b["extent_long"],
                           b["extent_short"], b["neck_over_bulb"]))
                f.flush()
                print("%s v = %.2f: E_B / (8 pi kappa) = %.6f (M = %d: %.6f)"
                      % (branch, v, b["energy"], modes, a["energy"]))
    difference = [energies[("prolate", v)] - energies[("oblate", v)]
                  for v in volumes]
    for i in range(len(volumes) - 1):
        if difference[i] < 0 <= difference[i + 1]:
            t = difference[i] / (difference[i] - difference[i + 1])
            v = volumes[i] + t * (volumes[i + 1] - volumes[i])
            print("prolate and oblate energies cross at v = %.3f" % v)


def plot_branches(csv, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [line.strip().split(",") for line in open(csv)][1:]
    fig, ax = plt.subplots(figsize=(6, 4))
    for branch in ("prolate", "oblate"):
        v = [float(r[1]) for r in rows if r[0] == branch]
        e = [float(r[2]) for r in rows if r[0] == branch]
        ax.plot(v, e, "o-", ms=3, label=branch)
    ax.axvline(0.652, color="gray", ls=":", label="v_po = 0.652 (SBL 1991)")
    ax.set_xlabel("reduced volume v")
    ax.set_ylabel("E_B / (8 pi kappa)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main()
