#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan, ./build-fuzz) and runs each for
# SECONDS (default 60) from its seed corpus. A finding stops with the crashing input saved as
# build-fuzz/findings/<target>/crash-*; fix it and copy the input to tests/fuzz/<target>/regressions/.
#   scripts/fuzz.sh [SECONDS] [TARGET...]    targets: scenario bicycle_parameters csv identification measured_data
#                                            tir overrides steer_controller yaml (default: all)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
# A fixed seed makes a run repeatable: the inputs CI tries are a prefix of a longer local run's.
seed="${MOTOSTAB_FUZZ_SEED:-1}"
MOTOSTAB_FUZZ_DEPS=1 "$root/scripts/install-deps.sh"
export MOTOSTAB_BUILD_DIR=build-fuzz
export MOTOSTAB_CMAKE_ARGS="-DCMAKE_CXX_COMPILER=clang++-14 -DMOTOSTAB_FUZZ=ON -DMOTOSTAB_BUILD_BENCH=OFF -DMOTOSTAB_EIGEN_CHECKS=ON -DMOTOSTAB_PYTHON=OFF"
export MOTOSTAB_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g"
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(scenario bicycle_parameters csv identification measured_data tir overrides steer_controller yaml)
fi
"$root/scripts/build.sh" "${targets[@]/#/fuzz_}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
for t in "${targets[@]}"; do
  work="$root/build-fuzz/corpus/$t" findings="$root/build-fuzz/findings/$t"
  mkdir -p "$work" "$findings"
  echo "fuzz_$t: ${seconds} s"
  # New inputs go to build-fuzz/corpus/<target> (kept between runs); the seeds stay read-only.
  status=0
  "$root/build-fuzz/tests/fuzz/fuzz_$t" -seed="$seed" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$findings/" -print_final_stats=1 "$work" "$root/tests/fuzz/$t/corpus" \
      "$root/tests/fuzz/$t/regressions" >"$findings.log" 2>&1 || status=$?
  grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|SUMMARY|fuzz finding)' "$findings.log" || true
  [ "$status" -eq 0 ] || { tail -40 "$findings.log" >&2; echo "fuzz_$t: FINDING, input in $findings" >&2; exit 1; }
done
