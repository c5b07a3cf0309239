#!/usr/bin/env bash
# Wall time of `hypergas sweep` without MPI and under mpirun -np P, interleaved:
#   long   24 DSMC cases of about 2 s each (3D hard spheres, N = 1e5, until = 540, seeds
#          1..24): the sweep's speed-up on P ranks;
#   tiny   200 cases of a few ms (2D, N = 50, until 0.2): cases per second, which the
#          per-case costs (output folder, CSV, gnuplot) and the hand-out limit.
# Each line: the kind, the way (none = no MPI; npP), the repetition, the job's wall time
# (mpirun's start included), the sweep's own wall time and rank 0's mean time from a
# request to the next case (`sweep --json`: coordination_ms). `long` skips np1 (the same
# cases in one process). Before each repetition of `long`, the machine's ceiling: one long
# case alone, then two at once as two plain `hypergas run` processes (`pair`: job_s is the
# pair's wall time, sweep_s the single one's), so ceiling = 2 single / pair. Repetitions
# alternate the ways so that the machine's load changes hit them alike.
# Usage: bench/sweep_scaling.sh [reps] [build dir] [max ranks]   (defaults 2, build, nproc)
#        KINDS="long" bench/sweep_scaling.sh ...   (one kind only)
set -euo pipefail
reps=${1:-2}
B=${2:-build}
maxp=${3:-$(nproc)}
H=$(realpath "$B/sim/hypergas")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
root=()
[ "$(id -u)" -eq 0 ] && root=(--allow-run-as-root)
# plan NAME DIM N UNTIL CASES: DSMC cases that differ in their seed (1..CASES)
plan() {
  printf 'engine = "dsmc"\ndim = %s\nn = %s\nuntil = %s\n[sweep]\nseed = { from = 1, to = %s, step = 1 }\n' \
    "$2" "$3" "$4" "$5" > "$tmp/$1.toml"
}
plan long 3 100000 540 24
plan tiny 2 50 0.2 200
ways=(none)
for ((p = 1; p <= maxp; ++p)); do ways+=("np$p"); done
printf '%-5s %-5s %3s %9s %9s %15s\n' kind way rep job_s sweep_s coordination_ms
now() { date +%s.%N; }
for kind in ${KINDS:-long tiny}; do
  for ((r = 0; r < reps; ++r)); do
    if [ "$kind" = long ]; then
      one=(run --dim 3 --n 100000 --until 540 --seed 99)
      t0=$(now)
      "$H" "${one[@]}" --out "$tmp/single" > /dev/null
      t1=$(now)
      "$H" "${one[@]}" --out "$tmp/pa" > /dev/null & "$H" "${one[@]}" --out "$tmp/pb" > /dev/null
      wait
      t2=$(now)
      python3 -c 'import sys; a, b, c = map(float, sys.argv[1:4]); print("%-5s %-5s %3d %9.3f %9.3f %15s" % ("long", "pair", int(sys.argv[4]), c - b, b - a, "-"))' "$t0" "$t1" "$t2" "$r"
      rm -rf "$tmp/single" "$tmp/pa" "$tmp/pb"
    fi
    for way in "${ways[@]}"; do
      [ "$kind" = long ] && [ "$way" = np1 ] && continue
      out="$tmp/$kind-$way-$r"
      cmd=("$H" sweep "$tmp/$kind.toml" --out "$out" --json)
      [ "$way" != none ] && cmd=(mpirun "${root[@]}" --oversubscribe -np "${way#np}" "${cmd[@]}")
      t0=$(now)
      last=$("${cmd[@]}" 2>/dev/null | tail -1)
      t1=$(now)
      python3 -c '
import json, sys
j = json.loads(sys.argv[1])
print("%-5s %-5s %3d %9.3f %9.3f %15.3f" % (sys.argv[2], sys.argv[3], int(sys.argv[4]),
      float(sys.argv[6]) - float(sys.argv[5]), j["wall_s"], j["coordination_ms"]))' \
        "$last" "$kind" "$way" "$r" "$t0" "$t1"
      rm -rf "$out"
    done
  done
done
