#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure -j "${MOTOSTAB_JOBS:-$(nproc)}" "$@"
