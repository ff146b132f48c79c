#!/usr/bin/python3
"""Small-deformation analysis of the conductivity crossover of the Part E
model (issue 16, item 4; doc/validation.md, section 4).

A sphere (d = 3) or circular cylinder (d = 2) of radius R with the diffuse
membrane of (E1), phi = tanh((r - R) / (sqrt2 eps)) (+1 outside), in the
uniform field E0 along the axis theta = 0. With the conductivity sigma(phi)
of (E10) radial, the potential of (E16) separates exactly,
psi = F(r) cos(theta), with

    (r^(d-1) sigma F')' = (d-1) sigma F r^(d-3),  F(0) = 0,
    F -> -E0 r + D / r^(d-1) far away (the exact far field of a uniform
    conductor, imposed at r_max as r F' + (d-1) F = -d E0 r).

The staggered scheme of spec 3.9 freezes psi in the shape equation, so the
force on the membrane is the first variation of the electric energies at
fixed psi. With e_in = e_out (spec 3.10) the electrolyte term (E8) has none
and flexoelectricity is off in the sweep: only the membrane dielectric
energy (E7) acts. A radial shift delta(theta) of the profile changes (E7) by

    dE_DM = (3 d_m e_m / (8 sqrt2 eps)) int delta g(theta) dGamma,
    g(theta) = int d/dr[(1 - phi^2)^2] |grad psi|^2 (r / R)^(d-1) dr,

so the membrane moves out where g is small (the membrane, of negative
energy density, moves towards the stronger field): d/dr (1 - phi^2)^2 is
positive inside the membrane centre and negative outside, and g weighs the
field on the inner side of the membrane against the outer side. With
|grad psi|^2 = F'^2 cos^2 + (F / r)^2 sin^2, g = G_pole cos^2(theta) +
G_equator sin^2(theta); the mean is taken by the volume multiplier and the
cos(2 theta) part decides the shape:

    G_pole < G_equator: prolate (poles pushed out), else oblate.

The script solves the radial problem by finite volumes on a grid graded
into the membrane (conductivity jumps of 1e7 across a few eps; harmonic
face averages), prints G_pole / G_equator for a list of conductivity
ratios, and finds the crossover ratio sigma_in / sigma_out (sigma_in +
sigma_out fixed, as in EM5) by bisection, for a sequence of eps: the
limit eps -> 0 is the model's sharp crossover.

Usage (Debian's python3 with numpy and scipy):
    /usr/bin/python3 tools/conductivity-crossover.py [--dim 3] [--radius 10]
        [--eps 2 1 0.5 0.25] [--sum 1.5] [--sigma-m 3e-7] [--check]
--check compares the solver with the exact piecewise solution of a
sharp insulating shell (d = 2 and 3) and prints the relative error.
"""
import argparse
import math
import sys

import numpy as np
from scipy.linalg import solve_banded


def conductivity(phi, s_in, s_out, s_m):
    """(E10), used as printed."""
    p8 = phi**8
    return (s_in / 4 * (1 - phi)**2 * p8 + s_m / 4 * (1 - phi)**2 *
            (1 + phi)**2 + s_out / 4 * (1 + phi)**2 * p8)


