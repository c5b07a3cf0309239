#!/usr/bin/env bash
# hypergas EDMD against Smallenburg's EDMD (Single and Cell variants), 3D, interleaved:
# three repeats of six cases (N = 32 000 and 256 000 at packing 0.2618, 0.45 and 0.55), the
# codes alternated within each case, the order reversed in the second repeat. Both codes start
# from the same fcc lattice, so at 0.55 (above melting, 0.545) both time the fcc crystal; the
# Cell variant is timed at 0.2618 only. Prints one line per
# run: repeat, N, packing, code, collisions per second (hypergas adds Z and bytes/particle).
# Build Smallenburg's code first (../shared/anchors/README.md); the project does not use it.
# Usage: bench/edmd_vs_smallenburg.sh SMALLENBURG_DIR [path/to/hypergas]
#   SMALLENBURG_DIR holds Single/md and Cell/md (e.g. $TMPDIR/anchors/smallenburg).
set -euo pipefail
S=${1:?usage: bench/edmd_vs_smallenburg.sh SMALLENBURG_DIR [path/to/hypergas]}
H=${2:-build/sim/hypergas}
H=$(cd "$(dirname "$H")" && pwd)/$(basename "$H")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# N packing MAXTIME WARMUP: Smallenburg's run length and warm-up (its time units), chosen so
# that it times about 5e6 collisions of the equilibrated fluid, as `hypergas bench` does.
cases=("32000 0.2618 41 1" "256000 0.2618 6 0.5" "32000 0.45 15 4" "256000 0.45 5.5 4"
       "32000 0.55 11 2" "256000 0.55 3.2 2")
[ -n "${CASES:-}" ] && IFS=';' read -r -a cases <<<"$CASES"  # e.g. CASES="32000 0.55 11 2"
for rep in 1 2 3; do
  for c in "${cases[@]}"; do
    read -r n eta tmax warm <<<"$c"
    order="hg single cell"
    [ $((rep % 2)) = 0 ] && order="cell single hg"
    for who in $order; do
      case $who in
        hg) r=$("$H" bench --engine edmd --dim 3 -n "$n" --packing "$eta" --reps 1 | awk "NR == 1" |
                python3 -c 'import json,sys; j=json.load(sys.stdin); print(j["collisions_per_s"], j["Z"], j["bytes_per_particle"])') ;;
        single) r=$("$S/Single/md" "$n" "$eta" "$tmax" "$warm" | grep BENCH | sed 's/.*rate_after_warmup=//') ;;
        cell) [ "$eta" != 0.2618 ] && continue
              r=$("$S/Cell/md" "$n" "$eta" "$tmax" "$warm" | grep BENCH | sed 's/.*rate_after_warmup=//') ;;
      esac
      echo "rep=$rep n=$n eta=$eta $who $r"
    done
  done
done
