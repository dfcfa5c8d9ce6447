#!/usr/bin/env bash
# Installs the Debian packages motostab needs, only those missing. Run as root (or with sudo available).
# MOTOSTAB_FUZZ_DEPS=1 adds the fuzzing tools.
set -euo pipefail
pkgs=(cmake g++ make libsimbody-dev libeigen3-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
      libfftw3-dev libgtest-dev libbenchmark-dev gnuplot-nox libopenmpi-dev openmpi-bin python3
      # The Python module (python/), its tests and the example notebook (docs/python.md).
      python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib python3-nbclient python3-nbformat
      python3-ipykernel
      # The MATLAB export (linear_models.mat) and its test.
      pkg-config libmatio-dev python3-scipy)
# The fuzz stage (scripts/fuzz.sh) also needs clang and its libFuzzer runtime.
[ -n "${MOTOSTAB_FUZZ_DEPS:-}" ] && pkgs+=(clang-14 libclang-rt-14-dev)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "motostab: installing missing packages: ${missing[*]}" >&2
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
