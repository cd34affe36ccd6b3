#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine: installs what is missing (apt-get) and
# configures build/ (Release) and builds firsthit there: one binary that runs
# on any x86-64 CPU at its widest SIMD (the tracer built for x86-64-v2, v3
# and v4, chosen at start-up). FIRSTHIT_ARCH=host (or native, x86-64-vN)
# bash scripts/setup.sh builds for one CPU only.
#   bash scripts/setup.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

packages=(build-essential cmake pkg-config libglm-dev libstb-dev libyaml-cpp-dev zlib1g-dev
          googletest libgtest-dev libbenchmark-dev ffmpeg gnuplot-nox
          libassimp-dev  # mesh files: OBJ, PLY, STL, OFF
          libtinygltf-dev nlohmann-json3-dev  # glTF 2.0 files (src/gltf)
          assimp-testmodels  # the glTF, OBJ, PLY, STL and OFF files of tests/gltf
          python3  # scripts/gltf_demo.py writes the glTF demo
          clang libclang-rt-14-dev  # clang, libclang-rt: the sanitizer builds and the fuzzers (scripts/test_tsan.sh, build_asan.sh)
          slurm-wlm munge  # a one-node Slurm cluster for tests/slurm/test_slurm.sh
          libembree-dev  # bench/embree_reference: the Embree 3 peer of the mesh benchmarks (optional at build time)
          libglfw3-dev libgl-dev  # firsthit view's window (optional at build time)
          xvfb xdotool libgl1-mesa-dri)  # its test: a virtual X server, keys, Mesa's software GL
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "setup: installing ${missing[*]}"
  sudo=""; [[ $(id -u) -eq 0 ]] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release -DFIRSTHIT_ARCH="${FIRSTHIT_ARCH:-dispatch}" >/dev/null
# The program alone: the tests, the Embree peer and the benchmarks are
# built when asked for (scripts/test.sh, make bench-...), which spares a
# first `make movies` about a quarter of the compiling.
cmake --build "$here/build" -j "$(nproc)" --target firsthit
echo "setup: built $here/build/firsthit"
