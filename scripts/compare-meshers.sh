#!/usr/bin/env bash
# What `pdr check` finds on TetGen, Gmsh and pdr meshes of the same domains (README,
# "pdr check versus other meshers"). Prints a markdown table, one row per (domain, mesher).
#   scripts/compare-meshers.sh [PDR_BINARY]     (default: build/pdr)
# Needs tetgen, gmsh and python3 on PATH. pdr rows appear when `pdr mesh` exists.
# Each mesh is checked with: pdr check MESH --domain data/D.poly --ratio 2 --json.
# Columns: validity (all validity.* checks pass), Delaunay (tets with a vertex strictly
# inside their circumsphere), max ratio (R / lmin) and tets with ratio >= 2, conformity
# (all conformity.* checks pass), encroachment (encroached subsegments / subfacets).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
pdr=$(realpath "${1:-$root/build/pdr}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

have_pdr_mesh=0
"$pdr" mesh --help 2>/dev/null | grep -q "Guaranteed-quality tetrahedral mesh" && have_pdr_mesh=1

row() {  # row DOMAIN MESHER MESH
  local json="$work/report.json"
  "$pdr" check "$3" --domain "$root/data/$1.poly" --ratio 2 --max-reported 1 --json \
    >"$json" 2>/dev/null || true
  python3 - "$1" "$2" "$json" <<'PY'
import json, sys
domain, mesher, path = sys.argv[1:4]
try:
    r = json.load(open(path))
except Exception:
    print(f"| {domain} | {mesher} | (unreadable) | | | | | |")
    sys.exit(0)
c = {x["id"]: x for x in r["checks"]}
def group(prefix):
    bad = [i[len(prefix) + 1:] for i, x in c.items() if i.startswith(prefix) and x["status"] == "fail"]
    return "pass" if not bad else "FAIL (" + ", ".join(bad) + ")"
d, q = c["delaunay.empty_sphere"], c["quality.ratio"]
ss, sf = c["encroachment.subsegments"], c["encroachment.subfacets"]
mr = q["values"].get("max_ratio")
print(f"| {domain} | {mesher} | {r['mesh']['tets']} | {group('validity')} | "
      f"{d['violations']} | {mr:.3f} | {q['violations']} | {group('conformity')} | "
      f"{ss['violations']} / {sf['violations']} |")
PY
}

echo "| domain | mesher | tets | validity | non-Delaunay tets | max ratio | tets ratio >= 2 | conformity | encroached subseg. / subfacets |"
echo "|---|---|---|---|---|---|---|---|---|"
for d in box cube-in-cube tee; do
  cp "$root/data/$d.poly" "$work/$d.poly"
  for flags in -pq -pqa1 -pq1.414 -pq1.414a1; do
    rm -f "$work/$d".1.*
    if (cd "$work" && tetgen "${flags}Q" "$d.poly" >/dev/null 2>&1); then
      row "$d" "tetgen $flags" "$work/$d.1"
    else
      echo "| $d | tetgen $flags | (tetgen failed) | | | | | | |"
    fi
  done
  if gmsh -3 "$root/tests/oracle/data/$d.geo" -v 0 -format msh41 -o "$work/$d-gmsh.msh" \
       >/dev/null 2>&1; then
    row "$d" "gmsh -3" "$work/$d-gmsh.msh"
  fi
  if [ "$have_pdr_mesh" = 1 ]; then
    # Exit 3: meshed, but the ratio bound is not guaranteed (inadmissible domain).
    rc=0
    "$pdr" mesh "$work/$d.poly" -o "$work/$d-pdr" --ratio 2 --formats node >/dev/null 2>&1 || rc=$?
    if [ -f "$work/$d-pdr.ele" ] && { [ $rc = 0 ] || [ $rc = 3 ]; }; then
      row "$d" "pdr mesh --ratio 2$([ $rc = 3 ] && echo ' (exit 3)')" "$work/$d-pdr"
    else
      echo "| $d | pdr mesh --ratio 2 | (pdr mesh failed, exit $rc) | | | | | | |"
    fi
  fi
done
