#!/usr/bin/env bash
# Assembly cost of the engine's kernel on 1 rank, machine-independent
# figures included (microseconds per element per call and per Newton
# iteration):
#  - RBVMS flow: the 3D channel of tools/bench/channel-3d.prm, 16^3
#    quadratic C^1 elements, 3 Gauss points per direction, 5 steps;
#  - phase field: tools/bench/phase-field-2d.prm, 128^2 quadratic C^1
#    elements (fourth order, primal form), 3 points, 10 steps.
# "call" = one Jacobian assembly (with its residual); per Newton iteration
# = all Jacobian and residual-only assemblies over the Newton corrections;
# whole_run_s = TimerOutput's total (set-up, solves, monitors and output
# included).
# CSV on stdout. Usage (after tools/build.sh): tools/bench/run-assembly.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh
echo "case,elements,jacobian_calls,s_per_call,us_per_element_per_call,newton_iterations,us_per_element_per_newton,whole_run_s"
report() { # name elements out-dir
  local jac res calls newton total
  jac=$(log_section assembly)
  total=$(log_total)
  res=$(log_section residual)
  calls=$(echo "$log" | sed -n 's/^| assembly *| *\([0-9]*\) |.*/\1/p')
  read -r _ newton _ < <(series_counts $3)
  awk -v name=$1 -v n=$2 -v j=$jac -v r=${res:-0} -v c=$calls -v it=$newton -v t=$total 'BEGIN {
    printf "%s,%d,%d,%.3f,%.2f,%d,%.2f,%.2f\n", name, n, c, j / c, 1e6 * j / c / n, it,
      1e6 * (j + r) / it / n, t }'
}
log=$(build/vesicle-iga - <<EOP
$(cat tools/bench/channel-3d.prm)
set Output directory = output/bench-assembly-channel
subsection Navier-Stokes
  set Quadrature points = 3
end
EOP
)
report rbvms-3d-p2 4096 output/bench-assembly-channel
log=$(build/vesicle-iga tools/bench/phase-field-2d.prm)
report phase-field-2d-p2 16384 output/bench-phase-field-2d
