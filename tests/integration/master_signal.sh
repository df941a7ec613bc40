#!/bin/sh
# `rs4sim master --link pty` prints its pty path first and exits cleanly (status 0, the
# final state of every RS4) on SIGTERM and on SIGINT. Usage: master_signal.sh RS4SIM
set -u
rs4sim=$1
. "$(dirname "$0")/lib.sh"
for sig in TERM INT; do
  bg_start master "$rs4sim" master --slave 4 --slave 5 --link pty
  # The banner on stderr ("...; Ctrl-C to stop") comes once the SIGINT/SIGTERM handlers are
  # installed: the signal is sent as soon as it is there.
  bg_await master.err 'Ctrl-C to stop'
  bg_stop master "$sig"
  rc=$bg_rc
  cat "$dir/master.out"
  [ $rc -eq 0 ] || { echo "SIG$sig: exit $rc"; cat "$dir/master.err"; exit 1; }
  head -n 1 "$dir/master.out" | grep -q '^/dev/' || { echo "SIG$sig: no pty path first"; exit 1; }
  grep -q 'end: RS4 5: DP start-up' "$dir/master.out" || { echo "SIG$sig: no final state"; exit 1; }
done
