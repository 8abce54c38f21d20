#!/usr/bin/env bash
# Installs the Debian 12 packages partimix needs to build, test, fuzz, benchmark and plot.
# Idempotent: does nothing when every package is already present.
set -euo pipefail

packages=(
  build-essential cmake make pkg-config
  libeigen3-dev libyaml-cpp-dev libcli11-dev libfmt-dev libspdlog-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy python3-scipy
  clang-format nlohmann-json3-dev libhdf5-dev libnlopt-dev
  # `make fuzz`: clang with libFuzzer and the sanitizer runtimes (libclang_rt.fuzzer is in
  # libclang-rt-14-dev, only recommended by clang), and clang's OpenMP
  clang libclang-rt-14-dev libomp-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: need root to install packages (run as root or with sudo)" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
