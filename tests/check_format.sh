#!/usr/bin/env bash
# Every C++ source follows the repository's .clang-format (Debian 12's clang-format 14, installed
# by tools/setup.sh). Lists each file that differs and how to fix it.
set -u
root=${1:-.}
command -v clang-format >/dev/null || {
  echo "clang-format not found: run tools/setup.sh (it installs Debian's clang-format)"; exit 1; }
cd "$root" || exit 1
# Batches of files per clang-format call (its start-up is most of the cost), on every core; each
# file that differs yields "FILE:LINE:COL: error: code should be clang-formatted".
out=$(find sim meshing anatomy protocols tools tests \( -name '*.cpp' -o -name '*.h' \) -print0 \
  | xargs -0 -P "$(nproc)" -n 32 clang-format --dry-run -Werror 2>&1)
rc=$?
mapfile -t bad < <(grep -E 'error: code should be clang-formatted' <<<"$out" | cut -d: -f1 | sort -u)
if [ $rc -ne 0 ] && [ ${#bad[@]} -eq 0 ]; then
  echo "clang-format failed (not a format difference):"; echo "$out" | head -20; exit 1
fi
if [ ${#bad[@]} -gt 0 ]; then
  echo "${#bad[@]} file(s) differ from .clang-format:"
  printf '  %s\n' "${bad[@]}"
  echo "fix: clang-format -i FILE... (or 'git clang-format' for the lines you changed)"
  exit 1
fi
echo "format ok"
