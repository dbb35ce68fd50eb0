#!/usr/bin/env bash
# The repository's own rules, checked on the tracked files (git ls-files):
#   - no tracked file larger than 1 MB (1,000,000 bytes) and at most 10 MB in total:
#     run outputs (checkpoints, tarballs, frames, long CSVs) go to out/, which git ignores;
#   - the project speaks of itself only: no reference to the development log of the work
#     ("session" followed by a number, in text or in a file name), to issue numbers, or to
#     the specification folder beside the repository and its notes;
#   - docs are complete in our own words (docs/method.md), so no file may send the reader
#     to a folder a user's clone does not have.
# Usage: tests/repo/repo_hygiene.sh [SOURCE_DIR]. Exit 0 when clean, 1 with the offending
# files and lines. Outside a git checkout (a source tarball) there is nothing to check:
# exit 0 with a message.
set -uo pipefail
src=${1:-$(dirname "$0")/../..}
cd "$src" || { echo "repo_hygiene: no folder $src" >&2; exit 1; }
if ! command -v git >/dev/null 2>&1 || ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "repo_hygiene: $PWD is not a git checkout; nothing to check (passed)"
  exit 0
fi
cd "$(git rev-parse --show-toplevel)"
max_file=1000000
max_total=10000000
fail=0

# Sizes of the tracked files as they are in the work tree (a file deleted but not yet
# staged counts 0).
total=0
while IFS= read -r -d '' f; do
  [ -f "$f" ] || continue
  size=$(stat -c %s -- "$f")
  total=$((total + size))
  if ((size > max_file)); then
    echo "repo_hygiene: $f is $size bytes (limit $max_file): run outputs go to out/"
    fail=1
  fi
done < <(git ls-files -z)
if ((total > max_total)); then
  echo "repo_hygiene: the tracked files hold $total bytes (limit $max_total)"
  fail=1
fi

# Forbidden references. Each pattern is written so that it does not match itself.
patterns=(
  'sessio[n]s?[ _-]?(<=?|>=?)? ?[0-9]'  # the development log's numbering
  'issu[e] ?#?[0-9]'                      # issue numbers
  '\.\.[/]shared'                          # the specification folder beside the repository
  '(NUMERIC[S]|DESIG[N]|STYL[E])\.md'     # and its notes
)
for p in "${patterns[@]}"; do
  hits=$(git grep -n -I -i -E -e "$p" -- . 2>/dev/null)
  if [ -n "$hits" ]; then
    echo "repo_hygiene: text matching /$p/ (case-insensitive):"
    echo "$hits" | head -n 50
    n=$(echo "$hits" | wc -l)
    ((n > 50)) && echo "  ... and $((n - 50)) more lines"
    fail=1
  fi
  names=$(git ls-files | grep -i -E -e "$p")
  if [ -n "$names" ]; then
    echo "repo_hygiene: file names matching /$p/:"
    echo "$names"
    fail=1
  fi
done

if ((fail)); then
  echo "repo_hygiene: FAILED"
  exit 1
fi
echo "repo_hygiene: $(git ls-files | wc -l) tracked files, $total bytes, no forbidden reference (passed)"
