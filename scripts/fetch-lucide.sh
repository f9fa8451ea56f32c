#!/bin/sh
# Fetches the Lucide icon set (the npm package `lucide-static`, its `icons/`
# folder of ~2,500 SVG files) into DEST (default target/corpus/lucide/icons),
# for `cargo run --release -p lncert-cli --example corpus -- DEST`.
# The icons are not committed: they are fetched, never vendored.
#
#   scripts/fetch-lucide.sh [DEST]        # LUCIDE_VERSION=1.87.0 pins a version
set -eu
dest="${1:-target/corpus/lucide/icons}"
version="${LUCIDE_VERSION:-latest}"
command -v npm >/dev/null || { echo "fetch-lucide: npm is needed (apt-get install -y npm)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && npm pack "lucide-static@$version" --silent >/dev/null)
tgz=$(ls "$tmp"/lucide-static-*.tgz)
tar -xzf "$tgz" -C "$tmp"
rm -rf "$dest"
mkdir -p "$(dirname "$dest")"
cp -r "$tmp/package/icons" "$dest"
echo "$(ls "$dest" | wc -l) icons in $dest ($(basename "$tgz" .tgz))"
