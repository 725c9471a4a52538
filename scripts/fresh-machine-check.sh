#!/usr/bin/env bash
# The fresh-machine check: builds a new Debian 12 root with debootstrap (minbase, from the Debian
# registry this machine's apt uses), clones this repository's HEAD into it, puts a read-only copy
# of ../shared beside it (as CI has it), and runs README's two set-up commands there as root, as a
# newcomer would: `bash scripts/quickstart.sh`, then `bash .ci/run` (CI=true). Prints how long each
# took and exits non-zero when either fails. Run it before resolving any change to dependencies,
# CI or README's commands (CONTRIBUTING.md). As root, on Debian; about 5 minutes for the root plus
# .ci/run's time.
#
#   bash scripts/fresh-machine-check.sh [--quickstart-only] [ROOT]
#
# ROOT (default /var/tmp/pdd-fresh-root) is removed and made anew. PDD_DEBIAN_MIRROR overrides the
# registry (default: the first Debian URI of this machine's apt sources). Logs: ROOT.logs/.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
only_quickstart=0
if [ "${1:-}" = "--quickstart-only" ]; then
  only_quickstart=1
  shift
fi
root=${1:-/var/tmp/pdd-fresh-root}
logs=$root.logs

[ "$(id -u)" -eq 0 ] || { echo "fresh-machine-check: run as root (debootstrap, chroot)" >&2; exit 2; }
if ! command -v debootstrap >/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
fi

mirror=${PDD_DEBIAN_MIRROR:-}
if [ -z "$mirror" ]; then # the registry apt already uses here (deb822 sources or sources.list)
  mirror=$(sed -n 's/^URIs:[[:space:]]*\([^[:space:]]*debian\/\{0,1\}\)$/\1/p' \
             /etc/apt/sources.list.d/*.sources 2>/dev/null | head -n 1)
  [ -n "$mirror" ] || mirror=$(awk '$1 == "deb" && $2 ~ /debian\/?$/ { print $2; exit }' \
                                 /etc/apt/sources.list 2>/dev/null)
fi
[ -n "$mirror" ] || { echo "fresh-machine-check: set PDD_DEBIAN_MIRROR" >&2; exit 2; }

unmount_all() {
  for m in dev/pts dev/shm dev proc sys; do
    mountpoint -q "$root/$m" && umount -l "$root/$m"
  done
  return 0
}
trap unmount_all EXIT
unmount_all
rm -rf "$root" "$logs"
mkdir -p "$root" "$logs"

t0=$(date +%s)
echo "fresh-machine-check: debootstrap bookworm (minbase) from $mirror into $root"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$logs/debootstrap.log" 2>&1 ||
  { tail -20 "$logs/debootstrap.log"; exit 1; }
# apt's sources as a Debian 12 machine has them: this machine's (bookworm, its updates, security),
# but not the deb-src lines scripts/install-deps.sh --tsan-tbb added here (a fresh machine has
# none: .ci/run must add them itself)
rm -f "$root/etc/apt/sources.list"
copied=0
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] && [ "$(basename "$f")" != pdd-deb-src.sources ] || continue
  cp "$f" "$root/etc/apt/sources.list.d/"
  copied=1
done
[ "$copied" = 1 ] || cp /etc/apt/sources.list "$root/etc/apt/sources.list"
cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
# no /etc/hosts, as debootstrap leaves it and as CI runs: the machine does not know its own name
# (the MPI tests set HWLOC_COMPONENTS=-gl, without which every mpiexec waited for DNS)
mount -t proc proc "$root/proc"
mount -t sysfs sysfs "$root/sys"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
mount -t tmpfs shm "$root/dev/shm"
t_root=$(($(date +%s) - t0))

# the committed HEAD, as a clone has it (no build outputs, no untracked files)
mkdir -p "$root/work"
commit=$(git -C "$repo" rev-parse --short HEAD)
git clone -q --no-local "$repo" "$root/work/main"
git -C "$root/work/main" checkout -q "$commit"
if [ -d "$repo/../shared" ]; then
  cp -a "$repo/../shared" "$root/work/shared"
  chmod -R a-w "$root/work/shared"
fi

run_in_root() { # LOG COMMAND: runs COMMAND in the root's clone with a newcomer's environment
  local log=$1
  shift
  chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb CI=true \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    /bin/bash -c "cd /work/main && $*" </dev/null >"$logs/$log" 2>&1
}

status=0
t0=$(date +%s)
run_in_root quickstart.log bash scripts/quickstart.sh || status=1
t_quick=$(($(date +%s) - t0))
echo "fresh-machine-check: bash scripts/quickstart.sh: $([ $status -eq 0 ] && echo passed || echo FAILED)" \
     "in ${t_quick} s (log $logs/quickstart.log)"
t_ci=-
if [ $status -eq 0 ] && [ $only_quickstart -eq 0 ]; then
  t0=$(date +%s)
  run_in_root ci.log bash .ci/run || status=1
  t_ci=$(($(date +%s) - t0))
  echo "fresh-machine-check: bash .ci/run: $([ $status -eq 0 ] && echo passed || echo FAILED)" \
       "in ${t_ci} s (log $logs/ci.log)"
  grep '^== ' "$logs/ci.log" || true
fi
[ $status -eq 0 ] || tail -40 "$logs"/*.log
echo "fresh-machine-check: root ${t_root} s, quickstart ${t_quick} s, .ci/run ${t_ci} s:" \
     "$([ $status -eq 0 ] && echo passed || echo FAILED) at $commit"
exit $status
