#!/usr/bin/env bash
# Time per Newton iteration of the RBVMS flow solver, split into assembly
# (tangent and residual), block-preconditioner set-up and FGMRES solve, and
# the Krylov iterations per Newton iteration, for the lid-driven cavity of
# prm/lid-driven-cavity-re100.prm (p = 2, run to its steady state) on N^2
# elements and 1 and 2 ranks. Usage (after tools/build.sh):
#   tools/bench/run-cavity.sh [element counts...]        (default 64 128 256)
# Environment: RE (Reynolds number, default 100), VELOCITY (velocity
# preconditioner: spline-multigrid or amg), SCHUR (cahouet-chabard or
# simple), METHOD (fgmres-block, gmres-ilu, direct), RANKS (default "1 2").
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh
sizes=${*:-64 128 256}
RE=${RE:-100}
VELOCITY=${VELOCITY:-spline-multigrid}
SCHUR=${SCHUR:-cahouet-chabard}
METHOD=${METHOD:-fgmres-block}
RANKS=${RANKS:-1 2}
echo "lid-driven cavity, Re = $RE, p = 2, method $METHOD" \
  "(velocity: $VELOCITY, Schur: $SCHUR); times in seconds per Newton iteration"
printf "%-8s %-5s %-8s %-6s %-6s %-10s %-9s %-9s %-9s %-9s %-9s %-8s\n" \
  cells ranks unknowns steps newton krylov/nwt total assembly pc-setup solve dev-u dev-v
for n in $sizes; do
  for np in $RANKS; do
    out=output/bench-cavity-re$RE-$n-$np
    log=$(mpirun -np $np build/vesicle-iga - <<EOP
$(cat prm/lid-driven-cavity-re100.prm)
set Output directory = $out
subsection Navier-Stokes
  set Reynolds number = $RE
  subsection Mesh
    set Elements = $n
  end
  subsection Linear solver
    set Method = $METHOD
    subsection Block preconditioner
      set Velocity preconditioner = $VELOCITY
      set Schur approximation     = $SCHUR
    end
  end
end
EOP
)
    unknowns=$(log_unknowns)
    total=$(log_total)
    read -r steps newton krylov < <(series_counts $out)
    dev() { echo "$log" | sed -n "s/^$1.csv: largest deviation.*: \(.*\)/\1/p"; }
    awk -v c="$n^2" -v np=$np -v u=$unknowns -v s=$steps -v nw=$newton -v k=$krylov \
        -v T=$total -v a="$(log_section assembly)" -v r="$(log_section residual)" \
        -v p="$(log_section preconditioner)" -v so="$(log_section 'linear solve')" \
        -v du="$(dev centerline-u)" -v dv="$(dev centerline-v)" 'BEGIN {
      printf "%-8s %-5s %-8s %-6s %-6s %-10.1f %-9.3f %-9.3f %-9.3f %-9.3f %-9.4f %-8.4f\n",
        c, np, u, s, nw, k/nw, T/nw, (a+r)/nw, p/nw, so/nw, du, dv }'
  done
done
