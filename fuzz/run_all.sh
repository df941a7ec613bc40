#!/usr/bin/env bash
# Runs every libFuzzer executable in <dir> for <seconds>, starting from its seed corpus
# fuzz/corpus/<target>/ (copied to a scratch directory so the checked-in corpus stays
# small), plus the seeds that live elsewhere in the tree (extra_seeds: the shipped GSD file
# is read where it is, not copied). Fails on the first crash, leak, timeout or sanitizer
# report.
#   fuzz/run_all.sh build-asan/fuzz 20        (-runs=N instead: RUNS=1000000; JOBS=2: two
#                                             targets at a time)
set -euo pipefail
dir=$1; seconds=${2:-20}
here=$(cd "$(dirname "$0")" && pwd)
extra_seeds() {  # target -> a folder of more seed files, or nothing
  case "$1" in
    fuzz_gsd_parse) echo "$here/../gsd/files" ;;
    fuzz_param_document) echo "$here/../tests/rs4/param_doc/data" ;;
  esac
}
# One target: its scratch corpus, its run, its summary; the log's tail on failure.
run_one() {  # exe
  local exe=$1 name work extra limit log rc
  name=$(basename "$exe")
  work=$(mktemp -d)
  [ -d "$here/corpus/$name" ] && cp -r "$here/corpus/$name/." "$work/"
  extra=$(extra_seeds "$name")
  [ -n "$extra" ] && cp "$extra"/* "$work/"
  if [ -n "${RUNS:-}" ]; then limit="-runs=$RUNS"; else limit="-max_total_time=$seconds"; fi
  log=$(mktemp)
  set +e
  "$exe" "$limit" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 "$work" >"$log" 2>&1
  rc=$?
  set -e
  # One write per target, so that the summaries of parallel runs do not interleave.
  {
    echo "--- $name ($limit)"
    grep -E 'stat::number_of_executed_units|Done [0-9]+ runs' "$log" || true
    if [ "$rc" -ne 0 ]; then
      tail -n 60 "$log"
      echo "fuzz target $name failed (exit $rc)"
    fi
  } >"$log.summary" 2>&1
  cat "$log.summary"
  rm -rf "$work" "$log" "$log.summary"
  return "$rc"
}
# JOBS targets at a time (each runs on one core; default 1).
jobs_max=${JOBS:-1}
found=0
failed=0
running=0
for exe in $(find "$dir" -type f -executable -name 'fuzz_*' | sort); do
  found=$((found + 1))
  run_one "$exe" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs_max" ]; then
    wait -n || failed=$((failed + 1))
    running=$((running - 1))
  fi
  [ "$failed" -eq 0 ] || break
done
while [ "$running" -gt 0 ]; do
  wait -n || failed=$((failed + 1))
  running=$((running - 1))
done
if [ "$found" -eq 0 ]; then echo "no fuzz targets found in $dir" >&2; exit 1; fi
if [ "$failed" -ne 0 ]; then echo "$failed fuzz target(s) failed" >&2; exit 1; fi
echo "ran $found fuzz targets"
