#!/usr/bin/env bash
# Installs playwright-core (the version pinned in package-lock.json) into DEPS_DIR with
# `npm ci` when it is not there yet, then runs one of this folder's page scripts with
# the other arguments. Used by tests/app/browser_support.h (the report's and the
# animation viewer's browser tests).
#
#   run-in-chromium.sh DEPS_DIR SCRIPT.mjs CHROMIUM PAGE.html [ARGUMENTS …]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
deps="$1"
script="$2"
shift 2
mkdir -p "$deps"
if ! cmp -s "$here/package-lock.json" "$deps/package-lock.json" || [ ! -d "$deps/node_modules/playwright-core" ]; then
  cp "$here/package.json" "$here/package-lock.json" "$deps/"
  (cd "$deps" && npm ci --silent --no-audit --no-fund >&2)
fi
cp "$here"/*.mjs "$deps/"
exec node "$deps/$script" "$@"
