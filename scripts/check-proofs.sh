#!/usr/bin/env bash
# Keeps the links of proofs/README.md alive: every file, test, fuzz target and checker id it
# names in backquotes must exist.
#   - a path (has a '/' or ends in .cpp/.hpp/.poly/.node/.md/.sh; '*' globs allowed) exists
#     under the repository root or under src/;
#   - an identifier (snake_case or Qualified::name) is a test registered in tests/
#     (pdr_test or add_test), a fuzz target (fuzz/NAME.cpp), or a name used in src/ (its
#     last component);
#   - a checker id (validity.x, delaunay.x, quality.x, conformity.x, encroachment.x; x may be
#     '*') is a string the checker in src/check reports.
# Other backquoted text (commands, formulas) is not checked.
#   scripts/check-proofs.sh [ROOT]   exit 0: all links resolve; 1: each dead one is printed
#                                    as proofs/README.md:line
#   scripts/check-proofs.sh --self-test   plants a dead link of each kind in a scratch copy
#                                         and expects each to be found
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
if [ "${1:-}" = "--self-test" ]; then
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  mkdir "$tmp/proofs"
  for d in src tests fuzz data; do ln -s "$here/$d" "$tmp/$d"; done
  for plant in 's/`refine_mesh_test`/`refine_mesh_tset`/' 's/`fuzz_predicates`/`fuzz_predicate`/' \
               's/`quality.ratio`/`quality.ratios`/' 's#`src/check/overlap.cpp`#`src/check/overlapp.cpp`#' \
               's/`domain::feature_size`/`domain::feature_sizes`/'; do
    sed "$plant" "$here/proofs/README.md" > "$tmp/proofs/README.md"
    if cmp -s "$tmp/proofs/README.md" "$here/proofs/README.md"; then
      echo "self-test: '$plant' planted nothing (update the self-test)" >&2; exit 1
    fi
    if bash "$0" "$tmp" 2>/dev/null; then
      echo "self-test: the dead link planted by '$plant' was not found" >&2; exit 1
    fi
  done
  echo "check-proofs self-test: ok"
  exit 0
fi
root=${1:-$here}
doc="$root/proofs/README.md"
tests=$(grep -rhoE 'pdr_test\([A-Za-z_0-9]+|add_test\(NAME [A-Za-z_0-9.]+' "$root/tests" "$root/fuzz" |
        sed -E 's/pdr_test\(//; s/add_test\(NAME //')
ids=$(grep -rhoE '"(validity|delaunay|quality|conformity|encroachment)\.[a-z_]+"' "$root/src/check" |
      tr -d '"' | sort -u)
words=$(grep -rhoE '[A-Za-z_][A-Za-z0-9_]*' "$root/src" | sort -u)
bad=0 n=0
while IFS=: read -r line text; do
  while read -r tok; do
    [ -n "$tok" ] || continue
    ok=skip
    if [[ "$tok" =~ ^(validity|delaunay|quality|conformity|encroachment)\.[a-z_*]+$ ]]; then
      ok=no
      pat="^${tok//\*/.*}\$"
      grep -qE "$pat" <<<"$ids" && ok=yes
    elif [[ "$tok" =~ ^[A-Za-z_][A-Za-z0-9_]*(::[A-Za-z_][A-Za-z0-9_]*)*$ && "$tok" == *_* ]]; then
      ok=no
      last=${tok##*::}
      if grep -qx "$last" <<<"$tests" || [ -f "$root/fuzz/$last.cpp" ] ||
         grep -qx "$last" <<<"$words"; then
        ok=yes
      fi
    elif [[ "$tok" =~ ^[A-Za-z0-9_./*-]+$ && ( "$tok" == */* || "$tok" =~ \.(cpp|hpp|poly|node|md|sh)$ ) ]]; then
      ok=no
      { compgen -G "$root/$tok" || compgen -G "$root/src/$tok"; } >/dev/null && ok=yes
    fi
    [ "$ok" = skip ] && continue
    n=$((n + 1))
    if [ "$ok" = no ]; then
      echo "proofs/README.md:$line: check-proofs: \`$tok\` names nothing that exists" >&2
      bad=1
    fi
  done < <(grep -oE '`[^`]+`' <<<"$text" | tr -d '`')
done < <(grep -n '`' "$doc")
[ "$bad" -eq 0 ] || exit 1
echo "check-proofs: all $n links of proofs/README.md resolve"
