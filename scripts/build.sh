#!/usr/bin/env bash
# Configures and builds motostab incrementally.
#   scripts/build.sh [TARGET...]       Release build in ./build (all targets when none is named)
# Environment: MOTOSTAB_BUILD_DIR (default build); MOTOSTAB_CMAKE_ARGS (extra configure arguments, one
# word each) and MOTOSTAB_CXX_FLAGS (CMAKE_CXX_FLAGS), used when the folder is first configured;
# MOTOSTAB_JOBS (default: the number of cores).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
jobs="${MOTOSTAB_JOBS:-$(nproc)}"
dir="$root/${MOTOSTAB_BUILD_DIR:-build}"
if [ ! -f "$dir/CMakeCache.txt" ]; then
  # shellcheck disable=SC2086
  cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release ${MOTOSTAB_CMAKE_ARGS:-} \
        -DCMAKE_CXX_FLAGS="${MOTOSTAB_CXX_FLAGS:-}" >/dev/null
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
# pipefail: the status is cmake's (the filter never fails).
cmake --build "$dir" -j "$jobs" "${targets[@]}" 2>&1 | { grep -Ev '^\[ *[0-9]+%\]' || true; }
