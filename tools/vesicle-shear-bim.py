#!/usr/bin/python3
"""Sharp-interface reference for HD3 (issue 15, item 9): the steady
tank-treading angle of a 2D vesicle in unbounded simple shear, equal
viscosities inside and outside (beta_mu = 1), by a boundary-integral method.

Independent of the phase field and of the finite-element code: the membrane
is a closed curve X(alpha) with N points equispaced in alpha, an inextensible
Helfrich membrane (bending rigidity kappa, a tension sigma(s) that keeps every
line element's length) in Stokes flow of viscosity mu. With equal viscosities
the velocity is the imposed shear plus the single-layer potential of the
membrane force,

  dX/dt = u_inf(X) + S[f](X),   u_inf = (gamma_dot y, 0),
  S[f](x) = 1/(4 pi mu) int (-log|r| I + r r^T / |r|^2) f(y) ds_y,  r = x - y,
  f = -kappa X_ssss + (sigma X_s)_s,   X_s . (dX/dt)_s = 0,

(the H^3 and H H_s parts of the Helfrich force are absorbed by sigma, which
is a free multiplier field). Discretisation (after Veerapaneni, Gueyffier,
Zorin and Biros, J. Comput. Phys. 228 (2009) 2334): Fourier differentiation
in alpha, Kress' product quadrature for the log singularity, the trapezoidal
rule elsewhere, semi-implicit BDF2 steps (bending, tension and the
constraint at the new time, the geometry of S and of the operators
extrapolated from the two last ones): a dense 3N x 3N solve per step.

Units: the effective radius R_0 = sqrt(A / pi) = 1, mu = 1, kappa = 1, so
the capillary number C_k = mu gamma_dot R_0^3 / kappa is gamma_dot; times
are printed as gamma_dot t. Inclination angle: the major principal axis of
the second moments of the enclosed region (spec 4.12, the same definition
as the phase-field code), in radians from the flow direction.

  tools/vesicle-shear-bim.py --reduced-area 0.84 --capillary 10
  tools/vesicle-shear-bim.py --reduced-area 0.84 --capillary 1,10,100 \
      --points 64,128 --csv output/bim-angles.csv

Checks of the tool itself: `--self-test` (the single layer of a circle
exact, spectral convergence on an ellipse); printed with every run: the area
and the length of the curve (conserved by the continuous model); the angle
against N and dt by the comma-separated lists.
"""
import argparse
import math
import sys

import numpy as np


