#!/usr/bin/env bash
# Runs the four Poisson benchmarks on 1 and 2 ranks and prints, per run,
# unknowns, CG-AMG iterations and the TimerOutput rows (setup, assembly,
# solve). Usage: tools/bench/run-poisson.sh (after tools/build.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh  # one thread per rank (THREADS)
for prm in poisson-2d-p2 poisson-2d-p3 poisson-3d-p2 poisson-3d-p3; do
  for np in 1 2; do
    echo "== $prm on $np rank(s)"
    mpirun -np $np build/vesicle-iga tools/bench/$prm.prm |
      grep -E "^p=|assembly|solve|setup|Total wallclock"
  done
done
