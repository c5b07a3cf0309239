#!/usr/bin/env bash
# Sets up hypergas from nothing on Debian 12: installs the Debian packages it needs (only
# those missing; non-interactive; as root or through sudo), then configures and builds a
# Release build in ./build: the `hypergas` command (what the default scene needs) and the
# Python module (build/python/hypergas), or with --all everything (tests, examples,
# benchmarks). Idempotent: a second run installs
# nothing and rebuilds only what changed. Other arguments are passed to the CMake
# configure step.
set -euo pipefail
cd "$(dirname "$0")/.."

targets=(--target hypergas_cli)  # + hypergas_python when configured (below)
args=()
for a in "$@"; do
  if [ "$a" = "--all" ]; then targets=(); else args+=("$a"); fi
done

packages=(
  build-essential cmake pkg-config       # toolchain
  libeigen3-dev                          # vectors (core)
  libpcg-cpp-dev                         # PCG random streams (core)
  libgsl-dev libfftw3-dev                # analysis: statistics, fits, FFT
  catch2                                 # tests
  libcli11-dev libfmt-dev                # the command: options and output
  gnuplot-nox                            # PNG plots
  python3-dev pybind11-dev python3-numpy # the Python module
  python3-matplotlib python3-pytest python3-tqdm  # its example, tests and progress bar
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install packages" >&2; exit 1; }
    sudo_cmd=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${args[@]+"${args[@]}"} >&2
if ((${#targets[@]})) && cmake --build build --target help | grep hypergas_python >/dev/null; then
  targets+=(hypergas_python)
fi
cmake --build build -j "$jobs" ${targets[@]+"${targets[@]}"} >&2
