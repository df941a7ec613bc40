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
tag+='|GridScan manual|METRON manual|Polaris manual|Modbus |VPC3|Felser|ELPRO|COM PROFIBUS|CP 5613|profirust|WAGO|Softing|tcpdump|PostgreSQL 15)[^][]*\]'

mapfile -d '' files < <(find . \( -name .git -o -name 'build*' -o -path ./fuzz/corpus \) -prune \
  -o -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.md' -o -name '*.txt' \
  -o -name '*.cmake' -o -name '*.sh' -o -name '*.py' \) -print0)

status=0
for f in "${files[@]}"; do
  [[ "$f" == ./tests/check_citations.sh ]] && continue
  if grep -nE "$outside" "$f" /dev/null; then
    status=1
  fi
  # § that is not inside a tag
  if sed -E "s#$tag##g" "$f" | grep -n '§' | sed "s|^|$f:|"; then
    status=1
  fi
done
if ((status)); then
  echo "check_citations: cite a source a reader can get (README, \"References\")" >&2
fi
exit "$status"
