#!/usr/bin/env bash
# The library order of src/: each folder is one CMake library, and a folder may include only
# its own headers and those of the folders listed for it below, all of which come earlier in
# `order`, so the dependencies point one way and form no circle. A new folder fails the check
# until its place is written here.
#   scripts/check-layers.sh [SRC_DIR]   exit 0: every include follows the order; 1: each
#                                       include that runs against it is printed as file:line
#   scripts/check-layers.sh --self-test plants a back-include in a scratch tree and expects
#                                       the check to find it
set -euo pipefail

order=(geom mesh io delaunay check domain surface refine par app)
declare -A below=(
  [geom]=""
  [mesh]="geom"
  [io]="geom mesh"
  [delaunay]="geom mesh"
  [check]="geom mesh"
  [domain]="geom mesh io"
  [surface]="geom mesh io domain"
  [refine]="geom mesh io delaunay domain surface"
  [par]="geom mesh io delaunay check domain surface refine"
  [app]="geom mesh io delaunay check domain surface refine par"
)

rank_of() {
  local i
  for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && { echo "$i"; return; }; done
  echo -1
}

check_tree() {
  local src=$1 bad=0 dir lib dep file line inc
  # The table itself: every dependency comes earlier in the order.
  for lib in "${order[@]}"; do
    for dep in ${below[$lib]}; do
      if [ "$(rank_of "$dep")" -ge "$(rank_of "$lib")" ]; then
        echo "check-layers: $lib may include $dep, which does not come before it" >&2
        bad=1
      fi
    done
  done
  for dir in "$src"/*/; do
    lib=$(basename "$dir")
    if [ "$(rank_of "$lib")" -lt 0 ]; then
      echo "$dir: check-layers: folder '$lib' has no place in the library order;" \
           "add it to scripts/check-layers.sh" >&2
      bad=1
      continue
    fi
    while IFS=: read -r file line inc; do
      dep=${inc#*\"}
      dep=${dep%%/*}
      [ "$dep" = "$lib" ] && continue
      [ -d "$src/$dep" ] || continue  # not a src/ folder (a system or third-party header)
      if [[ " ${below[$lib]} " != *" $dep "* ]]; then
        echo "$file:$line: check-layers: $lib includes $dep, which comes after it in the" \
             "library order (${order[*]})" >&2
        bad=1
      fi
    done < <(grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"[a-z_]+/' "$dir" || true)
  done
  return $bad
}

if [ "${1:-}" = "--self-test" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  mkdir -p "$tmp/src/geom" "$tmp/src/domain"
  echo '#include "geom/point.hpp"' > "$tmp/src/domain/ok.hpp"
  check_tree "$tmp/src" 2>/dev/null || { echo "self-test: a clean tree was rejected" >&2; exit 1; }
  printf '// planted\n#include "domain/ok.hpp"\n' > "$tmp/src/geom/back.hpp"
  if out=$(check_tree "$tmp/src" 2>&1); then
    echo "self-test: a back-include from geom to domain was not found" >&2
    exit 1
  fi
  [[ "$out" == *"geom/back.hpp:2:"* ]] || { echo "self-test: wrong report: $out" >&2; exit 1; }
  mkdir -p "$tmp/src/extra"
  rm "$tmp/src/geom/back.hpp"
  check_tree "$tmp/src" 2>/dev/null && { echo "self-test: an unplaced folder passed" >&2; exit 1; }
  echo "check-layers self-test: ok"
  exit 0
fi

src=${1:-"$(dirname "$0")/../src"}
check_tree "$src"
echo "check-layers: every include in $src follows ${order[*]}"
