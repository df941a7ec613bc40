#!/bin/sh
# rs4sim's commands on a PostgreSQL archive, as a maintenance engineer uses them: the demo's
# proxy archives into a database of the fixture's server, `archive list/history/diff/verify/export`
# read it (the dates are today's, the password is never printed), the export imports into a
# SQLite file with the same history, and psql shows the rows the commands reported.
#   archive_postgres_cli.sh RS4SIM URI_FILE
# Exit 77 (skipped) without a server, unless RS4SIM_REQUIRE_POSTGRES=1.
set -eu
rs4sim=$1
uri_file=$2
if [ ! -s "$uri_file" ]; then
  echo "no PostgreSQL server (tests/storage/postgres_server.sh)"
  [ "${RS4SIM_REQUIRE_POSTGRES:-0}" = 1 ] && exit 1
  exit 77
fi
server=$(cat "$uri_file")                 # postgresql://rs4sim:PASSWORD@127.0.0.1:PORT/postgres
password=${server#postgresql://rs4sim:}
password=${password%%@*}
db=rs4sim_cli_$$
archive=${server%/postgres}/$db
db2=rs4sim_cli_copy_$$
archive2=${server%/postgres}/$db2
tmp=$(mktemp -d)
cleanup() {
  psql "$server" -qc "DROP DATABASE IF EXISTS $db WITH (FORCE)" >/dev/null 2>&1 || true
  psql "$server" -qc "DROP DATABASE IF EXISTS $db2 WITH (FORCE)" >/dev/null 2>&1 || true
  rm -rf "$tmp"
}
trap cleanup EXIT
psql "$server" -qc "CREATE DATABASE $db"
psql "$server" -qc "CREATE DATABASE $db2"

fail() { echo "FAIL: $*"; exit 1; }
no_password() { if grep -q -- "$password" "$1"; then fail "$1 shows the password"; fi; }

"$rs4sim" demo --archive "$archive" >"$tmp/demo.txt" 2>&1 || { cat "$tmp/demo.txt"; fail "demo"; }
grep -q "demo complete" "$tmp/demo.txt" || fail "the demo did not complete"
grep -q "the demo's sets are in postgresql://rs4sim@127.0.0.1:" "$tmp/demo.txt" || fail "demo's archive line"
no_password "$tmp/demo.txt"

"$rs4sim" archive list --archive "$archive" >"$tmp/list.txt" 2>&1
cat "$tmp/list.txt"
grep -q "^demo  *4 " "$tmp/list.txt" || fail "archive list has no station demo/4"
"$rs4sim" archive history --archive "$archive" --bus demo --address 4 >"$tmp/history.txt"
cat "$tmp/history.txt"
today=$(date -u +%Y-%m-%d)
grep -q "^ *1  *1  $today" "$tmp/history.txt" || fail "version 1 is not dated today ($today)"
versions=$(grep -c "^ *[0-9][0-9]*  *[0-9][0-9]*  $today" "$tmp/history.txt")
# diff on the server: the commissioning upload against the exchange's download (the same set).
"$rs4sim" archive diff --archive "$archive" --bus demo --address 4 >"$tmp/diff.txt" ||
  { cat "$tmp/diff.txt"; fail "archive diff"; }
cat "$tmp/diff.txt"
"$rs4sim" archive verify --archive "$archive" >"$tmp/verify.txt"
grep -q ": ok (1 stations)" "$tmp/verify.txt" || fail "archive verify"
for f in list history diff verify; do no_password "$tmp/$f.txt"; done

# What the commands said is what the server holds.
rows=$(psql "$archive" -tAc "SELECT count(*) FROM versions v JOIN stations s ON s.id = v.station_id WHERE s.bus = 'demo' AND s.address = 4")
[ "$rows" = "$versions" ] || fail "psql counts $rows versions, archive history showed $versions"
first=$(psql "$archive" -tAc "SELECT to_char(stored_at AT TIME ZONE 'UTC', 'YYYY-MM-DD') FROM versions WHERE number = 1")
[ "$first" = "$today" ] || fail "psql dates version 1 $first"

# What maintenance records, on the server: a note, who restored, and the rows psql shows.
"$rs4sim" archive note 1 "checked after commissioning" --archive "$archive" >"$tmp/note.txt"
grep -q 'note "checked after commissioning"' "$tmp/note.txt" || fail "archive note"
note=$(psql "$archive" -tAc "SELECT note FROM versions WHERE id = 1")
[ "$note" = "checked after commissioning" ] || fail "psql shows the note '$note'"
users=$(psql "$archive" -tAc "SELECT count(*) FROM versions WHERE user_name <> '' AND host_name <> ''")
[ "$users" = "$versions" ] || fail "the demo's $versions versions record no user and host ($users do)"
"$rs4sim" archive history --archive "$archive" --bus demo --address 4 >"$tmp/history.txt"

# An empty database is no archive yet: the refusal says how to start one, and that works.
set +e
"$rs4sim" archive list --archive "$archive2" >"$tmp/empty.txt" 2>&1; rc=$?
set -e
cat "$tmp/empty.txt"
[ $rc -eq 1 ] && grep -q "holds no archive yet.*; start one with: rs4sim archive init --archive 'postgresql://rs4sim@127.0.0.1:" "$tmp/empty.txt" || fail "empty database: rc $rc"
no_password "$tmp/empty.txt"
"$rs4sim" archive init --archive "$archive2" | grep -q ": ready (0 stations)" || fail "archive init"
"$rs4sim" archive list --archive "$archive2" >/dev/null || fail "list after init"

# Server -> file: the SQLite archive shows the same history.
"$rs4sim" archive export --archive "$archive" "$tmp/demo.rs4a" >/dev/null
"$rs4sim" archive import --archive "$tmp/copy.sqlite3" "$tmp/demo.rs4a" >/dev/null
"$rs4sim" archive history --archive "$tmp/copy.sqlite3" --bus demo --address 4 >"$tmp/copy.txt"
diff "$tmp/history.txt" "$tmp/copy.txt" || fail "the SQLite copy's history differs"
# archive copy: server -> file -> another server, each verified by the command, each with the
# same history; a second copy into the same archive adds nothing (every version is recognised).
"$rs4sim" archive copy --from "$archive" --to "$tmp/copied.sqlite3" >"$tmp/copy1.txt"
cat "$tmp/copy1.txt"
grep -q "; verified" "$tmp/copy1.txt" || fail "copy to SQLite"
"$rs4sim" archive history --archive "$tmp/copied.sqlite3" --bus demo --address 4 >"$tmp/h1.txt"
diff "$tmp/history.txt" "$tmp/h1.txt" || fail "the copied SQLite history differs"
"$rs4sim" archive copy --from "$tmp/copied.sqlite3" --to "$archive2" >"$tmp/copy2.txt"
grep -q "to postgresql://rs4sim@127.0.0.1:.*/$db2; verified" "$tmp/copy2.txt" || fail "copy to PostgreSQL"
no_password "$tmp/copy2.txt"
"$rs4sim" archive history --archive "$archive2" --bus demo --address 4 >"$tmp/h2.txt"
diff "$tmp/history.txt" "$tmp/h2.txt" || fail "the copied PostgreSQL history differs"
"$rs4sim" archive copy --from "$tmp/copied.sqlite3" --to "$archive2" --json >"$tmp/copy3.txt"
grep -q '"verified": true' "$tmp/copy3.txt" || fail "second copy"
grep -q '"versions": 0' "$tmp/copy3.txt" || fail "the second copy added versions"
twice=$(psql "$archive2" -tAc "SELECT count(*) FROM versions")
[ "$twice" = "$versions" ] || fail "after two copies psql counts $twice versions"
logged=$(psql "$archive2" -tAc "SELECT count(*) FROM sync_log")
"$rs4sim" archive copy --from "$tmp/copied.sqlite3" --to "$archive2" >/dev/null
[ "$(psql "$archive2" -tAc "SELECT count(*) FROM sync_log")" = "$logged" ] || fail "a third copy added sync log rows"
set +e
"$rs4sim" archive copy --from "$archive" >"$tmp/usage.txt" 2>&1; rc=$?
set -e
[ $rc -eq 2 ] && grep -q "needs --from ARCHIVE and --to ARCHIVE" "$tmp/usage.txt" || fail "copy without --to: rc $rc"
echo "ok: $versions versions on the server, dated $today, the same in every copy"
