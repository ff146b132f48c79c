#!/usr/bin/env bash
# Flat profile of the assembly alone: records a run with `perf record`
# (one rank, one thread), takes the time window from the first to the last
# sample in the element-matrix kernel (TensorProductKernel<dim>::
# integrate_matrix, so set-up, solver and error norms fall outside it) and
# prints each function's share of the samples in that window, with the
# window's length. Needs perf (linux-perf) and read access to perf events.
#
# WINDOW=stack instead keeps the samples whose call stack passes through
# the engine's SystemAssembler (every Jacobian and residual-only pass, and
# nothing else: for runs whose assemblies are spread over the time steps,
# such as the phase-field row, tools/bench/phase-field-2d.prm), recorded
# with DWARF call graphs at 1 kHz, and prints the share of the run's
# samples in the assembly, then each innermost function's share of those.
# Unwinding the stacks takes about 10 minutes for a 20 s run.
#
#   tools/bench/profile-assembly.sh PRM [LINES] [EXTRA-SETTINGS]
#
# e.g. the 2D p = 2 Poisson row of doc/performance.md at 1024^2 elements
# (enough samples; the cost per element is that of 256^2):
#   tools/bench/profile-assembly.sh tools/bench/poisson-2d-p2.prm 25 \
#     'subsection Poisson MMS
#        subsection Mesh
#          set Elements = 1024
#        end
#      end'
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/mpi-env.sh
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1
prm=$1
lines=${2:-25}
extra=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
{
  cat "$prm"
  echo "set Output directory = $work/out"
  printf '%s\n' "$extra"
} >"$work/input.prm"
if [ "${WINDOW:-kernel}" = stack ]; then
  perf record -q -F 1000 --call-graph dwarf,16384 -o "$work/perf.data" \
    build/vesicle-iga "$work/input.prm" >"$work/log" 2>&1
  perf script -i "$work/perf.data" -F time,ip,sym 2>/dev/null |
    awk 'BEGIN {RS = ""; FS = "\n"}
      {n++; if ($0 !~ /SystemAssembler/) next; a++
       leaf = $2; sub(/^[ \t]*[0-9a-f]+ /, "", leaf); sub(/ \(inlined\)$/, "", leaf)
       gsub(/\(anonymous namespace\)::/, "", leaf); c[substr(leaf, 1, 100)]++}
      END {printf "100.0%%  the assembly: %d of the run's %d samples (%.1f%%)\n", a, n, 100 * a / n
           for (s in c) printf "%5.1f%%  %s\n", 100 * c[s] / a, s}' |
    sort -rn | head -n "$lines"
  exit 0
fi
perf record -q -F 5000 -o "$work/perf.data" build/vesicle-iga "$work/input.prm" \
  >"$work/log" 2>&1
perf script -i "$work/perf.data" -F time,ip,sym -G 2>/dev/null |
  awk '{t = $1; sub(":", "", t); $1 = ""; $2 = ""; sub(/^ +/, ""); print t "\t" $0}' \
    >"$work/samples.tsv"
read -r first last < <(awk -F'\t' '/integrate_matrix/ {if (!f) f = $1; l = $1}
  END {print f, l}' "$work/samples.tsv")
echo "assembly window: $first .. $last s ($(awk -v a=$first -v b=$last 'BEGIN {printf "%.3f", b - a}') s)"
awk -F'\t' -v a=$first -v b=$last '$1 >= a && $1 <= b {n++; c[$2]++}
  END {for (s in c) printf "%5.1f%%  %s\n", 100 * c[s] / n, substr(s, 1, 100)}' \
  "$work/samples.tsv" | sort -rn | head -n "$lines"
