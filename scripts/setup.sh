#!/usr/bin/env bash
# Sets up hypergas from nothing on Debian 12: installs the Debian packages it needs (only
# those missing; non-interactive; as root or through sudo), then configures and builds a
# Release build in ./build.
#   (no argument)  the `hypergas` command without `bench` and `report` (hypergas-measure):
#                  what the default scene needs
#   --python       also the Python module (build/python/hypergas) and its packages
#   --all          everything: the module, tests, examples and benchmarks
# Idempotent: a second run installs nothing and rebuilds only what changed. Other arguments
# are passed to the CMake configure step.
set -euo pipefail
cd "$(dirname "$0")/.."

level=cli
args=()
for a in "$@"; do
  case "$a" in
    --all) level=all ;;
    --python) [ "$level" = all ] || level=python ;;
    *) args+=("$a") ;;
  esac
done

packages=(
  build-essential cmake pkg-config       # toolchain
  ninja-build                            # build tool: starts a file once its headers exist
  libeigen3-dev                          # vectors (core)
  libpcg-cpp-dev                         # PCG random streams (core)
  libgsl-dev libfftw3-dev                # analysis: statistics, fits, FFT
  libcli11-dev libfmt-dev                # the command: options and output
  libtomlplusplus-dev                    # the command: sweep plans (TOML)
  gnuplot-nox                            # PNG plots
)
python_packages=(
  python3-dev pybind11-dev python3-numpy # the Python module
  libhdf5-dev python3-h5py               # H5MD trajectories (--trajectory-every) and h5py
  python3-matplotlib python3-pytest python3-tqdm  # its example, tests and progress bar
)
case "$level" in
  cli)
    targets=(--target hypergas_cli)
    config=(-DHYPERGAS_BUILD_TESTS=OFF -DHYPERGAS_PYTHON=OFF) ;;
  python)
    packages+=("${python_packages[@]}")
    targets=(--target hypergas_cli --target hypergas_python)
    config=(-DHYPERGAS_BUILD_TESTS=OFF -DHYPERGAS_PYTHON=ON) ;;
  all)
    # Open MPI: sweeps over ranks (the command builds without it); pandas: read_sweep's frames
    # hdf5-tools: h5diff in the resume tests; python3-mdanalysis: its H5MD reader in a test
    packages+=(catch2 libopenmpi-dev openmpi-bin python3-pandas hdf5-tools python3-mdanalysis
               "${python_packages[@]}")
    targets=()
    config=(-DHYPERGAS_BUILD_TESTS=ON -DHYPERGAS_PYTHON=AUTO) ;;
esac

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
# Ninja for a new build folder: unlike Makefiles it compiles a file as soon as the headers it
# needs exist, not after every library the file's target links is built, so the two cores
# stay busy (docs/benchmarks.md: 245 s against 296 s for the command). A folder configured
# before keeps its generator.
generator=()
if [ ! -f build/CMakeCache.txt ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "${config[@]}" ${args[@]+"${args[@]}"} >&2
cmake --build build -j "$jobs" ${targets[@]+"${targets[@]}"} >&2
