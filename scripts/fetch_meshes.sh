#!/usr/bin/env bash
# Real meshes to test and benchmark with, from a Debian package's data: the
# Stanford bunny (75,408 triangles), the armadillo and others from
# libcgal-demo's data archive, extracted into animations/meshes/. Not
# committed (the repository keeps no third-party meshes); fetched once.
#   bash scripts/fetch_meshes.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dest=$here/animations/meshes
want=(bunny00.off armadillo.off ChineseDragon-10kv.off elephant.off)
missing=0
for m in "${want[@]}"; do [[ -s $dest/$m ]] || missing=1; done
[[ $missing == 0 ]] && exit 0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get download libcgal-demo >/dev/null 2>&1) || { echo "fetch_meshes.sh: apt-get download libcgal-demo failed (run apt-get update first?)" >&2; exit 1; }
dpkg -x "$work"/libcgal-demo_*.deb "$work/pkg"
mkdir -p "$dest"
tar -xzf "$work/pkg/usr/share/doc/libcgal-dev/data.tar.gz" -C "$work" "${want[@]/#/data/meshes/}"
for m in "${want[@]}"; do mv "$work/data/meshes/$m" "$dest/$m.tmp" && mv "$dest/$m.tmp" "$dest/$m"; done
echo "fetch_meshes.sh: ${want[*]} into $dest"
