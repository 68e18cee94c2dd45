#!/usr/bin/env bash
# Checks that every C++ source of the tree is laid out as .clang-format says (clang-format 14,
# Debian's clang-format-14): prints each file that differs and exits 1, else 0.
# Usage: scripts/check_format.sh [CLANG_FORMAT]   (default clang-format-14)
# To lay the tree out: git ls-files '*.cpp' '*.hpp' | xargs clang-format-14 -i --style=file
set -euo pipefail
cd "$(dirname "$0")/.."
tool=${1:-clang-format-14}
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else
  mapfile -t files < <(find . -path './build*' -prune -o -path './out' -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print)
fi
# One process for all: --dry-run --Werror reports each line that differs as file:line:col.
if out=$("$tool" --style=file --dry-run --Werror "${files[@]}" 2>&1); then
  echo "check_format: ${#files[@]} files, all laid out"
  exit 0
fi
grep -oE '^[^:]+\.(cpp|hpp)' <<<"$out" | sort -u | sed 's/^/not laid out as .clang-format says: /'
echo "check_format: ${#files[@]} files, some differ"
exit 1
