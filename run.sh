#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (root, or a user with sudo):
#   ./run.sh main    install missing packages, build into build/, run the main job
#   ./run.sh test    install missing packages, build, run the whole test suite (release, then the
#                    unit tests again under AddressSanitizer + UndefinedBehaviorSanitizer)
#   ./run.sh bench   build and run the benchmarks (figures in docs/performance.md)
#   ./run.sh study   build and regenerate the accuracy-versus-cost study (docs/figures/)
set -euo pipefail
cd "$(dirname "$0")"

# Debian packages the build needs; each is installed only when missing.
# python3-matplotlib draws the point driver's figures (pointdriver plot, verify, convergence).
PACKAGES=(cmake g++ libeigen3-dev libgsl-dev libboost-test-dev nlohmann-json3-dev python3-matplotlib)

install_missing_packages() {
  local missing=() p
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "run.sh: installing missing Debian packages: ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {  # build <preset>
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1"
}

case "${1:-}" in
  main)
    install_missing_packages
    build release
    build/bin/material_check data/materials/al6061_t6.json >/dev/null
    build/bin/pointdriver verify --out build/pointdriver_verify
    ;;
  test)
    install_missing_packages
    build release
    ctest --preset release
    build asan
    ctest --preset asan
    ;;
  bench)
    install_missing_packages
    build release
    build/bin/models_benchmark "${@:2}"
    build/bin/pointdriver_benchmark
    build/bin/mpm_benchmark
    ;;
  study)
    install_missing_packages
    build release
    build/bin/pointdriver convergence --out docs/figures
    ;;
  *)
    sed -n '2,8p' "$0"
    exit 1
    ;;
esac
