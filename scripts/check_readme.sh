#!/usr/bin/env bash
# Runs the README's quick commands as written: every fenced ```sh block whose previous line
# is `<!-- quick -->`, one line at a time, from a scratch folder in which `build` points to
# the build folder and `examples` to the repository's (so `build/sim/hypergas ...`, plan
# files and relative --out folders work as in a fresh clone). Fails on the first command that fails, naming it.
#   usage: check_readme.sh README.md BUILD_DIR
set -euo pipefail
readme=$(realpath "$1")
build=$(realpath "$2")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
ln -s "$build" "$scratch/build"
ln -s "$(dirname "$readme")/examples" "$scratch/examples"  # the sweep plans the README runs
cd "$scratch"
commands=$(awk '
  /^<!-- quick -->$/ { mark = 1; next }
  mark && /^```sh$/ { inside = 1; mark = 0; next }
  inside && /^```$/ { inside = 0; next }
  inside { print }
  { mark = 0 }' "$readme")
[ -n "$commands" ] || { echo "check_readme: no quick sh blocks in $readme" >&2; exit 1; }
count=0
while IFS= read -r line; do
  [ -z "$line" ] && continue
  echo "check_readme: $line" >&2
  if ! bash -c "$line" > /dev/null; then
    echo "check_readme: FAILED: $line" >&2
    exit 1
  fi
  count=$((count + 1))
done <<< "$commands"
echo "check_readme: $count commands ran" >&2
