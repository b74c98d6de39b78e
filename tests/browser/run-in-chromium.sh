#!/usr/bin/env bash
# Installs playwright-core (the version pinned in package-lock.json) into DEPS_DIR with
# `npm ci` when it is not there yet, then runs report_readout.mjs with the other
# arguments. Used by tests/app/report_browser_test.cpp.
#
#   run-report-readout.sh DEPS_DIR CHROMIUM PAGE.html X Y [X Y …]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
deps="$1"
shift
mkdir -p "$deps"
if ! cmp -s "$here/package-lock.json" "$deps/package-lock.json" || [ ! -d "$deps/node_modules/playwright-core" ]; then
  cp "$here/package.json" "$here/package-lock.json" "$deps/"
  (cd "$deps" && npm ci --silent --no-audit --no-fund >&2)
fi
cp "$here/report_readout.mjs" "$deps/"
exec node "$deps/report_readout.mjs" "$@"
