#!/usr/bin/env bash
# Installs the Debian 12 packages hmira's build, tests, demo and benchmarks use (as root, or
# through sudo). Packages already present are skipped, so a second run costs nothing.
set -euo pipefail
pkgs=(build-essential cmake ninja-build ccache pkg-config
      libgtest-dev libbenchmark-dev libtbb-dev libcli11-dev zlib1g-dev libtinyobjloader-dev
      libopenmesh-dev libcgal-dev libcgal-demo libeigen3-dev
      python3-venv python3-dev libusb-1.0-0 doxygen time
      clang-14 libclang-rt-14-dev clang-16 libclang-rt-16-dev clang-format-16 chromium)
# npm: Debian's package, unless a Node.js with npm is already installed (Debian's npm would
# fight a newer nodejs package over the same files).
command -v npm >/dev/null || pkgs+=(npm)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
