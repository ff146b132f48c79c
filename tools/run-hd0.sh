#!/usr/bin/env bash
# HD0 (spec 6.3): prm/hd0-mesh-convergence.prm at N elements per unit
# length with eps = 2h, each to its end time on 2 ranks (RANKS to change),
# then the relative area and volume errors at the end per level as CSV,
# and the length and area of the zero level set at t = 0 and T.
# Usage (after tools/build.sh): tools/run-hd0.sh [N...]   (default 8 16 32)
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/mpi-env.sh
levels=${*:-8 16 32}
RANKS=${RANKS:-2}
for m in $levels; do
  out=output/hd0-mesh-convergence-$m
  eps=$(awk -v m=$m 'BEGIN {print 2 / m}')
  mpirun -np $RANKS build/vesicle-iga - >$out.log 2>&1 <<EOP
$(cat prm/hd0-mesh-convergence.prm)
set Output directory = $out
subsection Vesicle hydrodynamics
  set Epsilon = $eps
  subsection Mesh
    set Elements = $((5 * m)), $((5 * m))
  end
end
EOP
done
echo "per-unit,eps,steps,area_error,volume_error"
for m in $levels; do
  awk -F, -v m=$m 'NR == 1 {for (i = 1; i <= NF; ++i) c[$i] = i}
    END {printf "%s,%g,%s,%s,%s\n", m, 2 / m, $1, $c["area_error_1"], $c["volume_error_1"]}' \
    output/hd0-mesh-convergence-$m/time-series.csv
done
# The zero level set of each level (length and enclosed area at t = 0 and
# T, from the membrane samples); results and run times:
# doc/hydrodynamics.md, "HD0: mesh convergence".
for m in $levels; do
  python3 tools/zero-set.py output/hd0-mesh-convergence-$m
done
