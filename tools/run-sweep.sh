#!/usr/bin/env bash
# Runs one study file for several values of one parameter: each case is the
# base .prm followed by the changed entry (ParameterHandler keeps the last
# value it reads), read from stdin, with its own output directory
# <base output directory>/<name>-<value>. Example (spec EM3, field strength):
#   tools/run-sweep.sh -n 2 prm/electric-field-2d.prm \
#       "Willmore flow/Electric field/Field strength" 1e3 1e4 3e4 5e4
# Several entries per case: separate them by ';' in one value, e.g. the
# conductivity ratios of spec EM5 (sigma_in + sigma_out = 1.5 S/m):
#   tools/run-sweep.sh prm/conductivity-ratio-2d.prm \
#       "Willmore flow/Electric field/Conductivity inside;Willmore flow/Electric field/Conductivity outside" \
#       "0.3;1.2" "0.75;0.75" "1.2;0.3"
# Contours of all cases: /usr/bin/python3 tools/plot-contours.py DIRS... out.png
set -euo pipefail
ranks=2
if [[ "${1:-}" == "-n" ]]; then
  ranks=$2
  shift 2
fi
if [[ $# -lt 3 ]]; then
  echo "usage: tools/run-sweep.sh [-n RANKS] BASE.prm 'Sub/section/Parameter[;...]' VALUE[;...] ..." >&2
  exit 1
fi
here="$(cd "$(dirname "$0")/.." && pwd)"
source "$here/tools/mpi-env.sh"
base=$1
IFS=';' read -r -a entries <<< "$2"
shift 2
[[ -f "$base" ]] || { echo "run-sweep: no such file '$base'" >&2; exit 1; }
out=$(sed -n 's/^ *set Output directory *= *//p' "$base" | head -1)
out=${out:-output/$(basename "$base" .prm)}

# One "set" line inside its subsections for the path Sub/section/Parameter.
set_entry() {
  local path=$1 value=$2
  IFS='/' read -r -a parts <<< "$path"
  local n=${#parts[@]} i
  for ((i = 0; i < n - 1; ++i)); do echo "subsection ${parts[i]}"; done
  echo "set ${parts[n-1]} = $value"
  for ((i = 0; i < n - 1; ++i)); do echo "end"; done
}

for value in "$@"; do
  IFS=';' read -r -a values <<< "$value"
  if [[ ${#values[@]} -ne ${#entries[@]} ]]; then
    echo "run-sweep: value '$value' has ${#values[@]} parts for ${#entries[@]} parameters" >&2
    exit 1
  fi
  name=$(echo "$value" | sed 's/;/_/g; s#[/ ]#-#g')
  dir="$out/case-$name"
  mkdir -p "$dir"
  {
    cat "$base"
    for i in "${!entries[@]}"; do set_entry "${entries[i]}" "${values[i]}"; done
    echo "set Output directory = $dir"
  } > "$dir/case.prm"
  echo "== $dir"
  mpirun -np "$ranks" "$here/build/vesicle-iga" "$dir/case.prm" | tee "$dir/run.log" | grep -E "^(final|stationary|largest)" || true
done
