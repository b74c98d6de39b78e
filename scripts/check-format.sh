#!/usr/bin/env bash
# Fails if any C++ file in the repository is not as .clang-format writes it; prints the
# files and how to fix them (clang-format -i FILE). Takes seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --clang
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if ! clang-format --dry-run -Werror "${files[@]}" 2>/tmp/skylit-format.$$; then
  grep -E '^[^ ].*: error:' /tmp/skylit-format.$$ | cut -d: -f1 | sort -u | sed 's/^/not formatted: /' >&2
  echo "check-format: run clang-format -i on the files above" >&2
  rm -f /tmp/skylit-format.$$
  exit 1
fi
rm -f /tmp/skylit-format.$$
echo "check-format: ${#files[@]} files formatted"
