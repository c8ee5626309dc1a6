#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (root, or a user with sudo):
#   ./run.sh main    install missing packages, build into build/, run the main job: the report's
#                    recommended sphere-cylinder impact (history, figure, VTK in out/recommended/)
#   ./run.sh test    install missing packages, build, run the whole test suite (release, then the
#                    unit tests again under AddressSanitizer + UndefinedBehaviorSanitizer, then a
#                    one-minute libFuzzer run of the input loaders, clang, build-fuzz/)
#   ./run.sh fuzz [SECONDS]  build the libFuzzer targets of the input loaders (build-fuzz/) and run
#                    each for SECONDS (default 600) from a scratch copy of its seed corpus;
#                    findings in build-fuzz/findings/ (tests/fuzz/run_fuzz.sh, docs/reliability.md)
#   ./run.sh mpi [RANKS]  install Open MPI when missing, build with it, and run the recommended
#                    scene on RANKS (default 2) ranks of one thread (docs/mpi.md; results in
#                    out/recommended-mpi/recommended/)
#   ./run.sh mpi-bench [RANKS]  ranks against threads on the 2.25x sphere-cylinder grid, slabs
#                    and (2 ranks) boxes cut across y and across z (campaigns/benchmark/mpi_scaling.py;
#                    figures in docs/mpi.md; about 12 min once built)
#   ./run.sh bench   build and run the benchmarks (figures in docs/performance.md)
#   ./run.sh study   build and regenerate the accuracy-versus-cost study (docs/figures/)
#   ./run.sh table2  build and run the report's 16 cases (docs/figures/sphere_cylinder/)
#   ./run.sh stability  build and run the sphere-cylinder stability map (docs/figures/stability/)
#   ./run.sh accuracy   build and run the speed-versus-accuracy study (docs/figures/accuracy/)
#   ./run.sh quarter    build and run the quarter model against the full model (docs/figures/quarter_model/)
#   ./run.sh laws    build and plot the flow-stress laws of each shipped material
#                    (docs/figures/materials_*.png, docs/models.md)
#   ./run.sh paraview  install ParaView's Python (python3-paraview, xvfb) when missing and draw the
#                    main job's last snapshot coloured by plastic strain with pvpython
#                    (campaigns/plot/paraview_snapshot.py -> out/recommended/plastic_strain.png)
#   ./run.sh taylor [OUT] [OPTIONS]  build and run the House et al. Taylor shots against the
#                    experiments (docs/taylor.md; OUT defaults to docs/figures/taylor/)
set -euo pipefail
cd "$(dirname "$0")"

# Debian packages the build needs; each is installed only when missing.
# python3-matplotlib draws the point driver's figures (pointdriver plot, verify, convergence);
# python3-dev and pybind11-dev build the Python module impact (docs/python.md; optional: without
# them it is left out).
# libcli11-dev parses every program's command line (support/command_line.hpp).
# libmuparser-dev compiles the expressions of scenes (mpm/scene/expression.hpp).
PACKAGES=(cmake g++ libeigen3-dev libgsl-dev libboost-test-dev nlohmann-json3-dev libcli11-dev
  libmuparser-dev python3-matplotlib python3-dev pybind11-dev)
# clang-14 + libclang-rt-14-dev (libFuzzer, sanitizer runtimes) build the fuzz targets (test, fuzz)
# and the ASan + UBSan build (test); libomp-14-dev is clang's OpenMP, which the ASan build's
# solver and tests link.
FUZZ_PACKAGES=(clang-14 libclang-rt-14-dev)
SANITIZER_PACKAGES=("${FUZZ_PACKAGES[@]}" libomp-14-dev)
# clang-format-14 checks every C++ file against .clang-format (test `clang_format`); pytest runs
# the Python module's tests (python_pytest); python3-venv makes the virtual environment that
# `pip install .` installs into (python_pip_install; it brings pip's wheel for the venv).
# python3-sympy derives the manufactured solutions' body forces
# (campaigns/verification/manufactured_solutions.py, tests mpm_manufactured_*).
TEST_TOOL_PACKAGES=(clang-format-14 python3-pytest python3-venv python3-sympy)
# Open MPI builds the domain decomposition (docs/mpi.md); the test job runs it on 2 and 4 ranks.
# Optional: without it everything builds and runs on one rank.
MPI_PACKAGES=(libopenmpi-dev openmpi-bin)

