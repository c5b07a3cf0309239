#!/usr/bin/env bash
# compare_runs.sh OLD NEW [WORK] -- behaviour kept across a restructuring: runs two builds of
# the `hypergas` command (OLD and NEW: paths of the binaries) on the same fixed-seed cases
# (DSMC exact, NTC, lanes, granular, driven, sheared, trajectory; EDMD plain, sheared,
# granular, trajectory) and compares their outputs: every CSV and stderr with cmp,
# trajectory.h5 with h5diff, plot.gp with cmp, and summary.json key by key less the wall
# times and the build's identity. Prints one line per case; exit 1 if any differs.
set -uo pipefail
OLD=$1; NEW=$2; W=${3:-$(mktemp -d)}
rm -rf "$W"; mkdir -p "$W"
cases=(
 "dsmc_exact|--dim 3 --n 2000 --until 4 --seed 3"
 "dsmc_ntc|--dim 2 --n 2000 --until 4 --scheme ntc --dt 0.02 --seed 3"
 "dsmc_lanes|--dim 4 --n 4000 --until 4 --scheme lanes --seed 3"
 "dsmc_granular|--dim 3 --n 2000 --until 4 --restitution 0.8 --seed 3"
 "dsmc_driven|--dim 3 --n 2000 --until 4 --restitution 0.8 --drive white-noise --seed 3"
 "dsmc_shear|--dim 3 --n 2000 --until 4 --shear-rate 0.5 --thermostat isokinetic --model maxwell --seed 3"
 "dsmc_traj|--dim 3 --n 500 --until 2 --trajectory-every 0.5 --seed 3"
 "edmd|--engine edmd --dim 3 --n 500 --packing 0.3 --until 4 --seed 3"
 "edmd_shear|--engine edmd --dim 2 --n 900 --packing 0.2 --until 4 --shear-rate 0.5 --thermostat isokinetic --seed 3"
 "edmd_granular|--engine edmd --dim 3 --n 500 --packing 0.2 --until 4 --restitution 0.9 --seed 3"
 "edmd_traj|--engine edmd --dim 3 --n 500 --packing 0.3 --until 2 --trajectory-every 0.5 --seed 3"
)
status=0
for c in "${cases[@]}"; do
  name=${c%%|*}; read -r -a args <<< "${c#*|}"
  a=$W/old_$name; b=$W/new_$name
  "$OLD" run "${args[@]}" --out "$a" > /dev/null 2> "$a.err"
  "$NEW" run "${args[@]}" --out "$b" > /dev/null 2> "$b.err"
  res=""
  for f in $(cd "$a" && ls *.csv plot.gp 2>/dev/null); do
    cmp -s "$a/$f" "$b/$f" || res="$res $f"
  done
  if [ -f "$a/trajectory.h5" ]; then
    h5diff -q "$a/trajectory.h5" "$b/trajectory.h5" > /dev/null 2>&1 || res="$res trajectory.h5"
  fi
  cmp -s "$a.err" "$b.err" || res="$res stderr"
  keys=$(python3 - "$a/summary.json" "$b/summary.json" <<'PY'
import json, sys
skip = {"wall_s", "collisions_per_s", "setup_s", "engine_s", "analysis_s", "output_s",
        "peak_rss_bytes_per_particle", "git", "version"}
x, y = (json.load(open(p)) for p in sys.argv[1:3])
print(" ".join(sorted(k for k in set(x) | set(y) if k not in skip and x.get(k) != y.get(k))))
PY
)
  [ -n "$keys" ] && res="$res summary.json($keys)"
  if [ -n "$res" ]; then echo "$name: differ:$res"; status=1; else echo "$name: identical"; fi
done
exit $status
