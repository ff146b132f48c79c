#!/usr/bin/env bash
# Time per step and per Newton iteration of the 3D Willmore flow, split into
# assembly, multigrid set-up and Krylov solve, for the sphere of
# tools/bench/willmore-sphere-3d.prm on 20^3, 40^3, 60^3 cubic elements and
# 1 and 2 ranks, with the peak memory per rank. Usage (after tools/build.sh):
#   tools/bench/run-willmore-3d.sh [element counts...]
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh
sizes=${*:-20 40 60}
printf "%-6s %-5s %-8s %-6s %-6s %-8s %-9s %-10s %-9s %-9s %-9s %-8s\n" \
  cells ranks unknowns steps newton krylov s/step s/newton assembly mg-setup solve peakMB
for n in $sizes; do
  for np in 1 2; do
    out=output/bench-willmore-3d-$n-$np
    log=$(mpirun -np $np build/vesicle-iga - <<EOP
$(cat tools/bench/willmore-sphere-3d.prm)
set Output directory = $out
subsection Willmore flow
  set Epsilon over h = $((n / 20))
  subsection Mesh
    set Elements = $n
  end
end
EOP
)
    unknowns=$(echo "$log" | sed -n 's/.* \([0-9]*\) unknowns.*/\1/p' | head -1)
    total=$(echo "$log" | sed -n 's/^| Total wallclock time elapsed since start *| *\([0-9.e+-]*\)s.*/\1/p')
    section() { echo "$log" | sed -n "s/^| $1 *| *[0-9]* | *\([0-9.e+-]*\)s.*/\1/p"; }
    read -r steps newton krylov < <(awk -F, 'NR>1 {s++; n+=$4; k+=$5} END {print s, n, k}' $out/time-series.csv)
    peak=$(echo "$log" | sed -n 's/^peak memory (VmHWM) per rank: max \([0-9.]*\) MB.*/\1/p')
    awk -v c="$n^3" -v np=$np -v u=$unknowns -v s=$steps -v nw=$newton -v k=$krylov \
        -v T=$total -v a="$(log_sum assembly residual)" -v p="$(section preconditioner)" \
        -v so="$(section "linear solve")" -v m=$peak 'BEGIN {
      printf "%-6s %-5s %-8s %-6s %-6s %-8s %-9.2f %-10.2f %-9.2f %-9.2f %-9.2f %-8.0f\n",
        c, np, u, s, nw, k, T/s, T/nw, a, p, so, m }'
  done
done
