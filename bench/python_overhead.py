#!/usr/bin/env python3
"""Times one DSMC scene from Python and from the command, interleaved.

The scene: hard spheres, delta start, seed 1, until 10, sampling every 0.2 with the
moments recorder (what `hypergas run` does by default). Per repeat, in alternating order:
  cli     `hypergas run --engine dsmc --dim D --n N --until 10 --every 0.2 --out TMP --json`:
          its summary's wall_s (engine construction, run and analysis; not the file writes)
  python  hypergas.DSMC(...) + run(10, every=0.2, observers=[MomentsRecorder()]), timed
          around both calls in the same process
Both make the same trajectory (same seed and stops), so the collision counts must agree.
Prints one line per repeat and the median ratio python / cli.

    PYTHONPATH=build/python python3 bench/python_overhead.py --n 1000000 --reps 5
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import hypergas as hg


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dim", type=int, default=3)
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--cli", default=os.path.join(os.path.dirname(__file__), "..", "build",
                                                  "sim", "hypergas"))
    a = ap.parse_args()
    ratios = []
    for r in range(a.reps):
        res = {}
        for which in (("cli", "python") if r % 2 == 0 else ("python", "cli")):
            if which == "cli":
                with tempfile.TemporaryDirectory() as d:
                    out = subprocess.run(
                        [a.cli, "run", "--engine", "dsmc", "--dim", str(a.dim), "--n",
                         str(a.n), "--until", "10", "--every", "0.2", "--seed", "1",
                         "--out", os.path.join(d, "o"), "--json"],
                        capture_output=True, text=True, check=True).stdout
                s = json.loads(out.strip().splitlines()[-1])
                res["cli"] = (s["wall_s"], s["collisions"])
            else:
                t0 = time.perf_counter()
                g = hg.DSMC(dim=a.dim, n=a.n, seed=1)
                g.run(10.0, every=0.2, observers=[hg.MomentsRecorder()])
                res["python"] = (time.perf_counter() - t0, g.collisions)
                del g
        assert res["cli"][1] == res["python"][1], "different trajectories"
        ratio = res["python"][0] / res["cli"][0]
        ratios.append(ratio)
        print(f"rep {r}: cli {res['cli'][0]:.3f} s, python {res['python'][0]:.3f} s, "
              f"ratio {ratio:.3f}, collisions {res['cli'][1]}", flush=True)
    print(f"median python/cli: {statistics.median(ratios):.3f} over {a.reps} interleaved pairs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
