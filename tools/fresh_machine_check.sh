#!/bin/sh
# `./build.sh test`'s install step and preflight on a fresh Debian 12: builds a minimal
# bookworm root with debootstrap (the Debian mirror, apt sources as a fresh install has them:
# bookworm, bookworm-updates, bookworm-security), puts this checkout's committed tree (HEAD)
# in it and runs `./build.sh deps` there through chroot. It passes when the packages build.sh
# installs (--no-install-recommends) give every module and command the tests use.
#
#   sudo tools/fresh_machine_check.sh           (about 8 minutes, 1.5 GB under TMPDIR)
#   MODE=test tools/fresh_machine_check.sh      the whole `./build.sh test` in the root (hours)
#
# Environment: MIRROR (default http://deb.debian.org/debian), SECURITY_MIRROR (default
# http://deb.debian.org/debian-security), MODE (deps or test, default deps), KEEP=1 leaves
# the root in place (its path is printed).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
mirror=${MIRROR:-http://deb.debian.org/debian}
security=${SECURITY_MIRROR:-http://deb.debian.org/debian-security}
mode=${MODE:-deps}
case "$mode" in deps|test) ;; *) echo "MODE: deps or test, not '$mode'" >&2; exit 2 ;; esac
[ "$(id -u)" -eq 0 ] || { echo "fresh_machine_check: needs root (debootstrap, chroot)" >&2; exit 2; }

if ! command -v debootstrap >/dev/null 2>&1; then
  echo "==> installing debootstrap"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap
fi

root=$(mktemp -d)
chmod 755 "$root"  # apt downloads as _apt: it must reach the root
mounted=
cleanup() {
  for m in $mounted; do umount "$root/$m" 2>/dev/null || umount -l "$root/$m" 2>/dev/null || :; done
  if [ "${KEEP:-}" = 1 ]; then
    echo "fresh_machine_check: the root is kept in $root"
  else
    rm -rf "$root"
  fi
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

start=$(date +%s)
echo "==> debootstrap --variant=minbase bookworm $root $mirror"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 || {
  tail -n 30 "$root.debootstrap.log"; rm -f "$root.debootstrap.log"; exit 1; }
rm -f "$root.debootstrap.log"
booted=$(date +%s)

cat >"$root/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb $security bookworm-security main
EOF
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
mounted="proc"
mount --bind /dev/pts "$root/dev/pts"  # the pty tests of MODE=test
mounted="dev/pts $mounted"

echo "==> the committed tree (HEAD $(git -C "$here" rev-parse --short HEAD)) into the root"
mkdir "$root/src"
git -C "$here" archive HEAD | tar -x -C "$root/src"

echo "==> chroot: ./build.sh $mode"
chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  CI=true /bin/bash -c "cd /src && ./build.sh $mode" </dev/null
end=$(date +%s)
echo "fresh_machine_check: passed: ./build.sh $mode on a fresh Debian 12 root in" \
  "$((end - start)) s (debootstrap $((booted - start)) s, ./build.sh $mode $((end - booted)) s)"
