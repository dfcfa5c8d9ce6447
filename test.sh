#!/usr/bin/env bash
# Installs what is missing, builds, and runs the test suite with ctest.
#   ./test.sh [CTEST_ARGS...]          Release build (./build), whole suite but the `long` label
#   ./test.sh --long [CTEST_ARGS]      Release build, the `long` label only (wide null tests of diagnose)
#   ./test.sh --sanitize [CTEST_ARGS]  AddressSanitizer + UndefinedBehaviorSanitizer build (./build-asan), whole suite
#   ./test.sh --tsan [CTEST_ARGS]      ThreadSanitizer build (./build-tsan): the tests that run worker threads
#   ./test.sh --fuzz [SECONDS]         libFuzzer targets (clang, ./build-fuzz), SECONDS each (default 60)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
jobs="${MOTOSTAB_JOBS:-$(nproc)}"
mode="${1:-}"
case "$mode" in
  --sanitize)
    shift
    # Without the Python module: an instrumented extension cannot load into the plain interpreter.
    export MOTOSTAB_BUILD_DIR=build-asan MOTOSTAB_CMAKE_ARGS="-DMOTOSTAB_BUILD_BENCH=OFF -DMOTOSTAB_EIGEN_CHECKS=ON -DMOTOSTAB_PYTHON=OFF"
    export MOTOSTAB_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
    export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
    export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
    "$root/scripts/build.sh"
    cd "$root/build-asan"
    ctest --output-on-failure -j "$jobs" -LE long "$@" ;;
  --tsan)
    shift
    # Without the precompiled header and unity groups, so a missing #include is caught here.
    export MOTOSTAB_BUILD_DIR=build-tsan MOTOSTAB_CMAKE_ARGS="-DMOTOSTAB_BUILD_BENCH=OFF -DMOTOSTAB_EIGEN_CHECKS=ON -DMOTOSTAB_PCH=OFF -DMOTOSTAB_UNITY_GROUPS=OFF -DMOTOSTAB_PYTHON=OFF"
    export MOTOSTAB_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer"
    export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}"
    "$root/scripts/build.sh" test_core test_analysis test_apps test_plugins test_uncertainty test_diagnosis motostab
    cd "$root/build-tsan"
    # Everything that runs worker threads: runParallel, threaded sweeps (library, CLI --threads, and
    # the sweep workers' plugin and model-extension replicas, the diagnosis thread pool).
    ctest --output-on-failure -j "$jobs" -R 'Parallel|Threads|SweepWorker' "$@" ;;
  --fuzz)
    shift
    "$root/scripts/fuzz.sh" "${1:-60}" ;;
  --long)
    shift
    "$root/scripts/build.sh"
    cd "$root/build"
    ctest --output-on-failure -j "$jobs" -L long "$@" ;;
  *)
    "$root/scripts/build.sh"
    cd "$root/build"
    ctest --output-on-failure -j "$jobs" -LE long "$@" ;;
esac
