#!/bin/sh
# `rs4sim master --link pty` prints its pty path first and exits cleanly (status 0, the
# final state of every RS4) on SIGTERM and on SIGINT. Usage: master_signal.sh RS4SIM
set -u
rs4sim=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for sig in TERM INT; do
  "$rs4sim" master --slave 4 --slave 5 --link pty >"$dir/out" 2>"$dir/err" &
  pid=$!
  # the banner (second line) is printed just before the signal handlers are installed
  i=0
  while [ "$(wc -l <"$dir/out")" -lt 2 ] && [ $i -lt 100 ]; do
    sleep 0.1
    i=$((i + 1))
  done
  sleep 0.5
  kill -s "$sig" "$pid"
  wait "$pid"
  rc=$?
  cat "$dir/out"
  [ $rc -eq 0 ] || { echo "SIG$sig: exit $rc"; cat "$dir/err"; exit 1; }
  head -n 1 "$dir/out" | grep -q '^/dev/' || { echo "SIG$sig: no pty path first"; exit 1; }
  grep -q 'end: RS4 5: DP start-up' "$dir/out" || { echo "SIG$sig: no final state"; exit 1; }
done
