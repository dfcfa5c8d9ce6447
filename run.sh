#!/usr/bin/env bash
# Installs what is missing, builds the `motostab` program only (./test.sh builds the tests, benchmarks
# and example plugins), and runs `motostab ARGS...`.
# With no arguments it runs the main job: the swingarm study of Taraborrelli, Favaron and Doria ("The
# effect of swingarm stiffness on motorcycle stability") on the supersport motorcycle: weave and wobble
# with a rigid, bending, torsion and twist-compliant swingarm, at identified and halved stiffness, and
# a verdict on each finding of the paper's section 4 (examples/seed-findings/supersport.yaml: agrees,
# disagrees, cannot be checked), the cause diagnosis names for the disagreements, and the extended
# motorcycle ./supersport-study/extended.yaml (report.md, verdicts.json beside it).
# The Whipple benchmark sweep (Meijaard et al. 2007) is `./run.sh sweep scenarios/whipple-benchmark.yaml`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$root/scripts/build.sh" motostab
if [ $# -eq 0 ]; then
  "$root/build/apps/motostab" study "$root/scenarios/supersport.yaml" --out supersport-study
  echo
  echo "The verdicts above are in supersport-study/report.md (first section) and verdicts.json;"
  echo "the extended motorcycle is supersport-study/extended.yaml (motostab sweep supersport-study/extended.yaml)."
  echo "The enduro: ./run.sh study scenarios/enduro.yaml --out enduro-study"
  echo "Next: the Whipple benchmark bicycle's stability sweep, ./run.sh sweep scenarios/whipple-benchmark.yaml"
  exit 0
fi
exec "$root/build/apps/motostab" "$@"
