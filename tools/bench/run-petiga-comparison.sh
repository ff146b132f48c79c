#!/usr/bin/env bash
# The rows of doc/performance.md, "Side by side with PetIGA": the same
# meshes, degrees and quadrature (p+1 Gauss points per direction) run by
# vesicle-iga and by PetIGA's demos in one sitting, medians of R runs, on
# one rank and one thread. PetIGA is not part of this project: build it
# outside (commit 8fd3cdc plus its demo fix 6e3b1c1, against Debian's
# PETSc 3.18; doc/performance.md says how) and point PETIGA_DIR at it.
#
#   PETIGA_DIR=/path/to/petiga tools/bench/run-petiga-comparison.sh [R]
#
# Without PETIGA_DIR only the vesicle-iga side runs. CSV on stdout:
#   case,code,quantity,median_s,elements,us_per_element
# quantity: "assembly" = one matrix assembly (Poisson: matrix and right-hand
# side; PetIGA's IGAFormSystem), "jacobian call" = one Jacobian with its
# residual (PetIGA: IGAFormIJacobian + IGAFormIFunction per Jacobian),
# "newton iteration" = all assembly of a Newton iteration, "time step" = all
# assembly of a time step (ours keeps the phase-field Jacobian across Newton
# solves, so per step is the fair comparison there), "run" = the
# whole process (set-up, assembly, CG-AMG to 1e-8; ours also computes the
# error norms).
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
source tools/bench/log-fields.sh
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1
R=${1:-3}
out=output/bench-petiga
mkdir -p $out

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
row() { # case code quantity elements values...
  local c=$1 code=$2 q=$3 n=$4
  shift 4
  local m
  m=$(printf '%s\n' "$@" | median)
  awk -v c="$c" -v code=$code -v q="$q" -v m=$m -v n=$n \
    'BEGIN {printf "%s,%s,%s,%.4g,%d,%.2f\n", c, code, q, m, n, 1e6 * m / n}'
}

# --- vesicle-iga ---------------------------------------------------------
ours_poisson() { # prm -> "assembly_s total_s" per run
  log=$(build/vesicle-iga - <<EOF
$(cat tools/bench/$1.prm)
set Output directory = $out/$1
subsection Poisson MMS
  subsection Linear solver
    set Tolerance = 1e-8
  end
end
EOF
)
  echo "$(log_section assembly) $(log_total)"
}
ours_flow() { # prm extra-settings -> "s_per_call s_per_newton s_per_step"
  log=$(build/vesicle-iga - <<EOF
$(cat tools/bench/$1.prm)
set Output directory = $out/$1
$2
EOF
)
  local jac res calls steps newton
  jac=$(log_section assembly)
  res=$(log_section residual)
  calls=$(echo "$log" | sed -n 's/^| assembly *| *\([0-9]*\) |.*/\1/p')
  read -r steps newton _ < <(series_counts $out/$1)
  awk -v j=$jac -v r=${res:-0} -v c=$calls -v it=$newton -v st=$steps \
    'BEGIN {print j / c, (j + r) / it, (j + r) / st}'
}

flow_rows() { # case code elements command... (prints "call newton step")
  local c=$1 code=$2 n=$3 x y z
  shift 3
  local calls=() iterations=() steps=()
  for r in $(seq $R); do
    read -r x y z < <("$@")
    calls+=($x) iterations+=($y) steps+=($z)
  done
  row $c $code "jacobian call" $n "${calls[@]}"
  row $c $code "newton iteration" $n "${iterations[@]}"
  row $c $code "time step" $n "${steps[@]}"
}

echo "case,code,quantity,median_s,elements,us_per_element"
for b in poisson-3d-p3:32768 poisson-3d-p2:32768 poisson-2d-p3:65536 poisson-2d-p2:65536; do
  name=${b%%:*} n=${b##*:}
  a=() t=()
  for r in $(seq $R); do
    read -r x y < <(ours_poisson $name)
    a+=($x) t+=($y)
  done
  row $name vesicle-iga assembly $n "${a[@]}"
  [ $name = poisson-3d-p3 ] && row $name vesicle-iga run $n "${t[@]}"
done
channel='subsection Navier-Stokes
  set Quadrature points = 3
  subsection Time stepping
    set Max steps = 2
  end
end'
flow_rows rbvms-3d-p2 vesicle-iga 4096 ours_flow channel-3d "$channel"
flow_rows phase-field-2d-p2 vesicle-iga 16384 ours_flow phase-field-2d ""

# --- PetIGA --------------------------------------------------------------
[ -n "${PETIGA_DIR:-}" ] || exit 0
export LD_LIBRARY_PATH=$PETIGA_DIR/arch-default/lib:${LD_LIBRARY_PATH:-}
demo=$PETIGA_DIR/demo
event() { echo "$log" | awk -v e=$1 '$1 == e {print $2, $4}'; } # count time
petiga_poisson() { # dim elements degree -> "assembly_s total_s"
  log=$($demo/Poisson -iga_dim $1 -iga_elements $2 -iga_degree $3 \
    -iga_quadrature $(($3 + 1)) -ksp_type cg -pc_type ml -ksp_rtol 1e-8 \
    -log_view 2>&1)
  read -r _ a < <(event IGAFormSystem)
  echo "$a $(echo "$log" | awk '/^Time \(sec\):/ {print $3}')"
}
for b in poisson-3d-p3:3:32:3:32768 poisson-3d-p2:3:32:2:32768 \
  poisson-2d-p3:2:256:3:65536 poisson-2d-p2:2:256:2:65536; do
  IFS=: read -r name d e p n <<<"$b"
  a=() t=()
  for r in $(seq $R); do
    read -r x y < <(petiga_poisson $d $e $p)
    a+=($x) t+=($y)
  done
  row $name PetIGA assembly $n "${a[@]}"
  [ $name = poisson-3d-p3 ] && row $name PetIGA run $n "${t[@]}"
done
petiga_flow() { # command... -> "s_per_call s_per_newton s_per_step"
  log=$("$@" -log_view 2>&1)
  local nj tj nf tf ns
  read -r nj tj < <(event IGAFormIJacobian)
  read -r nf tf < <(event IGAFormIFunction)
  read -r ns _ < <(event TSStep)
  awk -v nj=$nj -v tj=$tj -v nf=$nf -v tf=$tf -v ns=$ns \
    'BEGIN {print (tj + tf * nj / nf) / nj, (tj + tf) / nj, (tj + tf) / ns}'
}
flow_rows rbvms-3d-p2 PetIGA 4096 petiga_flow $demo/NavierStokesVMS -N 16 \
  -p 2 -C 1 -iga_quadrature 3 -ts_max_steps 2 -ksp_type fgmres -pc_type asm
flow_rows phase-field-2d-p2 PetIGA 16384 petiga_flow $demo/CahnHilliard2D \
  -N 128 -p 2 -k 1 -iga_quadrature 3 -ts_max_steps 10 -ksp_type gmres \
  -pc_type asm
