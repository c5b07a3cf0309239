"""Two engines, one sheared gas: dilute EDMD under Lees-Edwards boundaries against the DSMC
engine's Boltzmann hard spheres, D = 2..6 (docs/validation.md, "Uniform shear flow").

    python3 examples/13-shear/two_engines.py [out/two-engines] [--a 0.5] [--dims 2,3,4,5,6]

Both engines run the isokinetic steady state at the same shear rate a per ideal-gas mean
collision time. EDMD runs at two packings eta and eta/2 with the same second-virial density
B2 n = 2^(D-1) eta in every D (0.04 and 0.02: eta = 0.01 and 0.005 in 3D): its
finite-density (Enskog) terms are O(B2 n), so 2 X(eta/2) - X(eta) is its dilute limit up to
O((B2 n)^2), which must equal the Boltzmann value within the combined standard errors. Prints one row per D and
component: DSMC, EDMD at each packing, the extrapolation, and the difference in combined
standard errors. Uses build/sim/hypergas, or the command in $HYPERGAS_CLI.
"""

import json
import math
import os
import pathlib
import subprocess
import sys

CLI = os.environ.get("HYPERGAS_CLI", "build/sim/hypergas")
KEYS = ("shear_stress", "normal_stress_xx", "normal_stress_yy", "thermostat_rate")


def run(out, args):
    """Runs the command (or reads the summary a previous run left) and returns it."""
    summary = pathlib.Path(out) / "summary.json"
    if not summary.exists():
        subprocess.run([CLI, "run", *args, "--out", str(out)], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return json.loads(summary.read_text())


def main(argv):
    out = pathlib.Path(argv[0] if argv and not argv[0].startswith("--") else "out/two-engines")
    a = float(argv[argv.index("--a") + 1]) if "--a" in argv else 0.5
    dims = [int(d) for d in (argv[argv.index("--dims") + 1] if "--dims" in argv else "2,3,4,5,6").split(",")]
    common = ["--shear-rate", str(a), "--thermostat", "isokinetic"]
    print(f"isokinetic uniform shear flow, a = {a} per ideal-gas mean collision time")
    print(" D  quantity            DSMC                 EDMD B2n=0.04        EDMD B2n=0.02"
          "        EDMD -> 0            diff/se")
    worst = 0.0
    for d in dims:
        ds = run(out / f"dsmc-{d}d", ["--engine", "dsmc", "--model", "hs", "--dim", str(d),
                                      "--n", "100000", "--init", "maxwell", "--until", "40",
                                      *common])
        ed = {}
        hi, lo = 0.04 / 2 ** (d - 1), 0.02 / 2 ** (d - 1)
        for eta in (hi, lo):
            # until in EDMD time units: 200 ideal mean collision times (nu0 = D 2^D eta /sqrt(pi))
            nu0 = d * 2 ** d * eta / math.sqrt(math.pi)
            # 6D: half the spheres and the time (a sheared scan visits 3^5 x 4 cells)
            n, span = (4000, 100) if d == 6 else (8000, 200)
            ed[eta] = run(out / f"edmd-{d}d-{eta:g}",
                          ["--engine", "edmd", "--dim", str(d), "--n", str(n),
                           "--packing", str(eta), "--until", f"{span / nu0:.6g}",
                           "--equilibration", f"{20 / nu0:.6g}", "--every", f"{1 / nu0:.6g}",
                           *common])
        for k in KEYS:
            x0, e0 = ds[k], ds[k + "_error"]
            x1, e1 = ed[hi][k], ed[hi][k + "_error"]
            x2, e2 = ed[lo][k], ed[lo][k + "_error"]
            xe, ee = 2 * x2 - x1, math.sqrt(4 * e2 ** 2 + e1 ** 2)
            z = (xe - x0) / math.sqrt(ee ** 2 + e0 ** 2)
            worst = max(worst, abs(z))
            print(f"{d:2d}  {k:18s} {x0:8.5f} +- {e0:.5f}   {x1:8.5f} +- {e1:.5f}   "
                  f"{x2:8.5f} +- {e2:.5f}   {xe:8.5f} +- {ee:.5f}   {z:6.2f}")
    print(f"largest difference: {worst:.2f} combined standard errors")


if __name__ == "__main__":
    main(sys.argv[1:])
