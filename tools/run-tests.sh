#!/usr/bin/env bash
# Builds vesicle-iga and runs the whole test suite (deal.II test macros,
# numdiff comparison, serial and 2-rank variants). README command 2; CI runs
# exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/mpi-env.sh
tools/build.sh
cmake --build build --target test-programs -j2
cd build
ctest -j2 --output-on-failure
