#!/usr/bin/env bash
# Cost of the 3D electromechanics step of tools/bench/electromechanics-3d.prm
# (spec set-up, every energy on) on 40^3 and 60^3 elements and 1 and 2
# ranks: the iteration counts (Newton, GMRES, ALM, CG of the potential), the
# set-up (mesh, spline space, sparsity: wall time outside the timed
# sections), and per step the potential solve (assembly + multigrid + CG,
# per solve; a run of N steps solves N + 1 times), the phase-field
# assembly, the multigrid set-up and the GMRES solves (the ALM Jacobian's
# assembly and solves included), with the time per Newton iteration and the
# peak memory per rank (MB, and bytes per unknown of a rank: peak / (unknowns /
# ranks)). Times in seconds. Usage (after tools/build.sh):
#   tools/bench/run-electromechanics-3d.sh [element counts, default "40 60"]
# Environment: RANKS (default "1 2"); THREADS (log-fields.sh); STEPS (default 1: the first step);
# EXTRA (parameter lines added to the file, e.g. another smoother) and TAG
# (appended to the output directory names); OUTPUT=1 writes the VTU files
# and the checkpoint at every step (the memory figures of doc/performance.md
# include them);
# REPORT_ONLY=1 prints the table from the logs of an earlier run.
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh
sizes=${*:-40 60}
RANKS=${RANKS:-1 2}
STEPS=${STEPS:-1}
EXTRA=${EXTRA:-}
if [[ "${OUTPUT:-0}" == 1 ]]; then
  EXTRA="subsection Willmore flow
  subsection Time stepping
    set VTU interval = 1
    set Checkpoint interval = 1
  end
end
$EXTRA"
fi
echo "3D electromechanics (all energies, 50 kV/m), $STEPS step(s) of dt = 0.01, $DEAL_II_NUM_THREADS thread(s) per rank; times in s"
printf "%-6s %-5s %-8s %-6s %-6s %-4s %-4s %-7s %-10s %-9s %-9s %-9s %-9s %-9s %-7s %-9s\n" \
  cells ranks unknowns newton gmres alm cg set-up potential/sol assembly mg-setup gmres s/step s/newton peakMB B/unknown
for n in $sizes; do
  for np in $RANKS; do
    out=output/bench-electromechanics-3d-$n-$np${TAG:-}
    if [[ "${REPORT_ONLY:-0}" != 1 ]]; then
      mkdir -p $out
      mpirun -np $np build/vesicle-iga - > $out.log <<EOP
$(cat tools/bench/electromechanics-3d.prm)
set Output directory = $out
subsection Willmore flow
  subsection Time stepping
    set Max steps = $STEPS
  end
  set Epsilon over h = $(awk -v n=$n 'BEGIN {print n / 30}')
  subsection Mesh
    set Elements = $n
  end
end
$EXTRA
EOP
      mv $out.log $out/run.log
    fi
    log=$(cat $out/run.log)
    read -r steps newton krylov < <(series_counts $out)
    read -r alm cg < <(awk -F, 'NR==1 {for (i = 1; i <= NF; ++i) c[$i] = i}
      NR>1 {a += $c["alm_iterations"]; p += $c["potential_iterations"]}
      END {print a, p}' $out/time-series.csv)
    # 'ALM Jacobian' holds assembly and solves of its own: not added again.
    awk -v c="$n^3" -v np=$np -v u=$(log_unknowns) -v s=$steps -v nw=$newton \
        -v k=$krylov -v al=$alm -v cg=$cg -v T=$(log_total) \
        -v ps="$(log_section potential)" -v a="$(log_sum assembly residual)" \
        -v p="$(log_section preconditioner)" -v so="$(log_section 'linear solve')" \
        -v mo="$(log_section monitor)" -v o="$(log_section output)" \
        -v m=$(log_peak_mb) 'BEGIN {
      step = (ps * s / (s + 1) + a + p + so + mo) / s
      printf "%-6s %-5s %-8s %-6s %-6s %-4s %-4s %-7.1f %-10.2f %-9.2f %-9.2f %-9.2f %-9.1f %-9.2f %-7.0f %-9.0f\n",
        c, np, u, nw, k, al, cg, T - (ps + a + p + so + mo + o), ps / (s + 1),
        a / s, p / s, so / s, step, step * s / nw, m, m * 1e6 * np / u }'
  done
done