def fourier_derivative_matrix(n):
    """Spectral differentiation matrix on n equispaced points of [0, 2 pi)
    (n even; the Nyquist mode's derivative set to zero)."""
    k = np.fft.fftfreq(n, d=1.0 / n)
    k[n // 2] = 0.0
    identity = np.eye(n)
    return np.real(np.fft.ifft(1j * k[:, None] * np.fft.fft(identity, axis=0), axis=0))


def kress_weights(n):
    """R[i, j]: int_0^{2 pi} log(4 sin^2((t_i - tau)/2)) g(tau) dtau =
    sum_j R[i, j] g(t_j) for trigonometric polynomials g of degree < n/2
    (Kress, Linear Integral Equations, 12.3)."""
    half = n // 2
    t = 2 * math.pi * np.arange(n) / n
    diff = t[:, None] - t[None, :]
    weights = np.zeros((n, n))
    for m in range(1, half):
        weights += np.cos(m * diff) / m
    return -(4 * math.pi / n) * weights - (4 * math.pi / n ** 2) * np.cos(half * diff)


class Membrane:
    """The discrete curve and the operators of one semi-implicit step."""

    def __init__(self, points):
        self.n = points
        self.h = 2 * math.pi / points
        self.d_alpha = fourier_derivative_matrix(points)
        self.kress = kress_weights(points)
        t = 2 * math.pi * np.arange(points) / points
        self.sin_half_sq4 = 4 * np.sin((t[:, None] - t[None, :]) / 2) ** 2

    def single_layer(self, x, speed):
        """2N x 2N matrix of S (mu = 1): rows/columns [x-components,
        y-components]."""
        n = self.n
        rx = x[:, 0][:, None] - x[:, 0][None, :]
        ry = x[:, 1][:, None] - x[:, 1][None, :]
        rho2 = rx ** 2 + ry ** 2
        np.fill_diagonal(rho2, 1.0)
        tangent = (self.d_alpha @ x) / speed[:, None]
        # -log|r| = -1/2 log(4 sin^2) - 1/2 log(|r|^2 / (4 sin^2)); the second
        # part is smooth, its diagonal limit log |X_alpha|^2.
        smooth = np.log(rho2 / np.where(self.sin_half_sq4 > 0, self.sin_half_sq4, 1.0))
        np.fill_diagonal(smooth, np.log(speed ** 2))
        log_part = -0.5 * self.kress - 0.5 * self.h * smooth
        rxx, rxy, ryy = rx * rx / rho2, rx * ry / rho2, ry * ry / rho2
        np.fill_diagonal(rxx, tangent[:, 0] ** 2)
        np.fill_diagonal(rxy, tangent[:, 0] * tangent[:, 1])
        np.fill_diagonal(ryy, tangent[:, 1] ** 2)
        weight = speed[None, :] / (4 * math.pi)
        s = np.zeros((2 * n, 2 * n))
        s[:n, :n] = (log_part + self.h * rxx) * weight
        s[:n, n:] = self.h * rxy * weight
        s[n:, :n] = self.h * rxy * weight
        s[n:, n:] = (log_part + self.h * ryy) * weight
        return s

    def step(self, x, x_old, dt, shear_rate, gradient=(0.0, 1.0, 0.0), kappa=1.0):
        """One semi-implicit step of size dt: backward Euler if x_old is None,
        otherwise BDF2 with the geometry (S, d/ds, X_s, u_inf) extrapolated
        to x* = 2 x - x_old (the first-order scheme moves the tank-treading
        points along chords and lets area and length drift by O(dt) per
        unit time). Returns the new positions and the tension."""
        n = self.n
        if x_old is None:
            geometry, history, scale = x, x, 1.0
        else:
            geometry, history, scale = 2 * x - x_old, (4 * x - x_old) / 3, 2.0 / 3.0
        x_alpha = self.d_alpha @ geometry
        speed = np.linalg.norm(x_alpha, axis=1)
        d_s = self.d_alpha / speed[:, None]
        x_s = x_alpha / speed[:, None]
        d_s4 = np.linalg.matrix_power(d_s, 4)
        zero = np.zeros((n, n))
        bending = -kappa * np.block([[d_s4, zero], [zero, d_s4]])
        tension = np.vstack([d_s @ np.diag(x_s[:, 0]), d_s @ np.diag(x_s[:, 1])])
        divergence = np.hstack([np.diag(x_s[:, 0]) @ d_s, np.diag(x_s[:, 1]) @ d_s])
        s = self.single_layer(geometry, speed)
        history = np.concatenate([history[:, 0], history[:, 1]])
        # u_inf = shear_rate (g11 x + g12 y, g21 x - g11 y): simple shear by
        # default, any traceless linear flow with --velocity-gradient.
        g11, g12, g21 = gradient
        u_inf = shear_rate * np.concatenate([g11 * geometry[:, 0] + g12 * geometry[:, 1],
                                             g21 * geometry[:, 0] - g11 * geometry[:, 1]])
        tau = scale * dt
        # Inextensibility X*_s . (dX/dt)_s = 0 with the BDF difference quotient.
        matrix = np.block([[np.eye(2 * n) - tau * s @ bending, -tau * s @ tension],
                           [divergence, np.zeros((n, n))]])
        rhs = np.concatenate([history + tau * u_inf, divergence @ history])
        solution = np.linalg.solve(matrix, rhs)
        return np.column_stack([solution[:n], solution[n:2 * n]]), solution[2 * n:]

    def measures(self, x):
        """Area, length, centroid and inclination angle (spec 4.12) of the
        region inside the curve, by spectrally accurate boundary integrals
        (Green's theorem)."""
        x_alpha = self.d_alpha @ x
        speed = np.linalg.norm(x_alpha, axis=1)
        h = self.h
        px, py = x[:, 0], x[:, 1]
        dy = x_alpha[:, 1]
        dx = x_alpha[:, 0]
        area = h * np.sum(px * dy)
        length = h * np.sum(speed)
        cx = h * np.sum(px ** 2 / 2 * dy) / area
        cy = -h * np.sum(py ** 2 / 2 * dx) / area
        qx, qy = px - cx, py - cy
        ixx = h * np.sum(qx ** 3 / 3 * dy)
        iyy = -h * np.sum(qy ** 3 / 3 * dx)
        ixy = h * np.sum(qx ** 2 / 2 * qy * dy)
        angle = 0.5 * math.atan2(2 * ixy, ixx - iyy)
        return area, length, (cx, cy), angle


def initial_ellipse(points, reduced_area):
    """Ellipse of area pi (R_0 = 1) and the requested reduced area
    4 pi A / L^2, major axis along y (as HD3's vesicles start), sampled at
    equal arc length."""
    def perimeter(ratio):
        a, b = 1 / math.sqrt(ratio), math.sqrt(ratio)
        t = np.linspace(0, 2 * math.pi, 20001)[:-1]
        return np.sum(np.hypot(a * np.sin(t), b * np.cos(t))) * 2 * math.pi / t.size

    low, high = 1.0, 50.0
    for _ in range(200):
        mid = 0.5 * (low + high)
        if 4 * math.pi * math.pi / perimeter(mid) ** 2 > reduced_area:
            low = mid
        else:
            high = mid
    ratio = 0.5 * (low + high)
    a, b = 1 / math.sqrt(ratio), math.sqrt(ratio)
    fine = np.linspace(0, 2 * math.pi, 200001)
    arc = np.concatenate([[0], np.cumsum(np.hypot(np.diff(a * np.cos(fine)),
                                                  np.diff(b * np.sin(fine))))])
    targets = arc[-1] * np.arange(points) / points
    t = np.interp(targets, arc, fine)
    return np.column_stack([a * np.cos(t), b * np.sin(t)])


def write_profile(name, membrane, x, sigma, capillary):
    """The last state along the membrane, counter-clockwise from its
    rightmost point (as the phase-field code's tension-<step>.csv): arc
    length, position, tension sigma and sigma / (mu gamma_dot R_0) =
    sigma / C_k (the viscous scale, in which tensions of runs at any C_k,
    and of the phase field, compare)."""
    speed = np.linalg.norm(membrane.d_alpha @ x, axis=1)
    start = int(np.argmax(x[:, 0]))
    order = np.roll(np.arange(membrane.n), -start)
    arc = np.concatenate([[0.0], np.cumsum(membrane.h * speed[order])[:-1]])
    with open(name, "w") as out:
        out.write("s,x,y,sigma,sigma_over_viscous_scale\n")
        for s_value, i in zip(arc, order):
            out.write(f"{s_value:.6f},{x[i, 0]:.6f},{x[i, 1]:.6f},{sigma[i]:.6g},"
                      f"{sigma[i] / capillary:.6g}\n")


def run(points, reduced_area, capillary, end_time, steps_per_unit, log, history_file=None,
        gradient=(0.0, 1.0, 0.0), profile_file=None):
    membrane = Membrane(points)
    x = initial_ellipse(points, reduced_area)
    area0, length0, _, _ = membrane.measures(x)
    dt = 1.0 / (steps_per_unit * capillary)
    steps = int(round(end_time * steps_per_unit))
    history = []
    samples = [(0.0, membrane.measures(x)[3])]
    x_old = None
    for step in range(1, steps + 1):
        x_new, sigma = membrane.step(x, x_old, dt, capillary, gradient)
        x_old, x = x, x_new
        if step % max(1, steps_per_unit // 10) == 0:
            samples.append((step / steps_per_unit, membrane.measures(x)[3]))
        if step % steps_per_unit == 0 or step == steps:
            area, length, centroid, angle = membrane.measures(x)
            history.append((step / steps_per_unit, angle))
            if log:
                print(f"  gamma_dot t = {step / steps_per_unit:6.2f}  theta = {angle:.6f}"
                      f"  dA/A = {(area - area0) / area0:.2e}  dL/L = {(length - length0) / length0:.2e}"
                      f"  sigma mean = {np.mean(sigma):.4g}", file=sys.stderr)
    if history_file:
        with open(history_file, "w") as out:
            out.write("gamma_dot_t,theta\n")
            out.writelines(f"{t:g},{a:.6f}\n" for t, a in samples)
    if profile_file:
        write_profile(profile_file, membrane, x, sigma, capillary)
    area, length, centroid, angle = membrane.measures(x)
    drift = abs(history[-1][1] - history[-max(2, len(history) // 10)][1])
    return dict(points=points, capillary=capillary, steps_per_unit=steps_per_unit,
                angle=angle, drift=drift, area_error=(area - area0) / area0,
                length_error=(length - length0) / length0,
                reduced_area=4 * math.pi * area / length ** 2)


def self_test():
    """The quadrature checks of doc/hydrodynamics.md: the single layer of a
    circle (radius a) is exact (normal load: no flow; tangential load tau:
    rigid rotation a tau / (2 mu)), and on an ellipse it converges
    spectrally in N. Returns the number of failed checks."""
    failures = 0
    for n in (16, 32, 64):
        membrane = Membrane(n)
        t = 2 * math.pi * np.arange(n) / n
        a = 1.3
        x = np.column_stack([a * np.cos(t), a * np.sin(t)])
        s = membrane.single_layer(x, np.full(n, a))
        normal = np.concatenate([np.cos(t), np.sin(t)])
        tangent = np.concatenate([-np.sin(t), np.cos(t)])
        errors = (np.abs(s @ normal).max(), np.abs(s @ tangent - a / 2 * tangent).max())
        ok = max(errors) < 1e-13
        failures += not ok
        print(f"circle, N = {n}: |S[n]| = {errors[0]:.1e}, |S[t] - a t / 2| = {errors[1]:.1e}"
              f" {'ok' if ok else 'FAILED'}")
    values = {}
    for n in (32, 64, 128, 256):
        membrane = Membrane(n)
        t = 2 * math.pi * np.arange(n) / n
        x = np.column_stack([0.7 * np.cos(t), 1.4 * np.sin(t) + 0.1 * np.cos(2 * t)])
        speed = np.linalg.norm(membrane.d_alpha @ x, axis=1)
        load = np.concatenate([np.cos(t) ** 3, np.sin(2 * t) + 0.3])
        values[n] = (membrane.single_layer(x, speed) @ load)[:n][::n // 32]
    for n, bound in ((32, 1e-6), (64, 1e-10), (128, 1e-13)):
        error = np.abs(values[n] - values[256]).max()
        ok = error < bound
        failures += not ok
        print(f"ellipse, N = {n} against 256: {error:.1e} (bound {bound:.0e})"
              f" {'ok' if ok else 'FAILED'}")
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--reduced-area", type=float, default=0.84)
    parser.add_argument("--capillary", default="10",
                        help="comma-separated C_k = mu gamma_dot R_0^3 / kappa")
    parser.add_argument("--points", default="64", help="comma-separated N")
    parser.add_argument("--steps-per-unit", default="200",
                        help="comma-separated steps per unit of gamma_dot t")
    parser.add_argument("--end-time", type=float, default=30.0, help="in units of 1 / gamma_dot")
    parser.add_argument("--csv", help="write the table here too")
    parser.add_argument("--history", help="write theta against gamma_dot t (every 0.1) of the"
                        " last run here")
    parser.add_argument("--velocity-gradient", default="0,1,0",
                        help="g11,g12,g21: u_inf = gamma_dot (g11 x + g12 y, g21 x - g11 y);"
                        " the default is simple shear")
    parser.add_argument("--profile", help="write the last run's tension along the membrane here")
    parser.add_argument("--verbose", action="store_true")
    parser.add_argument("--self-test", action="store_true",
                        help="check the quadrature (circle exact, ellipse spectral) and exit")
    args = parser.parse_args()
    if args.self_test:
        sys.exit(1 if self_test() else 0)
    if not 0 < args.reduced_area < 1:
        sys.exit(f"--reduced-area = {args.reduced_area}: must be in (0, 1)")
    gradient = tuple(float(v) for v in args.velocity_gradient.split(","))
    if len(gradient) != 3:
        sys.exit(f"--velocity-gradient = {args.velocity_gradient}: three numbers g11,g12,g21")
    rows = []
    print("N,steps_per_unit,C_k,gamma_dot_T,theta,theta_over_pi,drift_last_10pct,"
          "area_error,length_error,reduced_area_end")
    for points in (int(v) for v in args.points.split(",")):
        if points < 16 or points % 2:
            sys.exit(f"--points = {points}: must be even and >= 16")
        for spu in (int(v) for v in args.steps_per_unit.split(",")):
            for capillary in (float(v) for v in args.capillary.split(",")):
                r = run(points, args.reduced_area, capillary, args.end_time, spu, args.verbose,
                        args.history, gradient, args.profile)
                line = (f"{points},{spu},{capillary:g},{args.end_time:g},{r['angle']:.6f},"
                        f"{r['angle'] / math.pi:.5f},{r['drift']:.2e},{r['area_error']:.2e},"
                        f"{r['length_error']:.2e},{r['reduced_area']:.5f}")
                print(line, flush=True)
                rows.append(line)
    if args.csv:
        with open(args.csv, "w") as out:
            out.write("N,steps_per_unit,C_k,gamma_dot_T,theta,theta_over_pi,drift_last_10pct,"
                      "area_error,length_error,reduced_area_end\n")
            out.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
