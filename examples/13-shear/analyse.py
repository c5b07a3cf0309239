"""Uniform shear flow: the rheology of Maxwell molecules and hard spheres in D = 2..6, the
velocity tails of a sheared 3D gas and the granular steady state (examples/13-shear/README.md).

    python3 examples/13-shear/analyse.py out/usf-maxwell out/usf-hs out/usf3 out/granular

Prints the viscosity ratio eta(a)/eta(0) of every case beside the exact Maxwell-molecule
value, the overpopulation of the sheared gas's marginal tails against a Gaussian, and the
granular gas's steady temperature and reduced shear rate; draws rheology.png and tails.png
in the current folder (with matplotlib).
"""

import csv
import json
import math
import pathlib
import sys

import numpy as np

import hypergas as hg


def maxwell_shear(d, a, n):
    """The exact steady state of Maxwell molecules (docs/validation.md, "Uniform shear
    flow"): the thermostat rate zeta solves zeta (r + 2 zeta)^2 = a^2 r / D, r = N/(2(N-1));
    returns (viscosity ratio, P_xy/p)."""
    r = n / (2.0 * (n - 1.0))
    lo, hi = 0.0, max(1.0, a)
    for _ in range(200):
        z = 0.5 * (lo + hi)
        lo, hi = (z, hi) if z * (r + 2 * z) ** 2 < a * a * r / d else (lo, z)
    z = 0.5 * (lo + hi)
    return (r / (r + 2 * z)) ** 2, -a * r / (r + 2 * z) ** 2


def rows(folder):
    with open(pathlib.Path(folder) / "sweep.csv") as f:
        return list(csv.DictReader(f))


def main(maxwell_dir, hs_dir, tails_dir, granular_dir):
    mx, hs = rows(maxwell_dir), rows(hs_dir)
    print("eta(a)/eta(0) under the isokinetic thermostat (second half of each run)")
    print(" D     a   maxwell               exact    hard spheres")
    worst = 0.0
    for m, h in zip(mx, hs):
        d, a, n = int(m["dim"]), float(m["shear_rate"]), int(m["n"])
        exact, _ = maxwell_shear(d, a, n)
        v, e = float(m["viscosity_ratio"]), float(m["viscosity_ratio_error"])
        worst = max(worst, abs(v - exact) / e)
        print(f"{d:2d} {a:5.2f}   {v:.4f} +- {e:.4f}   {exact:.4f}    "
              f"{float(h['viscosity_ratio']):.4f} +- {float(h['viscosity_ratio_error']):.4f}")
    print(f"largest Maxwell deviation: {worst:.2f} standard errors")

    t = hg.read_trajectory(pathlib.Path(tails_dir) / "trajectory.h5")
    v = np.concatenate([t.velocities[k] for k in range(1, len(t))])  # the steady frames
    c = v / np.sqrt((v ** 2).sum(1).mean() / v.shape[1])
    print(f"tails: 3D hard spheres at a = 2, {len(t) - 1} frames of {t.n} particles")
    for axis, name in ((0, "x"), (1, "y")):
        x = c[:, axis] / c[:, axis].std()
        frac = (np.abs(x) > 3).mean()
        gauss = math.erfc(3 / math.sqrt(2))
        print(f"  |c_{name}| > 3 sd: {frac:.2e} of the particles, Gaussian {gauss:.2e} "
              f"(x{frac / gauss:.1f})")

    g = json.loads((pathlib.Path(granular_dir) / "summary.json").read_text())
    print(f"granular steady state (alpha = 0.9, a = {g['shear_rate']}): "
          f"T/T0 = {g['temperature_ratio']:.3f} +- {g['temperature_ratio_error']:.3f}, "
          f"reduced shear rate {g['reduced_shear_rate']:.4f} +- "
          f"{g['reduced_shear_rate_error']:.4f}, P_xy/p = {g['shear_stress']:.4f} +- "
          f"{g['shear_stress_error']:.4f}, heating rate {g['heating_rate']:.1e} +- "
          f"{g['heating_rate_error']:.1e}")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not found: no plots")
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    grid = np.geomspace(0.1, 5, 60)
    for k, d in enumerate(range(2, 7)):
        col = f"C{k}"
        ax.plot(grid, [maxwell_shear(d, a, 20000)[0] for a in grid], color=col, lw=1)
        pts = [(float(r["shear_rate"]), float(r["viscosity_ratio"])) for r in mx
               if int(r["dim"]) == d]
        ax.plot(*zip(*pts), "o", color=col, label=f"D = {d}")
        pts = [(float(r["shear_rate"]), float(r["viscosity_ratio"])) for r in hs
               if int(r["dim"]) == d]
        ax.plot(*zip(*pts), "s", color=col, mfc="none")
    ax.set_xscale("log")
    ax.set_xlabel("shear rate a (per mean collision time)")
    ax.set_ylabel("eta(a) / eta(0)")
    ax.set_title("circles: Maxwell molecules (lines exact); squares: hard spheres")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("rheology.png", dpi=120)
    fig, ax = plt.subplots(figsize=(6, 4))
    bins = np.linspace(-6, 6, 61)
    for axis, name in ((0, "c_x"), (1, "c_y")):
        x = c[:, axis] / c[:, axis].std()
        h, e = np.histogram(x, bins=bins, density=True)
        ax.semilogy(0.5 * (e[1:] + e[:-1]), h, "o", ms=3, label=name)
    xs = np.linspace(-6, 6, 200)
    ax.semilogy(xs, np.exp(-xs ** 2 / 2) / math.sqrt(2 * math.pi), "k-", lw=1, label="Gaussian")
    ax.set_xlabel("velocity component / its standard deviation")
    ax.set_ylabel("density")
    ax.set_title("3D hard spheres, a = 2, isokinetic")
    ax.legend()
    fig.tight_layout()
    fig.savefig("tails.png", dpi=120)
    print("wrote rheology.png, tails.png")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
