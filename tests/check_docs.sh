#!/usr/bin/env bash
# Files describe what the toolkit is, not how it was made, and the documentation's links work.
# Fails when
#   - a tracked file holds a development-history marker: a numbered work period ("session" or
#     "sessions" followed by a number), a tracker number ("issue" followed by a number or #number),
#     a numbered "stop", or a path of a developer's machine (an absolute /tmp or /work folder);
#   - a tracked file names DESIGN.md (not in the repository; the conventions are in
#     docs/conventions.md, the design principles in docs/developer-guide.md) or a docs/*.md page
#     that does not exist;
#   - a relative link in a tracked Markdown file (README.md, docs/**, the folder READMEs) does
#     not resolve to a file or folder of the repository.
# The words alone ("a session", "this issue", "stop the run") are fine; so are version numbers.
set -u
root=${1:-.}
cd "$root" || exit 1
self=tests/check_docs.sh
status=0

# The files to check: the tracked ones, or every file outside build folders without git.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files | grep -vxF "$self")
else
  mapfile -t files < <(find . -type f -not -path './.git/*' -not -path './build*' \
    -not -path "./$self" | sed 's|^\./||')
fi
existing=()
for f in "${files[@]}"; do [ -f "$f" ] && existing+=("$f"); done
files=("${existing[@]}")

report() {  # report <title> <hits>
  if [ -n "$2" ]; then
    echo "$1:"
    echo "$2" | head -40 | sed 's/^/  /'
    local n
    n=$(echo "$2" | wc -l)
    [ "$n" -gt 40 ] && echo "  ... and $((n - 40)) more"
    status=1
  fi
}

# Development-history markers (Perl regular expressions, case-insensitive).
markers=(
  '\bsessions?[ -]?#?[0-9]+'
  '\bissues? #?[0-9]+\b'
  '\bstop #[0-9]+|\bstop [0-9]+\b(?![.,][0-9]|\s*(s|ms|mm|%|steps?|iterations?)\b)'
  '(?<![A-Za-z0-9_.~-])/(tmp|work)/'
)
pattern=$(IFS='|'; echo "${markers[*]}")
hits=$(printf '%s\0' "${files[@]}" | xargs -0 grep -nIiP -e "$pattern" -- 2>/dev/null)
report "development-history markers (describe the current state; the history is in git log)" \
  "$hits"

# Names of documents that are not there.
hits=$(printf '%s\0' "${files[@]}" | xargs -0 grep -nIP -e '\bDESIGN\.md\b' -- 2>/dev/null)
report "DESIGN.md is not in the repository (conventions: docs/conventions.md; design principles: docs/developer-guide.md)" \
  "$hits"
hits=$(printf '%s\0' "${files[@]}" | xargs -0 grep -noIP -e '(?<![A-Za-z0-9_./-])docs/[A-Za-z0-9_./-]*[A-Za-z0-9_-]\.md\b' -- 2>/dev/null |
  while IFS=: read -r file line ref; do [ -f "$ref" ] || echo "$file:$line: $ref"; done)
report "references to docs pages that do not exist" "$hits"

# Relative links in Markdown files: [text](target) and [name]: target.
hits=""
for md in "${files[@]}"; do
  case "$md" in *.md) ;; *) continue ;; esac
  dir=$(dirname "$md")
  while IFS=: read -r line target; do
    case "$target" in http:* | https:* | mailto:* | '#'* | '') continue ;; esac
    path=${target%%#*}
    path=${path%%\?*}
    [ -z "$path" ] && continue
    if [ "${path#/}" != "$path" ]; then resolved=".$path"; else resolved="$dir/$path"; fi
    [ -e "$resolved" ] || hits+="$md:$line: $target"$'\n'
  done < <(grep -noP '\]\(\s*<?\K[^)\s>]+' "$md"; grep -noP '^\s*\[[^\]]+\]:\s*<?\K[^\s>]+' "$md")
done
report "relative links that do not resolve" "${hits%$'\n'}"

[ $status -eq 0 ] && echo "docs ok: ${#files[@]} files, no history markers, every link resolves"
exit $status
