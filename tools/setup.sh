#!/usr/bin/env bash
# Installs what vesicle-iga needs on Debian 12 (run as root), builds it with
# -j2, runs the default study (two vesicles in a shear flow) and plots it.
# README command 1.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
packages="libdeal.ii-dev cmake g++ make numdiff openmpi-bin python3-matplotlib python3-scipy gnuplot-nox"
missing=""
for p in $packages; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $missing
fi
tools/build.sh
source tools/mpi-env.sh
mpirun -np 2 build/vesicle-iga prm/doublet-shear-quick.prm
/usr/bin/python3 tools/plot-vesicles.py output/doublet-shear-quick/vesicles.png \
  output/doublet-shear-quick
echo "Figure: output/doublet-shear-quick/vesicles.png"