def radial_grid(R, eps, r_max, n):
    """Nodes on [0, r_max], half of them within 8 eps of R (graded)."""
    core = np.linspace(R - 8 * eps, R + 8 * eps, n // 2)
    inner = np.linspace(0, R - 8 * eps, n // 4, endpoint=False)
    outer = np.geomspace(R + 8 * eps, r_max, n // 4 + 1)[1:]
    return np.concatenate([inner, core, outer])


def solve_radial(r, sigma_faces, d, E0=1.0):
    """F at the nodes r (r[0] = 0) for face conductivities sigma_faces
    (len(r) - 1): finite volumes of (r^(d-1) sigma F')' = (d-1) sigma F
    r^(d-3), F(0) = 0, far-field Robin condition at r[-1]."""
    n = len(r)
    h = np.diff(r)
    rf = 0.5 * (r[1:] + r[:-1])  # faces between nodes
    flux = sigma_faces * rf**(d - 1) / h  # coefficient of F_{i+1} - F_i
    ab = np.zeros((3, n))  # banded: upper, diagonal, lower
    b = np.zeros(n)
    ab[1, 0] = 1.0  # F(0) = 0
    i = np.arange(1, n - 1)
    vol = 0.5 * (h[i - 1] + h[i])
    # sigma at a node: the mean of its faces; source (d-1) sigma r^(d-3) F
    s_node = 0.5 * (sigma_faces[i - 1] + sigma_faces[i])
    ab[1, i] = -(flux[i - 1] + flux[i]) - (d - 1) * s_node * r[i]**(d -
                                                                   3) * vol
    ab[0, i + 1] = flux[i]
    ab[2, i - 1] = flux[i - 1]
    # r F' + (d-1) F = -d E0 r at r_max (one-sided difference)
    ab[1, n - 1] = r[-1] / h[-1] + (d - 1)
    ab[2, n - 2] = -r[-1] / h[-1]
    b[-1] = -d * E0 * r[-1]
    return solve_banded((1, 1), ab, b)


def membrane_forces(R, eps, d, s_in, s_out, s_m, n=200000, r_max_factor=6):
    """(G_pole, G_equator) of the module documentation, per E0^2."""
    r = radial_grid(R, eps, r_max_factor * R, n)
    rf = 0.5 * (r[1:] + r[:-1])
    phi_f = np.tanh((rf - R) / (math.sqrt(2) * eps))
    sig = conductivity(phi_f, s_in, s_out, s_m)
    F = solve_radial(r, sig, d)
    dF = np.diff(F) / np.diff(r)  # at the faces
    Ff = 0.5 * (F[1:] + F[:-1])
    weight = (1 - phi_f**2)**2
    dweight = np.gradient(weight, rf)
    jac = (rf / R)**(d - 1) * np.diff(r)
    g_pole = np.sum(dweight * dF**2 * jac)
    g_equator = np.sum(dweight * (Ff / rf)**2 * jac)
    return g_pole, g_equator


def crossover(R, eps, d, total, s_m, lo=0.2, hi=10.0):
    """The ratio s_in / s_out where G_pole = G_equator (s_in + s_out =
    total), by bisection in log(ratio); None if no sign change."""

    def excess(log_ratio):
        q = math.exp(log_ratio)
        s_out = total / (1 + q)
        gp, ge = membrane_forces(R, eps, d, q * s_out, s_out, s_m)
        return (gp - ge) / (abs(gp) + abs(ge))

    a, b = math.log(lo), math.log(hi)
    fa, fb = excess(a), excess(b)
    if fa * fb > 0:
        return None
    for _ in range(40):
        m = 0.5 * (a + b)
        fm = excess(m)
        if fa * fm <= 0:
            b, fb = m, fm
        else:
            a, fa = m, fm
        if b - a < 1e-4:
            break
    return math.exp(0.5 * (a + b))


def check_solver(d):
    """A sharp insulating shell (sigma_in inside r < R, sigma_m in
    R < r < R + t, sigma_out outside) against its exact solution."""
    R, t, s_in, s_m, s_out = 1.0, 0.01, 0.3, 1e-4, 1.2
    r = np.concatenate([
        np.linspace(0, R, 4000, endpoint=False),
        np.linspace(R, R + t, 4000, endpoint=False),
        np.geomspace(R + t, 6.0, 8000)
    ])
    rf = 0.5 * (r[1:] + r[:-1])
    sig = np.where(rf < R, s_in, np.where(rf < R + t, s_m, s_out))
    F = solve_radial(r, sig, d)
    # exact: F = a r inside, b r + c / r^(d-1) in the shell, -r + e / r^(d-1)
    # outside; continuity of F and sigma F' at R and R + t.
    k = d - 1
    R2 = R + t
    A = np.array([
        [R, -R, -R**-k, 0],
        [s_in, -s_m, s_m * k * R**(-k - 1), 0],
        [0, R2, R2**-k, -R2**-k],
        [0, s_m, -s_m * k * R2**(-k - 1), s_out * k * R2**(-k - 1)],
    ])
    rhs = np.array([0, 0, -R2, -s_out])
    a, b, c, e = np.linalg.solve(A, rhs)
    exact = np.where(r < R, a * r,
                     np.where(r < R2, b * r + c / np.maximum(r, 1e-30)**k,
                              -r + e / np.maximum(r, 1e-30)**k))
    # the far-field condition is exact for this F: compare everywhere
    return np.max(np.abs(F - exact)) / np.max(np.abs(exact))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--dim', type=int, default=3)
    parser.add_argument('--radius', type=float, default=10.0)
    parser.add_argument('--eps', type=float, nargs='+', default=[2, 1, 0.5,
                                                                 0.25])
    parser.add_argument('--sum', type=float, default=1.5,
                        help='sigma_in + sigma_out (EM5: 1.5 S/m)')
    parser.add_argument('--sigma-m', type=float, default=3e-7)
    parser.add_argument('--ratios', type=float, nargs='+',
                        default=[0.25, 0.5, 0.87, 1, 1.5, 2.75, 4])
    parser.add_argument('--check', action='store_true')
    parser.add_argument('--plot', metavar='PNG',
                        help='crossover ratio against eps / R, d = 2 and 3')
    args = parser.parse_args()
    if args.check:
        for d in (2, 3):
            print(f'd = {d}: sharp insulating shell, max relative error of F: '
                  f'{check_solver(d):.2e}')
        return
    d, R = args.dim, args.radius
    print(f'd = {d}, R = {R}, sigma_in + sigma_out = {args.sum}, '
          f'sigma_m = {args.sigma_m}')
    print('eps,ratio,G_pole,G_equator,shape')
    for eps in args.eps:
        for q in args.ratios:
            s_out = args.sum / (1 + q)
            gp, ge = membrane_forces(R, eps, d, q * s_out, s_out,
                                     args.sigma_m)
            shape = 'prolate' if gp < ge else 'oblate'
            print(f'{eps},{q},{gp:.6e},{ge:.6e},{shape}')
    print('eps,crossover ratio sigma_in/sigma_out')
    for eps in args.eps:
        c = crossover(R, eps, d, args.sum, args.sigma_m)
        print(f'{eps},{c:.4f}' if c else f'{eps},none in [0.2, 10]')
    sys.stdout.flush()
    if args.plot:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5, 3.6))
        for dim, marker in ((2, 'o'), (3, 's')):
            points = [(eps / R, crossover(R, eps, dim, args.sum,
                                          args.sigma_m)) for eps in args.eps]
            points = [(x, c - 1) for x, c in points if c]
            ax.loglog(*zip(*points), marker=marker, label=f'd = {dim}')
        ax.set_xlabel('eps / R')
        ax.set_ylabel('crossover ratio - 1')
        ax.set_title('sigma_in/sigma_out where the sphere/circle\n'
                     'turns from oblate to prolate (small deformation)',
                     fontsize=9)
        ax.grid(True, which='both', alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print(f'figure: {args.plot}')


if __name__ == '__main__':
    main()
