#!/usr/bin/env bash
# Every C++ source follows the repository's .clang-format (Debian 12's clang-format 14, installed
# by tools/setup.sh). Lists each file that differs and how to fix it.
set -u
root=${1:-.}
command -v clang-format >/dev/null || {
  echo "clang-format not found: run tools/setup.sh (it installs Debian's clang-format)"; exit 1; }
cd "$root" || exit 1
bad=()
while IFS= read -r -d '' f; do
  clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done < <(find sim meshing anatomy protocols tools tests \( -name '*.cpp' -o -name '*.h' \) -print0 \
           | sort -z)
if [ ${#bad[@]} -gt 0 ]; then
  echo "${#bad[@]} file(s) differ from .clang-format:"
  printf '  %s\n' "${bad[@]}"
  echo "fix: clang-format -i FILE... (or 'git clang-format' for the lines you changed)"
  exit 1
fi
echo "format ok"
