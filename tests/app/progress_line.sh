#!/usr/bin/env bash
# The progress line (issue #12): on a terminal (a pseudo-terminal made by script(1)),
# `pdr mesh` and `pdr check` redraw a line on stderr with the phase and, while refining, the
# vertex count and rate; with --json, or when stderr is not a terminal, nothing of it is
# written. Usage: progress_line.sh PDR DOMAIN
set -euo pipefail
pdr=$1 domain=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export PDR_PROGRESS_MS=5  # redraw often: even a fast machine's short phases are seen
fail() { echo "progress_line: $*" >&2; exit 1; }

# On a terminal: the phases, a count with its rate, then the line erased before the summary.
script -qfec "$pdr mesh $domain -o $dir/m --max-volume 0.005" /dev/null > "$dir/tty.out"
grep -aq $'\r\033\\[K\\[pdr [0-9.]* s\\] refine' "$dir/tty.out" || fail "no refine line on a terminal"
grep -aqE 'refine: [0-9]+ vertices, [0-9]+/s' "$dir/tty.out" || fail "no vertex count and rate"
grep -aq 'check: topology' "$dir/tty.out" || fail "no check phase"
grep -aq $'\r\033\\[Kcommand: mesh' "$dir/tty.out" || fail "the line is not erased before the summary"
script -qfec "$pdr check $dir/m --domain $domain" /dev/null > "$dir/check.out"
grep -aq 'check: delaunay' "$dir/check.out" || fail "no line from pdr check on a terminal"

# --json on a terminal, and stderr not a terminal: no line at all.
script -qfec "$pdr mesh $domain -o $dir/j --max-volume 0.005 --json" /dev/null > "$dir/json.out"
if grep -aq '\[pdr ' "$dir/json.out"; then fail "a progress line with --json"; fi
"$pdr" mesh "$domain" -o "$dir/p" --max-volume 0.005 2> "$dir/err" > /dev/null
if grep -aq '\[pdr ' "$dir/err"; then fail "a progress line when stderr is not a terminal"; fi
"$pdr" check "$dir/p" --domain "$domain" 2> "$dir/err2" > /dev/null
if grep -aq '\[pdr ' "$dir/err2"; then fail "a progress line from pdr check off a terminal"; fi
echo "progress_line: ok"
