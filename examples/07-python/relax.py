#!/usr/bin/env python3
"""07 -- two beams relaxing to Maxwell-Boltzmann in 2D and 6D, from Python.

Two cold beams stream through each other along x (init "beams"). Collisions turn the
bimodal v_x into a Gaussian: the kurtosis of v_x climbs from about 1.2 to the Maxwell-
Boltzmann value 3, and the speed distribution goes from a narrow peak at the beam speed to
the D-dimensional MB density, whose shape depends strongly on D.

The script runs hypergas.DSMC in both dimensions, records one row of the command's
moments.csv every `every` mean collision times (hypergas.MomentsRecorder), takes the speed
histogram at three moments (hypergas.analyse on the engine's live velocity view) and
draws two panels per dimension: the speed histograms against the D-dimensional MB density,
and the kurtosis against time with its standard error. It writes relax.png (and
relax_<D>d.csv) into --out and checks that the final state is Maxwellian.

    PYTHONPATH=build/python python3 examples/07-python/relax.py            # N = 200000
    PYTHONPATH=build/python python3 examples/07-python/relax.py --short    # N = 20000
"""

import argparse
import math
import os
import sys

import hypergas as hg  # first: it also finds Debian's numpy from another Python 3.11

import numpy as np


def relax(dim, n, until, every, seed):
    """Runs one gas; returns its moments table and the histograms at three times."""
    gas = hg.DSMC(dim=dim, n=n, init="beams", seed=seed)
    rec = hg.MomentsRecorder(bins=60)
    snapshots = {}
    for t in (0.0, 2.0, until):
        gas.run(t, every=every, observers=[rec])
        snapshots[t] = hg.analyse(gas, bins=60)
    return rec.table(), snapshots


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--short", action="store_true", help="N = 20000 (what ctest runs)")
    ap.add_argument("--out", default=".", help="folder for relax.png and the CSVs")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    n = 20000 if args.short else 200000
    until, every = 12.0, 0.25
    os.makedirs(args.out, exist_ok=True)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    ok = True
    print(f"two beams relaxing, N = {n}, t in mean collision times")
    print(f"{'D':>2} {'t':>6} {'kurtosis_x':>11} {'+-':>7} {'L1(MB)':>8} {'KS p':>9}")
    for row, dim in enumerate((2, 6)):
        table, snaps = relax(dim, n, until, every, args.seed)
        with open(os.path.join(args.out, f"relax_{dim}d.csv"), "w") as f:
            f.write("time,kurtosis_x,kurtosis_x_err,l1_speed,ks_p_speed\n")
            for k in range(len(table["time"])):
                f.write(",".join(f"{table[c][k]:.17g}" for c in
                                 ("time", "kurtosis_x", "kurtosis_x_err", "l1_speed",
                                  "ks_p_speed")) + "\n")
        for t, a in snaps.items():
            print(f"{dim:>2} {t:6.1f} {a.kurtosis_x:11.4f} {a.kurtosis_x_err:7.4f} "
                  f"{a.l1_speed:8.4f} {a.ks_p_speed:9.3g}")
        ax = axes[row, 0]
        for t, a in snaps.items():
            h = a.histogram
            ax.step(h.centres, h.density, where="mid", label=f"t = {t:g}")
        h = snaps[until].histogram
        v = np.linspace(0.0, h.hi[-1], 400)
        ax.plot(v, hg.maxwell_pdf(v, dim, kT=h.kT), "k--", label=f"Maxwell-Boltzmann, D = {dim}")
        ax.set_xlabel("speed |v|")
        ax.set_ylabel("density")
        ax.set_title(f"{dim}D: speed distribution")
        ax.legend(fontsize=8)
        ax = axes[row, 1]
        ax.errorbar(table["time"], table["kurtosis_x"], yerr=table["kurtosis_x_err"], fmt=".",
                    ms=3)
        ax.axhline(3.0, color="k", ls="--", lw=0.8)
        ax.set_xlabel("time (mean collision times)")
        ax.set_ylabel("kurtosis of v_x")
        ax.set_title(f"{dim}D: kurtosis against time (MB: 3)")
        # Checks: the final kurtosis is 3 within 5 standard errors, and the KS test of the
        # final speeds does not reject MB at the 1e-4 level.
        last = snaps[until]
        ok &= abs(last.kurtosis_x - 3.0) < 5 * last.kurtosis_x_err and last.ks_p_speed > 1e-4
    fig.tight_layout()
    png = os.path.join(args.out, "relax.png")
    fig.savefig(png, dpi=90)
    print(f"wrote {png}")
    print("as expected: both gases end Maxwellian" if ok else "UNEXPECTED: not Maxwellian")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
