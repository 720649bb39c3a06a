#!/usr/bin/env bash
# Times the README's first command on a fresh Debian 12: a minimal Debian 12
# (debootstrap --variant=minbase bookworm) in a chroot, a clean clone of this
# repository at COMMIT (default HEAD) in it, and `./build.sh demo` timed from
# its start to the demo picture. Needs root, debootstrap and Debian's
# package archive; leaves nothing behind.
#   bench/fresh_demo.sh [COMMIT]   prints "COMMIT: SECONDS s"
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
commit=$(git -C "$repo" rev-parse --short "${1:-HEAD}")
# The archive this machine's apt uses (absent files and comments skipped).
mirror=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/* 2>/dev/null | grep -v "^[[:space:]]*#" | grep -oE "https?://[^ ]+/debian/?( |$)" | head -1 | tr -d ' ' || true)
[ -n "$mirror" ] || { echo "fresh_demo.sh: no Debian archive in /etc/apt/sources*" >&2; exit 1; }
root=$(mktemp -d /tmp/umbra-fresh-XXXXXX)
cleanup() {
  umount "$root/proc" 2>/dev/null || true
  rm -rf "$root" "$root.log"
}
trap cleanup EXIT
debootstrap --variant=minbase bookworm "$root" "$mirror" > "$root.log" 2>&1 || { tail -20 "$root.log" >&2; exit 1; }
cp /etc/resolv.conf "$root/etc/"
mount -t proc proc "$root/proc"
git clone -q "$repo" "$root/root/umbra"
git -C "$root/root/umbra" checkout -q "$commit"
start=$(date +%s.%N)
if ! chroot "$root" /bin/bash -c 'cd /root/umbra && ./build.sh demo' > "$root/demo.log" 2>&1; then
  tail -20 "$root/demo.log" >&2
  exit 1
fi
end=$(date +%s.%N)
awk -v c="$commit" -v s="$start" -v e="$end" 'BEGIN { printf "%s: %.0f s\n", c, e - s }'
