#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the npm packages of the viewer into a build directory (never into
# the source tree): three.js for the page, and with --test puppeteer-core for
# the browser test. Versions are pinned so that the page is tested against the
# three.js it is served with. Does nothing when they are already there, so
# that the tests run offline once installed.
#
#   bash scripts/install_viewer_web.sh BUILD_DIR [--test]
set -euo pipefail

three_version=0.187.0
puppeteer_version=24.43.1

if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [--test]" >&2
  exit 2
fi
prefix="$(realpath -m "$1")/viewer_web"
packages=("three@$three_version")
if [ "${2:-}" = "--test" ]; then
  packages+=("puppeteer-core@$puppeteer_version")
fi

installed_version() {
  node -e 'try { process.stdout.write(require(process.argv[1]).version) } catch (e) {}' \
    "$prefix/node_modules/$1/package.json" 2>/dev/null || true
}

missing=()
for package in "${packages[@]}"; do
  name="${package%@*}"
  version="${package##*@}"
  if [ "$(installed_version "$name")" != "$version" ]; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

if ! command -v npm >/dev/null 2>&1; then
  echo "error: npm is needed to install ${missing[*]} (Debian: apt-get install npm)" >&2
  exit 1
fi
mkdir -p "$prefix"
# A package.json of its own keeps npm from looking for one in the parents.
[ -f "$prefix/package.json" ] || echo '{ "private": true }' > "$prefix/package.json"
echo "Installing npm packages into $prefix: ${missing[*]}"
if ! npm install --prefix "$prefix" --no-audit --no-fund --save-exact "${missing[@]}"; then
  echo "error: npm could not install ${missing[*]} into $prefix (no network access to the npm registry?)" >&2
  exit 1
fi
