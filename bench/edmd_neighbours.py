#!/usr/bin/env python3
"""Neighbours per particle within a shell, against D and packing: the size of the
neighbour lists an EDMD with a Verlet shell would keep.

For each D and packing (given as a fraction of D's jamming packing), an equilibrated EDMD
fluid of n particles (hypergas.EDMD, 20 collisions per particle after the lattice start)
is sampled and the particles within a centre distance r < shell * sigma of each particle
are counted (minimum image, all pairs). Prints one row per case: the mean count for each
shell.

    PYTHONPATH=build/python python3 bench/edmd_neighbours.py
"""

import sys

import hypergas as hg

import numpy as np



def neighbours(x, box, shells):
    n = len(x)
    counts = np.zeros(len(shells))
    for i in range(0, n, 256):
        d = x[i:i + 256, None, :] - x[None, :, :]
        d -= box * np.round(d / box)
        r = np.sqrt(np.einsum("ijk,ijk->ij", d, d))
        for k, s in enumerate(shells):
            counts[k] += np.count_nonzero(r < s) - min(256, n - i)  # not itself
    return counts / n


def main():
    shells = (1.2, 1.5, 2.0)
    n = 4000
    print(f"{'D':>2} {'eta':>7} {'eta/eta_J':>9} " + " ".join(f"{'r<' + str(s):>8}" for s in shells))
    for dim in (3, 4, 5, 6):
        for frac in (0.4, 0.7):
            eta = round(frac * hg.jamming_packing(dim), 4)
            g = hg.EDMD(dim=dim, n=n, packing=eta, seed=1)
            while 2 * g.collisions / g.n < 20:
                g.run(g.time + 0.1)
            c = neighbours(np.array(g.positions), g.box_side, shells)
            print(f"{dim:>2} {eta:7.4f} {frac:9.2f} " + " ".join(f"{v:8.1f}" for v in c),
                  flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
