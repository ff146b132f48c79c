#!/usr/bin/env bash
# Time per step and per Newton iteration (assembly, block-preconditioner
# set-up, FGMRES solve) and the iteration counts of the 3D channel set-up of
# tools/bench/channel-3d.prm on 1 and 2 ranks. Usage (after tools/build.sh):
#   tools/bench/run-channel-3d.sh [element count per direction, default 16]
# Environment: VELOCITY (spline-multigrid or amg), RANKS (default "1 2").
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh
n=${1:-16}
VELOCITY=${VELOCITY:-spline-multigrid}
RANKS=${RANKS:-1 2}
echo "3D channel, $n^3 elements, p = 2, 5 steps of dt = 1e-2, fgmres-block" \
  "(velocity: $VELOCITY); times in seconds"
printf "%-6s %-5s %-8s %-6s %-6s %-10s %-8s %-10s %-10s %-9s %-9s %-8s\n" \
  cells ranks unknowns steps newton krylov/nwt s/step s/newton assembly/nwt pc/nwt solve/nwt peakMB
for np in $RANKS; do
  out=output/bench-channel-3d-$n-$np
  log=$(mpirun -np $np build/vesicle-iga - <<EOP
$(cat tools/bench/channel-3d.prm)
set Output directory = $out
subsection Navier-Stokes
  subsection Mesh
    set Elements = $n, $n, $n
  end
  subsection Linear solver
    subsection Block preconditioner
      set Velocity preconditioner = $VELOCITY
    end
  end
end
EOP
)
  unknowns=$(log_unknowns)
  total=$(log_total)
  read -r steps newton krylov < <(series_counts $out)
  peak=$(log_peak_mb)
  awk -v c="$n^3" -v np=$np -v u=$unknowns -v s=$steps -v nw=$newton -v k=$krylov \
      -v T=$total -v a="$(log_section assembly)" -v r="$(log_section residual)" \
      -v p="$(log_section preconditioner)" -v so="$(log_section 'linear solve')" \
      -v m=$peak 'BEGIN {
    printf "%-6s %-5s %-8s %-6s %-6s %-10.1f %-8.2f %-10.2f %-10.2f %-9.2f %-9.2f %-8.0f\n",
      c, np, u, s, nw, k/nw, T/s, T/nw, (a+r)/nw, p/nw, so/nw, m }'
done
