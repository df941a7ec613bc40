#!/bin/sh
# tools/preflight.sh: passes on this machine (every module and command the tests use is
# there), and names a missing Python module or command with its Debian package when one is
# hidden: a module through a PYTHONPATH entry that shadows it with a failing import, a command
# through a PATH that holds every command of the table but that one.
# usage: preflight_test.sh PREFLIGHT
set -u
preflight=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$preflight" >"$dir/out" 2>&1 || { cat "$dir/out"; fail "the preflight fails on this machine"; }
cat "$dir/out"
"$preflight" --packages | grep -qx 'python3-serial-asyncio' || fail "--packages lacks python3-serial-asyncio"

# A module hidden: serial_asyncio (pymodbus' serial client needs it).
mkdir "$dir/shadow"
echo 'raise ModuleNotFoundError("No module named serial_asyncio (hidden)", name="serial_asyncio")' \
  >"$dir/shadow/serial_asyncio.py"
PYTHONPATH="$dir/shadow" "$preflight" >"$dir/out" 2>&1
rc=$?
cat "$dir/out"
[ $rc -eq 1 ] || fail "serial_asyncio hidden: exit $rc, expected 1"
grep -q 'python serial_asyncio: .*No module named serial_asyncio' "$dir/out" || fail "serial_asyncio not named"
grep -q 'package python3-serial-asyncio, for ' "$dir/out" || fail "python3-serial-asyncio not named"
grep -q 'install: apt-get install --no-install-recommends python3-serial-asyncio ' "$dir/out" ||
  fail "no install line with exactly python3-serial-asyncio"
# the module that fails because of it (pymodbus.client) is not blamed on its own package
! grep -q 'python pymodbus.client' "$dir/out" || fail "pymodbus.client named though installed"

# A command hidden: mbpoll, from a PATH with every other command of the table.
mkdir "$dir/bin"
"$preflight" --list | while read -r kind name _; do
  [ "$kind" = command ] && [ "$name" != mbpoll ] && [ "${name#/}" = "$name" ] &&
    ln -s "$(command -v "$name")" "$dir/bin/$name"
done
PATH="$dir/bin" /bin/sh "$preflight" >"$dir/out" 2>&1
rc=$?
cat "$dir/out"
[ $rc -eq 1 ] || fail "mbpoll hidden: exit $rc, expected 1"
grep -q 'command mbpoll: command not found' "$dir/out" || fail "mbpoll not named"
grep -q 'package mbpoll, for ' "$dir/out" || fail "package mbpoll not named"
grep -q '1 of the [0-9]* modules, commands and files' "$dir/out" || fail "more than mbpoll missing"
echo "ok: the preflight passes here and names a hidden module and a hidden command with their packages"
