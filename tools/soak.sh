#!/usr/bin/env bash
# Long runs do not leak (issue 17, item 8): peak resident memory per rank
# (VmHWM, printed by the program with 'Print details') after 10, 100 and
# 1000 steps of two small 2D studies, the lid-driven cavity (RBVMS, 16^2,
# p = 2, fixed dt) and the Willmore flow of an ellipse (32^2, p = 3,
# adaptive dt up to 0.002 so that 1000 steps end before the stationary
# shape, iterative solver), each with a checkpoint every 10 steps and
# a VTU file every 100. Flat figures mean no leak per step.
#   tools/soak.sh [ranks (2)] [output directory (soak)] [studies (cavity ellipse)]
# Prints one line per run: study, steps, seconds, peak MB per rank (max).
set -euo pipefail
cd "$(dirname "$0")/.."
source tools/mpi-env.sh
ranks=${1:-2}
out=${2:-soak}
studies=${3:-cavity ellipse}
binary=build/vesicle-iga
mkdir -p "$out"

cavity() {
  cat <<PRM
set Study = navier-stokes
set Print details = true
subsection Navier-Stokes
  set Reynolds number = 100
  subsection Mesh
    set Elements = 16
  end
  subsection Boundary 1
    set Type = strong
    set Where = x-min; x-max; y-min
    set Velocity = 0; 0
  end
  subsection Boundary 2
    set Type = weak
    set Where = y-max
    set Velocity = 1; 0
  end
  subsection Time stepping
    set Initial dt = 0.01
    set Max dt = 0.01
    set Step control = fixed
    set End time = 1e9
    set Steady tolerance = 0
    set Checkpoint interval = 10
    set VTU interval = 100
    set Max steps = $1
  end
end
PRM
}

ellipse() {
  cat <<PRM
set Study = willmore-flow
set Print details = true
subsection Willmore flow
  set Initial shape = ellipsoid
  set Semi-axes = 1.5, 0.75
  set Center = 0,0
  subsection Mesh
    set Lower corner = -3.2
    set Upper corner = 3.2
    set Elements = 32
  end
  subsection Time stepping
    set End time = 1e9
    set Initial dt = 1e-3
    set Max dt = 0.002
    set Checkpoint interval = 10
    set VTU interval = 100
    set Max steps = $1
    set Stationarity tolerance = 0
  end
end
PRM
}

for study in $studies; do
  for steps in 10 100 1000; do
    dir="$out/$study-$steps"
    start=$(date +%s)
    if ! { $study "$steps"; echo "set Output directory = $dir"; } |
      mpirun -np "$ranks" "$binary" - > "$dir.log" 2>&1; then
      echo "$study steps=$steps FAILED, see $dir.log"
      continue
    fi
    end=$(date +%s)
    peak=$(sed -n 's/^peak memory (VmHWM) per rank: max \([0-9.]*\) MB.*/\1/p' "$dir.log")
    rows=$(($(wc -l < "$dir/time-series.csv") - 1))
    echo "$study steps=$rows seconds=$((end - start)) peak_MB_per_rank=$peak"
  done
done
