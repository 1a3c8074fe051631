#!/usr/bin/env bash
# Checks that every C++ file of the project follows .clang-format (clang-format 14, Debian 12's).
# Prints the files that differ and fails if there is one; --fix rewrites them in place instead.
#
#   tools/check_format.sh          check (CI)
#   tools/check_format.sh --fix    format every file
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
format=${CLANG_FORMAT:-clang-format}
command -v "$format" >/dev/null || bash "$here/voxelfair.sh" setup

mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [[ "${1:-}" == "--fix" ]]; then
  "$format" -i --style=file "${files[@]}"
  exit 0
fi

bad=()
for f in "${files[@]}"; do
  if ! "$format" --style=file --dry-run --Werror "$f" >/dev/null 2>&1; then
    bad+=("$f")
  fi
done
if ((${#bad[@]})); then
  printf 'not formatted (run tools/check_format.sh --fix):\n' >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "format: ${#files[@]} files follow .clang-format"
