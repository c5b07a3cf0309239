#!/usr/bin/env bash
# Where the wall time of a default `hypergas run` goes: engine, per-snapshot analysis and
# output (CSV and plots), from summary.json, for DSMC 3D hard spheres at N = 1e6 and 1e7
# (add 1e8 with --large: 3.3 GB of memory and several minutes), default --every (until/50).
# Usage: bench/analysis_split.sh [--large] [-j T] [path/to/hypergas]
#        (default build/sim/hypergas; -j T runs engine and analysis on T threads).
# Needs python3 (Debian python3) to read summary.json.
set -euo pipefail
sizes=(1000000 10000000)
if [ "${1:-}" = "--large" ]; then sizes+=(100000000); shift; fi
threads=1
if [ "${1:-}" = "-j" ]; then threads=$2; shift 2; fi
H=${1:-build/sim/hypergas}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-10s %10s %10s %10s %10s %9s %12s %10s\n' n wall_s engine_s analysis_s output_s \
  analysis% "engine c/s" "B/particle"
for n in "${sizes[@]}"; do
  out=$(mktemp -d -p "$tmp")
  "$H" run --engine dsmc --dim 3 --n "$n" --until 1 --seed 1 --threads "$threads" --out "$out" --json | tail -1 |
    python3 -c '
import json, sys
j = json.load(sys.stdin)
n, e, a, o = j["n"], j["engine_s"], j["analysis_s"], j["output_s"]
rate, mem = j["collisions_per_s"], j["peak_rss_bytes_per_particle"]
print("%-10d %10.2f %10.2f %10.2f %10.2f %8.1f%% %12.4g %10.1f"
      % (n, j["wall_s"] + o, e, a, o, 100 * a / (e + a + o), rate, mem))'
  rm -rf "$out"
done
