#!/usr/bin/env bash
# A rank killed in the middle of `mpirun -np 3 pdr mesh` ends the run: mpirun returns
# within 60 s with a failure, and no output file is left behind.
#   mpi_kill_rank.sh MPIEXEC PDR DOMAIN OUTDIR
set -u
mpiexec=$1 pdr=$2 domain=$3 outdir=$4
rm -rf "$outdir" && mkdir -p "$outdir"
"$mpiexec" -n 3 --oversubscribe "$pdr" mesh "$domain" -o "$outdir/killed" --max-volume 0.0005 \
  --initial-tets 2000 --no-check >/dev/null 2>"$outdir/stderr" &
launcher=$!
# Wait for the ranks to start (the children of mpirun running pdr), then kill one.
victim=""
for _ in $(seq 1 300); do
  victim=$(pgrep -f -n -- "$outdir/killed" | grep -v "^$launcher\$" | tail -1)
  [ -n "$victim" ] && [ "$(pgrep -f -c -- "$pdr mesh $domain -o $outdir/killed")" -ge 3 ] && break
  sleep 0.1
done
[ -n "$victim" ] || { echo "no rank started"; kill -9 "$launcher"; exit 1; }
sleep 1
kill -9 "$victim"
for _ in $(seq 1 600); do
  kill -0 "$launcher" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$launcher" 2>/dev/null; then
  echo "mpirun still running 60 s after a rank was killed"
  pkill -9 -f -- "$outdir/killed"
  exit 1
fi
wait "$launcher"
rc=$?
[ "$rc" -ne 0 ] || { echo "mpirun returned 0 after a rank was killed"; exit 1; }
if ls "$outdir"/killed* >/dev/null 2>&1; then
  echo "output left behind: $(ls "$outdir"/killed*)"
  exit 1
fi
echo "mpirun returned $rc after rank pid $victim was killed; nothing written"
