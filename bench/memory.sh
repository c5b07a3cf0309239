#!/usr/bin/env bash
# Whole-process peak memory per particle of `hypergas run`: (peak RSS at N - peak RSS at
# N = 1000) / N, for the sizes of docs/benchmarks.md. Peak RSS is the process's maximum
# resident set (getrusage), which summary.json reports as peak_rss_bytes_per_particle * n.
# Usage: bench/memory.sh [path/to/hypergas]   (default build/sim/hypergas). Needs python3
# (Debian python3) to read summary.json.
set -euo pipefail
H=${1:-build/sim/hypergas}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
peak() {  # prints the peak RSS in bytes of: hypergas run ARGS --out DIR --json
  local out
  out=$(mktemp -d -p "$tmp")
  "$H" run "$@" --out "$out" --json | tail -1 |
    python3 -c 'import json,sys; j=json.load(sys.stdin); print(j["peak_rss_bytes_per_particle"]*j["n"], j["engine_bytes_per_particle"])'
  rm -rf "$out"
}
printf '%-58s %12s %14s %12s\n' "run" "n" "peak B/part." "engine B/p."
while IFS='|' read -r label n args; do
  small=$(peak $args --n 1000)
  big=$(peak $args --n "$n")
  engine=${big#* }
  small=${small% *}
  big=${big% *}
  python3 -c "print(f'{\"$label\":<58s} {$n:>12d} {($big - $small) / $n:>14.1f} {$engine:>12.1f}')"
done <<'LIST'
dsmc 3D hard spheres, --until 0.2|10000000|--engine dsmc --dim 3 --until 0.2
edmd 3D packing 0.2618, --until 0.2|256000|--engine edmd --dim 3 --packing 0.2618 --until 0.2
LIST
