#!/usr/bin/env bash
# Citations a reader can follow (README, "References"): fails if a source file, script,
# CMake file or doc of the tree names a file outside the repository (a spec/ digest, a
# shared/ or seeds/ folder, a machine path) or a bare §-number without a source tag such as
# [RS4 manual §5.2.2]. Usage: tests/check_citations.sh [tree]   (default: this checkout)
set -euo pipefail

root="${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
cd "$root"

outside='spec/[a-z0-9-]+\.md|\.\./shared|shared/spec|(^|[^a-z])seeds/|/work/|/root/|/tmp/'
outside+='|(^|[^a-z/-])(rs4-profisafe|profibus-dp|profisafe-v1|other-devices)\.md'
outside+='|DESIGN\.md|STYLE(\.md)? habit|CONTRIBUTING-HELPERS|docs/requests'
# a source tag: [RS4 manual …], [IEC …], [PROFIsafe …], [PROFIBUS GSD spec …], [VPC3+ …],
# [docs/…] and the other names of docs/references.md
tag='\[(RS4 manual|IEC [0-9]|PROFIsafe V|PROFIBUS GSD spec|docs/|roboticslibrary/|pyprofibus'
tag+='|GridScan manual|METRON manual|Polaris manual|Modbus |VPC3|Felser|ELPRO|COM PROFIBUS|CP 5613|profirust|WAGO|Softing|tcpdump|PostgreSQL 15|RFC [0-9])[^][]*\]'

mapfile -d '' files < <(find . \( -name .git -o -name 'build*' -o -path ./fuzz/corpus \) -prune \
  -o -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.md' -o -name '*.txt' \
  -o -name '*.cmake' -o -name '*.sh' -o -name '*.py' \) -print0)

status=0
files=("${files[@]/#.\/tests\/check_citations.sh/}")  # this script names what it forbids
mapfile -d '' -t files < <(printf '%s\0' "${files[@]}" | grep -zv '^$')
# One grep and one perl over every file (a process per file took half a minute).
if grep -nE "$outside" "${files[@]}" /dev/null; then
  status=1
fi
# § that is not inside a tag
if perl -ne 'BEGIN { $tag = shift @ARGV } my $l = $_; $l =~ s/$tag//g;
             if ($l =~ /§/) { print "$ARGV:$.:$_"; $found = 1 }
             close ARGV if eof; END { exit($found ? 0 : 1) }' "$tag" "${files[@]}"; then
  status=1
fi
if ((status)); then
  echo "check_citations: cite a source a reader can get (README, \"References\")" >&2
fi
exit "$status"