install_missing_packages() {  # install_missing_packages [EXTRA_PACKAGE ...]
  local missing=() p
  for p in "${PACKAGES[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "run.sh: installing missing Debian packages: ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {  # build <preset> [CMAKE_ARG ...]
  cmake --preset "$1" "${@:2}" >/dev/null
  cmake --build --preset "$1"
}

build_programs() {  # build_programs [CMAKE_ARG ...]: the release programs and the Python module
  cmake --preset release "$@" >/dev/null  # only (no tests), into build/bin
  cmake --build --preset programs
}

case "${1:-}" in
  main)
    install_missing_packages
    build_programs
    build/bin/material_check data/materials/al6061_t6.json >/dev/null
    # The report's conclusion (KeepStress, single_velocity, multiplier 0.1): writes
    # out/recommended/recommended/{history.csv, summary.json, particles.pvd, particles/*.vtu},
    # then the energy/momentum figure and the summary table beside it.
    build/bin/mpm run data/scenes/sphere_cylinder/recommended.json \
      --out out/recommended/recommended --threads "$(nproc)"
    /usr/bin/python3 campaigns/study/study_plot.py out/recommended
    ;;
  test)
    install_missing_packages "${SANITIZER_PACKAGES[@]}" "${TEST_TOOL_PACKAGES[@]}" "${MPI_PACKAGES[@]}"
    # The test job treats every compiler warning as an error (-Wall -Wextra -Wpedantic are on).
    build release -DCMAKE_COMPILE_WARNING_AS_ERROR=ON
    # JUnit XML of each run for CI servers, in its build directory (build/junit.xml, ...). Tests run
    # side by side on every core; each one that runs 2 threads claims 2 (PROCESSORS).
    ctest --preset release --output-junit junit.xml -j "$(nproc)"
    build asan -DCMAKE_COMPILE_WARNING_AS_ERROR=ON
    ctest --preset asan --output-junit junit.xml -j "$(nproc)"
    # Each loader's fuzz target for a few seconds (about a minute in all); fails on any finding.
    build fuzz -DCMAKE_COMPILE_WARNING_AS_ERROR=ON
    ctest --preset fuzz --output-junit junit.xml -j "$(nproc)"
    ;;
  mpi)
    install_missing_packages "${MPI_PACKAGES[@]}"
    build_programs -DIMPACT_MPI=ON
    # As root Open MPI needs its allow flags; --oversubscribe lets RANKS exceed the cores.
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 \
      mpirun -np "${2:-2}" --oversubscribe build/bin/mpm run \
      data/scenes/sphere_cylinder/recommended.json --out out/recommended-mpi/recommended --threads 1
    /usr/bin/python3 campaigns/study/study_plot.py out/recommended-mpi
    ;;
  mpi-bench)
    install_missing_packages "${MPI_PACKAGES[@]}"
    build_programs -DIMPACT_MPI=ON
    if [ "${2:-2}" = 2 ]; then splits=(--splits 1x2x1 1x1x2); else splits=(); fi
    /usr/bin/python3 campaigns/benchmark/mpi_scaling.py build/bin/mpm build/mpi-bench --ranks "${2:-2}" \
      "${splits[@]}"
    ;;
  paraview)
    # python3-paraview brings pvpython (about 450 MB with ParaView); xvfb renders without a display.
    install_missing_packages python3-paraview xvfb xauth
    if [ ! -f out/recommended/recommended/particles.pvd ]; then
      echo "run.sh paraview: no out/recommended/recommended/particles.pvd: run ./run.sh main first" >&2
      exit 1
    fi
    xvfb-run -a pvpython campaigns/plot/paraview_snapshot.py out/recommended/recommended \
      --out out/recommended/plastic_strain.png
    ;;
  fuzz)
    install_missing_packages "${FUZZ_PACKAGES[@]}"
    build fuzz
    tests/fuzz/run_fuzz.sh build-fuzz "${2:-600}"
    ;;
  bench)
    install_missing_packages
    build release
    build/bin/machine_probe  # memory bandwidth and FMA peak per ISA (the roofline's limits)
    # vector pow/log (libmvec) on the Johnson-Cook flow stress (x86-64 only)
    if [ -x build/bin/simd_math_probe ]; then build/bin/simd_math_probe; fi
    build/bin/models_benchmark "${@:2}"
    build/bin/pointdriver_benchmark
    # Scaling, feature cost and box size of the explicit step (CSV + figures in
    # docs/figures/performance/; best of 3-5 repeats: 6 min on the 2-core VM).
    build/bin/mpm_benchmark --out docs/figures/performance
    /usr/bin/python3 campaigns/benchmark/plot_benchmark.py docs/figures/performance
    ;;
  study)
    install_missing_packages
    build_programs
    build/bin/pointdriver convergence --out docs/figures
    ;;
  table2)
    install_missing_packages
    build_programs
    build/bin/mpm study data/scenes/sphere_cylinder --out docs/figures/sphere_cylinder --threads 2
    ;;
  accuracy)
    install_missing_packages
    build_programs
    # Variants of recommended.json (grid x1, x1.5, x2.25 per interpolation/scheme, x3 for
    # gimp/MUSL, multipliers, particles per cell) to 40 us, their observables against the
    # Richardson-extrapolated or finest run, Pareto charts (docs/accuracy.md); 77 min of runs on
    # the 2-core VM at half speed (2026-11-24), the 3x grid 33 min of it. Options after
    # `accuracy` go to the script, e.g. --levels 1,1.5,2.25 (no 3x grid), --max-level-others 1.5
    # (the 2.25x grid for gimp/MUSL only) or --jobs 2 --threads 1.
    /usr/bin/python3 campaigns/study/accuracy_study.py docs/figures/accuracy --mpm build/bin/mpm \
      --threads 2 "${@:2}"
    ;;
  quarter)
    install_missing_packages
    build_programs
    # The centred impact as a quarter with symmetric planes against the full model, 40 us
    # (docs/performance.md#quarter-model).
    /usr/bin/python3 campaigns/study/quarter_model.py docs/figures/quarter_model --mpm build/bin/mpm \
      --threads 1 "${@:2}"
    ;;
  taylor)
    install_missing_packages
    build_programs
    # House et al. (1995) Taylor shots (data/experiments/taylor/) with the Table 1 set and the set
    # `pointdriver fit` gives from the stress-strain curves, failure off, 6 cells per radius, two
    # runs at a time (docs/taylor.md). Options after OUT go to the script and override these,
    # e.g. the failure study: ./run.sh taylor docs/figures/taylor_failure --sets fit_all
    #   --cells-per-radius 4 --failure off,shipped,compression_aware
    /usr/bin/python3 campaigns/taylor/taylor.py "${2:-docs/figures/taylor}" --runs build/taylor \
      --sets table1,fit_all --cells-per-radius 6 --jobs "$(nproc)" --threads 1 "${@:3}"
    ;;
  laws)
    install_missing_packages
    build_programs
    # Every flow-stress law of each shipped material at 1e-3 and 1e3 /s, 294 and 600 K
    # (docs/models.md; figures and CSV in docs/figures/; a few seconds).
    /usr/bin/python3 pointdriver/plot/material_laws.py build/bin/pointdriver docs/figures
    ;;
  stability)
    install_missing_packages
    build_programs
    # 112 variants (multiplier x interpolation x contact x AV x velocity) + the report's case 2
    # row, 10 us each, classified stable / energy-drifting / unstable (docs/accuracy.md).
    /usr/bin/python3 campaigns/study/stability_map.py --out docs/figures/stability --mpm build/bin/mpm \
      --threads 2 "${@:2}"
    ;;
  *)
    sed -n '2,/^set -euo/p' "$0" | sed '$d'  # the header comment, whole
    exit 1
    ;;
esac
