#!/usr/bin/env bash
# Bad input on one rank only (the input missing on one host): `mpirun -np 3 pdr mesh` ends
# within 60 s, every rank with exit 2, the failing rank's message said once, nothing
# written.
#   mpi_one_rank_fails.sh MPIEXEC PDR DOMAIN OUTDIR
set -u
mpiexec=$1 pdr=$2 domain=$3 outdir=$4
rm -rf "$outdir" && mkdir -p "$outdir"
cat > "$outdir/rank.sh" <<EOS
#!/bin/sh
input="$domain"
[ "\$OMPI_COMM_WORLD_RANK" = 1 ] && input="$outdir/missing.poly"
exec "$pdr" mesh "\$input" -o "$outdir/out" --max-volume 0.05
EOS
chmod +x "$outdir/rank.sh"
timeout 60 "$mpiexec" -n 3 --oversubscribe "$outdir/rank.sh" >"$outdir/stdout" 2>"$outdir/stderr"
rc=$?
[ "$rc" -eq 2 ] || { echo "mpirun returned $rc, expected 2"; cat "$outdir/stderr"; exit 1; }
n=$(grep -c "missing.poly" "$outdir/stderr")
[ "$n" -eq 1 ] || { echo "the missing file is named $n times, expected once:"; cat "$outdir/stderr"; exit 1; }
if ls "$outdir"/out* >/dev/null 2>&1; then echo "output written: $(ls "$outdir"/out*)"; exit 1; fi
echo "exit 2 on every rank; stderr: $(tr '\n' ' ' < "$outdir/stderr")"
