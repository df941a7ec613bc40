#!/bin/sh
# A throw-away PostgreSQL server for the archive's tests: a real server on loopback, started
# by the tests themselves (a ctest fixture), never assumed to be running.
#
#   postgres_server.sh start DIR   initdb + pg_ctl start in a new temporary directory, on
#                                  127.0.0.1 and a free port, superuser "rs4sim" with a random
#                                  password (scram-sha-256 on TCP); writes DIR/uri, the URI
#                                  the tests connect with
#   postgres_server.sh stop DIR    stops that server and removes its files
#
# Without PostgreSQL's server programs (Debian: postgresql) `start` exits 77 (ctest: skipped)
# and writes no DIR/uri, so the PostgreSQL half of the suite skips itself; with
# RS4SIM_REQUIRE_POSTGRES=1 (./build.sh test, CI) it fails instead. As root the server runs
# as the postgres user (initdb refuses root). Durability is off (fsync=off): the cluster is
# thrown away, and a process crash, the only crash the tests provoke, loses nothing anyway.
set -eu
cmd=${1:?start or stop}
dir=${2:?a directory for the URI file}

as_server_user() {
  if [ "$(id -u)" -eq 0 ]; then runuser -u postgres -- "$@"; else "$@"; fi
}

bindir=""
for candidate in "$(pg_config --bindir 2>/dev/null || true)" /usr/lib/postgresql/*/bin; do
  if [ -x "$candidate/initdb" ] && [ -x "$candidate/pg_ctl" ]; then bindir=$candidate; break; fi
done

case "$cmd" in
  start)
    rm -rf "$dir"
    mkdir -p "$dir"
    if [ -z "$bindir" ]; then
      echo "postgres_server.sh: no initdb/pg_ctl (Debian package postgresql)" >&2
      [ "${RS4SIM_REQUIRE_POSTGRES:-0}" = 1 ] && exit 1
      exit 77
    fi
    data=$(mktemp -d -t rs4sim-pg-XXXXXX)
    echo "$data" >"$dir/data_dir"
    password=$(od -An -N12 -tx1 /dev/urandom | tr -d ' \n')
    printf '%s\n' "$password" >"$data/pwfile"
    chmod 600 "$data/pwfile"
    [ "$(id -u)" -eq 0 ] && chown -R postgres "$data"
    as_server_user "$bindir/initdb" -D "$data/db" -U rs4sim --pwfile="$data/pwfile" \
      --auth-local=trust --auth-host=scram-sha-256 -E UTF8 --locale=C.UTF-8 \
      >"$data/initdb.log" 2>&1 || { cat "$data/initdb.log" >&2; exit 1; }
    rm -f "$data/pwfile"
    # A free port: try a few at random (two ctest runs may start servers at once).
    tries=0
    while :; do
      random=$(od -An -N2 -tu2 /dev/urandom | tr -d ' ')
      port=$((20000 + random % 40000))
      if as_server_user "$bindir/pg_ctl" -D "$data/db" -l "$data/server.log" -w -t 60 \
           -o "-c listen_addresses=127.0.0.1 -p $port -k $data -c fsync=off \
               -c full_page_writes=off -c synchronous_commit=off -c max_connections=60" \
           start >/dev/null 2>&1; then
        break
      fi
      tries=$((tries + 1))
      if [ "$tries" -ge 5 ]; then cat "$data/server.log" >&2; exit 1; fi
    done
    echo "postgresql://rs4sim:$password@127.0.0.1:$port/postgres" >"$dir/uri"
    version=$("$bindir/postgres" --version)
    echo "$version on 127.0.0.1:$port (data in $data)"
    ;;
  stop)
    [ -f "$dir/data_dir" ] || exit 0
    data=$(cat "$dir/data_dir")
    [ -n "$bindir" ] && as_server_user "$bindir/pg_ctl" -D "$data/db" -m fast -w stop >/dev/null 2>&1 || true
    rm -rf "$data" "$dir"
    ;;
  *)
    echo "usage: postgres_server.sh start|stop DIR" >&2
    exit 2
    ;;
esac
