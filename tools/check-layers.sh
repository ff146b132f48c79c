#!/usr/bin/env bash
# The layers of doc/engine.md ("a lower layer never includes a higher one"),
# checked on every #include <vesicle_iga/...> of include/ and source/.
# Prints each include that points upwards; exit code 1 if there is one.
# Run by the test suite (tests/CMakeLists.txt, test "layers").
set -euo pipefail
cd "$(dirname "$0")/.."
# Layer of each folder, lowest first; folders of one layer may include each
# other (postprocess, studies, app are the top).
declare -A layer=(
  [base]=0 [spline]=1 [parallel]=2 [fields]=3 [kernel]=4 [physics]=5
  [io]=6 [terms]=7 [solvers]=8 [time]=9 [models]=10
  [postprocess]=11 [studies]=11 [app]=11)
violations=0
files=0
while IFS= read -r file; do
  files=$((files + 1))
  folder=$(echo "$file" | sed -E 's#^(include/vesicle_iga|source)/([a-z_]+)/.*#\2#')
  own=${layer[$folder]:-}
  if [ -z "$own" ]; then
    echo "$file: folder '$folder' has no layer in tools/check-layers.sh"
    violations=$((violations + 1))
    continue
  fi
  while IFS= read -r included; do
    target=${layer[$included]:-}
    if [ -z "$target" ] || [ "$target" -gt "$own" ]; then
      echo "$file (layer $own, $folder/) includes $included/ (layer ${target:-none})"
      violations=$((violations + 1))
    fi
  done < <(sed -n -E 's@^#include <vesicle_iga/([a-z_]+)/.*@\1@p' "$file" | sort -u)
done < <(find include/vesicle_iga source -name '*.h' -o -name '*.cc' | sort)
echo "$files files, $violations includes against the layers"
[ "$violations" -eq 0 ]
