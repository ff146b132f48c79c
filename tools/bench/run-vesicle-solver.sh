#!/usr/bin/env bash
# Linear solver of the coupled vesicle-flow system (spec Part H): one
# vesicle (R_0 = 0.45, chi = 0.84, centre (1, 1)) in a closed box [-2,2]^2 of fluid at rest,
# cubic C^2 elements, eps = 0.125 (fixed, so that only h changes), dt =
# 1e-3, one step, for N elements per unit length; Newton and FGMRES
# iterations, and the time per Newton iteration of assembly (tangent and
# residual), preconditioner set-up and linear solve. Usage (after
# tools/build.sh):
#   tools/bench/run-vesicle-solver.sh [elements per unit length...]  (default 8 16 32)
# Environment: METHOD (fgmres-block or direct), RANKS (default "1 2"),
# EXTRA (lines added to the Block preconditioner subsection), MODEL_EXTRA
# (lines added to the Vesicle hydrodynamics subsection, e.g. "set Phase
# field boundary condition = natural"), VESICLES (default "1, 1, 0.45, 0.84,
# 90", the set-up of the measurements in doc/hydrodynamics.md before the
# smooth initial data; the vesicle at "0, 0, 0.45, 0.84, 90" with
# MODEL_EXTRA="set Initial distance = level-set" has multipliers and
# bending energy that converge under refinement, doc "Initial distance").
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh
sizes=${*:-8 16 32}
METHOD=${METHOD:-fgmres-block}
RANKS=${RANKS:-1 2}
EXTRA=${EXTRA:-}
MODEL_EXTRA=${MODEL_EXTRA:-}
VESICLES=${VESICLES:-1, 1, 0.45, 0.84, 90}
echo "vesicle in a box at rest, p = 3, eps = 0.125, method $METHOD; times in seconds per Newton iteration"
echo "per-unit,ranks,unknowns,newton,krylov/newton,total/newton,assembly,pc-setup,solve,peak-MB"
for m in $sizes; do
  for np in $RANKS; do
    out=output/bench-vesicle-solver-$m-$np-$METHOD
    log=$(mpirun -np $np build/vesicle-iga - <<EOP
set Study = vesicle-hydrodynamics
set Dimension = 2
set Output directory = $out
subsection Vesicle hydrodynamics
  set Vesicles = $VESICLES
  set Epsilon = 0.125
  set Write VTU = false
  set Write membrane samples = false
  $MODEL_EXTRA
  subsection Mesh
    set Lower corner = -2, -2
    set Upper corner = 2, 2
    set Elements = $((4 * m)), $((4 * m))
  end
  subsection Boundary 1
    set Type = strong
    set Where = all
    set Velocity = 0; 0
  end
  subsection Linear solver
    set Method = $METHOD
    subsection Block preconditioner
      $EXTRA
    end
  end
  subsection Time stepping
    set Step control = fixed
    set Initial dt = 1e-3
    set Max dt = 1e-3
    set End time = 1e-3
    set Checkpoint interval = 0
  end
end
EOP
)
    read -r steps newton krylov < <(series_counts $out)
    awk -v m=$m -v np=$np -v u="$(log_unknowns)" -v nw=$newton -v k=$krylov \
        -v T="$(log_total)" -v a="$(log_section assembly)" -v r="$(log_section residual)" \
        -v p="$(log_section preconditioner)" -v so="$(log_section 'linear solve')" \
        -v mb="$(log_peak_mb)" 'BEGIN {
      printf "%s,%s,%s,%s,%.1f,%.2f,%.2f,%.2f,%.2f,%s\n", m, np, u, nw, k/nw, T/nw, (a+r)/nw, p/nw, so/nw, mb }'
  done
done
