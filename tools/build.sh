#!/usr/bin/env bash
# Configures (Release, tests enabled: fails if numdiff is missing) and builds
# the library, the executable and the benchmark with two jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
