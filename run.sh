#!/usr/bin/env bash
# Installs what is missing, builds the `motostab` program only (./test.sh builds the tests, benchmarks
# and example plugins), and runs `motostab ARGS...`.
# With no arguments it runs the main job: a stability sweep of the Whipple benchmark bicycle.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$root/scripts/build.sh" motostab
if [ $# -eq 0 ]; then
  set -- sweep "$root/scenarios/whipple-benchmark.yaml"
fi
exec "$root/build/apps/motostab" "$@"
