#!/usr/bin/env bash
# Runs every libFuzzer executable in <dir> for <seconds>, starting from its seed corpus
# fuzz/corpus/<target>/ (copied to a scratch directory so the checked-in corpus stays
# small), plus the seeds that live elsewhere in the tree (extra_seeds: the shipped GSD file
# is read where it is, not copied). Fails on the first crash, leak, timeout or sanitizer
# report.
#   fuzz/run_all.sh build-fuzz/fuzz 20        (-runs=N instead: RUNS=1000000)
set -euo pipefail
dir=$1; seconds=${2:-20}
here=$(cd "$(dirname "$0")" && pwd)
extra_seeds() {  # target -> a folder of more seed files, or nothing
  case "$1" in
    fuzz_gsd_parse) echo "$here/../gsd/files" ;;
    fuzz_param_document) echo "$here/../tests/rs4/param_doc/data" ;;
  esac
}
found=0
for exe in $(find "$dir" -type f -executable -name 'fuzz_*' | sort); do
  name=$(basename "$exe")
  found=$((found + 1))
  work=$(mktemp -d)
  [ -d "$here/corpus/$name" ] && cp -r "$here/corpus/$name/." "$work/"
  extra=$(extra_seeds "$name")
  [ -n "$extra" ] && cp "$extra"/* "$work/"
  if [ -n "${RUNS:-}" ]; then limit="-runs=$RUNS"; else limit="-max_total_time=$seconds"; fi
  echo "--- $name ($limit)"
  log=$(mktemp)
  set +e
  "$exe" "$limit" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 "$work" >"$log" 2>&1
  rc=$?
  set -e
  grep -E 'stat::number_of_executed_units|Done [0-9]+ runs' "$log" || true
  [ "$rc" -ne 0 ] && tail -n 60 "$log" >&2
  rm -f "$log"
  rm -rf "$work"
  if [ "$rc" -ne 0 ]; then echo "fuzz target $name failed (exit $rc)" >&2; exit 1; fi
done
if [ "$found" -eq 0 ]; then echo "no fuzz targets found in $dir" >&2; exit 1; fi
echo "ran $found fuzz targets"
