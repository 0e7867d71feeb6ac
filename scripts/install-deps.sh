#!/usr/bin/env bash
# Install pdr's dependencies from Debian packages. Idempotent: installs only what is missing.
#   scripts/install-deps.sh          build + run dependencies
#   scripts/install-deps.sh --tests  also the test-only dependencies (RapidCheck, GoogleTest,
#                                    clang and its libFuzzer runtime for the fuzz build,
#                                    TetGen and Gmsh to produce meshes for the checker tests,
#                                    meshio to write and read files in the io tests,
#                                    pybind11, the Python headers and pytest for the
#                                    Python module pdr and its tests, spin to model-check
#                                    the parallel protocol)
#   scripts/install-deps.sh --bench  also the benchmark-only dependencies (CGAL, TetGen)
set -euo pipefail

pkgs=(build-essential cmake ninja-build pkg-config libgmp-dev libboost-dev libcli11-dev
      nlohmann-json3-dev libmetis-dev libopenmpi-dev openmpi-bin)
for arg in "$@"; do
  case "$arg" in
    --tests) pkgs+=(librapidcheck-dev libgtest-dev tetgen gmsh clang libclang-rt-14-dev
                     python3-meshio python3-numpy pybind11-dev python3-dev python3-pytest spin) ;;
    --bench) pkgs+=(libcgal-dev tetgen) ;;
    *) echo "install-deps.sh: unknown option '$arg' (use --tests or --bench)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps.sh: installing ${missing[*]}" >&2
$sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
