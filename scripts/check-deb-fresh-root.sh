#!/usr/bin/env bash
# Installs the Debian package (scripts/check-deb.sh builds it) on a new Debian 12 root, as a user
# would (`apt-get install ./pdd_<version>_<arch>.deb`, which brings its Depends from the Debian
# registry), then runs there what README promises: `pdd-mesh` on the bundled pipe, `pdd-verify`
# on its output, `python3 -c "import pdd"` with a mesh, and checks the man pages (issue 38 item
# 5). As root, on Debian; a few minutes (debootstrap and the Depends' download).
#
#   bash scripts/check-deb-fresh-root.sh DEB [ROOT]
#
# ROOT (default /var/tmp/pdd-deb-root) is removed and made anew; PDD_DEBIAN_MIRROR overrides the
# registry (default: the first Debian URI of this machine's apt sources).
set -euo pipefail
deb=$(realpath "${1:?usage: scripts/check-deb-fresh-root.sh DEB [ROOT]}")
root=${2:-/var/tmp/pdd-deb-root}
[ "$(id -u)" -eq 0 ] || { echo "check-deb-fresh-root: run as root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap
mirror=${PDD_DEBIAN_MIRROR:-$(sed -n 's/^URIs:[[:space:]]*\([^[:space:]]*debian\/\{0,1\}\)$/\1/p' \
  /etc/apt/sources.list.d/*.sources 2>/dev/null | head -n 1)}
[ -n "$mirror" ] || { echo "check-deb-fresh-root: set PDD_DEBIAN_MIRROR" >&2; exit 2; }

unmount_all() {
  for m in dev/pts dev proc sys; do mountpoint -q "$root/$m" && umount -l "$root/$m"; done
  return 0
}
trap unmount_all EXIT
unmount_all
rm -rf "$root"
debootstrap --variant=minbase bookworm "$root" "$mirror" >/dev/null
cp -L /etc/resolv.conf /etc/hosts "$root/etc/" 2>/dev/null || true
mount -t proc proc "$root/proc" && mount -t sysfs sysfs "$root/sys"
mount --bind /dev "$root/dev" && mount --bind /dev/pts "$root/dev/pts"
cp "$deb" "$root/tmp/"
in_root() { chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 PATH=/usr/bin:/bin /bin/bash -c "$*"; }
start=$(date +%s)
in_root "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq /tmp/$(basename "$deb")" \
  >/dev/null
echo "check-deb-fresh-root: installed $(basename "$deb") and its Depends in $(($(date +%s) - start)) s"
in_root "cd /tmp && pdd-mesh --version && pdd-mesh /usr/share/pdd/data/pipe.poly --max-area 1e-4 \
  --subdomains 8 --output-per-subdomain pipe && pdd-verify pipe/mesh.pvtu /usr/share/pdd/data/pipe.poly \
  --max-area 1e-4 --quiet && echo pdd-verify: passed"
in_root "cd /tmp && python3 -c \"import pdd; r = pdd.triangulate({'vertices': [[0, 0], [1, 0], [1, 1], [0, 1]], \
'segments': [[0, 1], [1, 2], [2, 3], [3, 0]]}, 'pqa0.01'); print('python3: pdd', pdd.__version__, pdd.__file__, \
len(r['triangles']), 'triangles')\""
for page in "$root"/usr/share/man/man1/pdd-*.1*; do echo "man page: ${page#"$root"}"; done
