#!/usr/bin/env bash
# Model-checks the parallel protocol (proofs/parallel_protocol.pml, paper §4) with spin:
#   spin_protocol.sh safety   MODEL DIR   every assertion holds, no invalid end state and no
#                                         message left at the end (pan -q), exhaustively, in
#                                         three configurations: 2 ranks x 2 insertions with a
#                                         retry; 2 ranks on an 8-tet ring, where a rank commits
#                                         while its search waits; 3 ranks (relink notices)
#   spin_protocol.sh liveness MODEL DIR   `ltl terminates` under weak fairness (pan -a -f):
#                                         2 ranks x 1 insertion with two retries; the 8-tet
#                                         ring above
#   spin_protocol.sh mutation MODEL DIR   with -DCAVITY_LOCKING_ONLY spin reports violations,
#                                         every one of property (1), both kinds present:
#                                         Fig. 3/4 (hit) and overlapping closures (spoil)
# Work files go to DIR. Exit 0: as expected; 1: not (the pan output is printed); 77: spin or
# a C compiler is missing (CTest: skipped).
set -euo pipefail
mode=$1 source=$2 dir=$3
cc=${CC:-cc}
for tool in spin "$cc"; do
  if ! command -v "$tool" >/dev/null; then
    echo "spin_protocol: $tool is not on PATH (scripts/install-deps.sh --tests); skipped"
    exit 77
  fi
done
mkdir -p "$dir"
cp "$source" "$dir/model.pml"  # pan writes its trail beside the copy, where spin -t finds it
cd "$dir"
model=model.pml

# pan DEFS... -- CFLAGS... -- RUNFLAGS...: builds and runs one verifier, output in pan.out.
pan() {
  local defs=() cflags=() run=()
  while [ "$1" != -- ]; do defs+=("$1"); shift; done; shift
  while [ "$1" != -- ]; do cflags+=("$1"); shift; done; shift
  run=("$@")
  rm -f pan.c pan ./*.trail
  spin "${defs[@]}" -a "$model" >/dev/null
  "$cc" -O1 -w -DCOLLAPSE -DMEMLIM=2048 "${cflags[@]}" -o pan pan.c
  ./pan -m1000000 -w24 "${run[@]}" >pan.out 2>&1 || true
  if grep -qE 'max search depth too small|reached -DMEMLIM|out of memory' pan.out; then
    cat pan.out; echo "spin_protocol: the search was cut short (${defs[*]})"; exit 1
  fi
  echo "spin_protocol: ${defs[*]}: $(grep -oE '^ *[0-9.e+]+ states, stored' pan.out | xargs)," \
       "$(grep -oE 'errors: [0-9]+' pan.out), $(grep -oE 'elapsed time [0-9.e+]+' pan.out) s"
}
clean() {
  if ! grep -q 'errors: 0' pan.out; then
    cat pan.out
    { spin -t "$@" "$model" 2>&1 || true; } | grep -E 'rank|assert' | tail -40
    echo "spin_protocol: violation with $*"; exit 1
  fi
}

case "$mode" in
  safety)
    for cfg in "-DP=2 -DW0=2 -DW1=2 -DMAXSB=1" \
               "-DP=2 -DN=8 -DH0=31 -DH1=224 -DW0=2 -DW1=1" \
               "-DP=3 -DW0=1 -DW1=1 -DW2=0 -DMAXSB=0"; do
      # shellcheck disable=SC2086
      pan $cfg -- -DSAFETY -- -q
      # shellcheck disable=SC2086
      clean $cfg
    done ;;
  liveness)
    for cfg in "-DP=2 -DW0=1 -DW1=1 -DMAXSB=2" "-DP=2 -DN=8 -DH0=31 -DH1=224 -DW0=2 -DW1=1"; do
      # shellcheck disable=SC2086
      pan -DLIVENESS $cfg -- -DNFAIR=3 -- -a -f -q
      # shellcheck disable=SC2086
      clean -DLIVENESS $cfg
    done ;;
  mutation)
    pan -DP=2 -DCAVITY_LOCKING_ONLY -- -DSAFETY -- -q -c0
    n=$(grep -oE 'errors: [0-9]+' pan.out | grep -oE '[0-9]+')
    reported=$(grep -cE '^pan:[0-9]+: ' pan.out || true)  # pan prints some of them
    hit=$(grep -c 'assertion violated (hit\[r\]==0)' pan.out || true)
    spoil=$(grep -c 'assertion violated (spoil\[r\]==0)' pan.out || true)
    if [ "$n" -eq 0 ] || [ "$hit" -eq 0 ] || [ "$spoil" -eq 0 ] ||
       [ $((hit + spoil)) -ne "$reported" ]; then
      grep -vE 'assertion violated \((hit|spoil)' pan.out | head -40
      echo "spin_protocol: the mutation was expected to break property (1) only, both ways" \
           "($n errors; reported: $hit Fig. 3/4, $spoil closures, $reported in all)"
      exit 1
    fi
    echo "spin_protocol: the mutation breaks property (1): $n errors; of those reported, $hit" \
         "Fig. 3/4 (hit), $spoil overlapping closures (spoil)"
    # The first counterexample, as the model's own log.
    pan -DP=2 -DCAVITY_LOCKING_ONLY -- -DSAFETY -- -q
    { spin -DP=2 -DCAVITY_LOCKING_ONLY -t "$model" 2>&1 || true; } |
      grep -E 'rank|assertion' | sed 's/^ */  /' ;;
  *) echo "spin_protocol: unknown mode '$mode' (safety, liveness, mutation)" >&2; exit 2 ;;
esac
