#!/usr/bin/env bash
# Where the wall time of a recorded `hypergas run` goes: engine (with the collision-level
# tally it keeps), per-row analysis and output (CSV and plots), from summary.json, for DSMC
# hard spheres, beams, default sampling (51 rows) to --until 10, in 3D and 6D at
# N = 1e4, 1e6, 1e7 (add 1e8 with --large: 3.3 GB in 3D and several minutes); then
# bench_tally: the same engine with and without the tally (interleaved pairs) and one
# streaming read of the velocities, the floor of a pass over the particles.
# Usage: bench/analysis_split.sh [--large] [-j T] [build dir]   (default build)
# Needs python3 (Debian python3) to read summary.json.
set -euo pipefail
sizes=(10000 1000000 10000000)
if [ "${1:-}" = "--large" ]; then sizes+=(100000000); shift; fi
threads=1
if [ "${1:-}" = "-j" ]; then threads=$2; shift 2; fi
B=${1:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-3s %-10s %9s %9s %10s %9s %9s %11s %10s\n' D n wall_s engine_s analysis_s \
  output_s "share%" "engine c/s" "B/particle"
for dim in 3 6; do
  for n in "${sizes[@]}"; do
    out=$(mktemp -d -p "$tmp")
    "$B/sim/hypergas" run --engine dsmc --dim "$dim" --n "$n" --init beams --until 10 --seed 1 \
      --threads "$threads" --out "$out" --json | tail -1 |
      python3 -c '
import json, sys
j = json.load(sys.stdin)
n, e, a, o = j["n"], j["engine_s"], j["analysis_s"], j["output_s"]
rate, mem = j["collisions_per_s"], j["peak_rss_bytes_per_particle"]
print("%-3d %-10d %9.3f %9.3f %10.4f %9.3f %8.1f%% %11.4g %10.1f"
      % (j["dim"], n, j["wall_s"] + o, e, a, o, 100 * (a + o) / (e + a + o), rate, mem))'
    rm -rf "$out"
  done
done
echo "# the tally's cost inside engine_s (bench_tally, medians of 3 interleaved pairs)"
"$B/bench/bench_tally" --dims 3,6 --ns "$(IFS=,; echo "${sizes[*]}")" --until 10 --reps 3
