#!/usr/bin/env bash
# Installs the Debian 12 packages porelab needs to build, test and run (idempotent).
# Needs root (or sudo) and access to Debian's package mirrors. Prints what it needs if it
# cannot install.
set -euo pipefail
PKGS=(
  build-essential cmake pkg-config
  liblua5.4-dev lua5.4
  libcairo2-dev libfreetype-dev libpng-dev fonts-dejavu-core
  libsuitesparse-dev libopenblas-dev
  libplplot-dev plplot-driver-cairo
  libosmesa6-dev libsdl2-dev
  libgmsh-dev liblapack-dev liblapacke-dev
)
# ffmpeg: videos; xvfb + xdotool: the live-window test under a virtual X server; parallel: sweeps;
# lammps + openmpi-bin: runs of exported dry disc scenes (porelab export-lammps, test cli_lammps_settle).
# The benchmarks' peers are not installed here (the tests do not need them):
#   apt-get install liggghts freefem++   (tests/bench/run_liggghts.sh, run_freefem*.sh)
OPTIONAL=(ffmpeg xvfb xdotool parallel lammps openmpi-bin)
missing=()
for p in "${PKGS[@]}" "${OPTIONAL[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "porelab: all build dependencies are installed"
  exit 0
fi
echo "porelab: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "porelab: not root and no sudo; please install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
if ! $SUDO apt-get update -qq || ! $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; then
  echo "porelab: apt-get failed; the required packages are: ${PKGS[*]} (optional: ${OPTIONAL[*]})" >&2
  # ffmpeg is optional: retry without it
  req=()
  for p in "${missing[@]}"; do [[ " ${OPTIONAL[*]} " == *" $p "* ]] || req+=("$p"); done
  [ ${#req[@]} -eq 0 ] || $SUDO apt-get install -y -qq --no-install-recommends "${req[@]}" >/dev/null
fi
