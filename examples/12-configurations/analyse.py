"""Example 12: read the saved trajectory and the twenty runs started from its frames.

    PYTHONPATH=build/python python3 examples/12-configurations/analyse.py out/dense4 out/restart4

Prints the saved state (frames, box, packing from N and the box), the pressure Z of each
run started from a frame, their mean with its standard error, and the parent run's Z.
"""

import json
import math
import sys

import numpy as np

import hypergas as hg

parent, sweep = sys.argv[1], sys.argv[2]
traj = hg.read_trajectory(f"{parent}/trajectory.h5")
L = traj.box[-1]
ball = math.pi ** (traj.dim / 2) / math.gamma(traj.dim / 2 + 1) * 0.5 ** traj.dim
print(f"saved: {len(traj)} frames of {traj.n} spheres in D = {traj.dim}, t = {traj.time[0]}"
      f" .. {traj.time[-1]}, box {L:.6g}, packing {traj.n * ball / L ** traj.dim:.6g}")
print(f"       temperature {traj.observables['temperature'][-1]:.6f} at the last frame")

# the twenty runs: one per frame, Z over each run's window
z = np.asarray(hg.read_sweep(sweep, frame=False)["Z"], dtype=float)
mean, se = z.mean(), z.std(ddof=1) / math.sqrt(len(z))
with open(f"{parent}/summary.json") as f:
    ref = json.load(f)
print(f"runs from frames 1..{len(z)}: Z = {mean:.4f} +- {se:.4f} (mean and standard error)")
print(f"parent run over t in [{ref['equilibration_time']}, {ref['time']}]: "
      f"Z = {ref['Z']:.4f} +- {ref['Z_error']:.4f}")
print(f"difference {(mean - ref['Z']) / math.hypot(se, ref['Z_error']):+.2f} combined se")

# a frame as the arguments of a new engine, in Python
md = hg.EDMD.from_state(**traj.state(-1), seed=1)
md.run(1.0)
print(f"from the last frame in Python: packing {md.packing:.6g}, Z over t in [0, 1] "
      f"{md.pressure_Z:.4f}")
