#!/usr/bin/env bash
# The repository stands alone: someone who clones it has every document it cites. The project's
# documents are in docs/ (docs/README.md); nothing may send a reader to the team's shared folder
# beside the checkout, which a clone does not have.
#
#   tests/repo/check_stands_alone.sh [SOURCE_DIR]      (ctest: repo_stands_alone, label repo)
#
# Exit 1, printing FILE:LINE: what is wrong, when a tracked file
#   1. names a path into the shared folder beside the checkout (".." then "/shared"); test data is
#      in data/ (docs/design.md, "Test data");
#   2. cites a Markdown file named DESIGN, PAPERS or STYLE (upper case, as the shared documents
#      were) by a path that is not a file inside the repository, taken from the repository's root
#      or from the citing file's folder.
# Files: `git ls-files` when SOURCE_DIR is in a git checkout, else every file under it except
# .git/ and build*/ (a source archive). Files missing from the work tree and binary files are
# skipped. Exit 0 when nothing is found, 2 on bad usage.
set -euo pipefail

if [[ $# -gt 1 ]]; then
  echo "usage: check_stands_alone.sh [SOURCE_DIR]" >&2
  exit 2
fi
src=${1:-$(dirname "$0")/../..}
if ! root=$(cd "$src" 2>/dev/null && pwd -P); then
  echo "check_stands_alone.sh: no such folder: $src" >&2
  exit 2
fi
cd "$root"

shared_re='\.\./shared'
doc_re='[A-Za-z0-9_./-]*(DESIGN|PAPERS|STYLE)\.md'

files=()
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  while IFS= read -r -d '' f; do
    [[ -f $f ]] && files+=("$f")
  done < <(git ls-files -z)
else
  while IFS= read -r -d '' f; do
    files+=("${f#./}")
  done < <(find . \( -name .git -o -path './build*' \) -prune -o -type f -print0)
fi
if [[ ${#files[@]} -eq 0 ]]; then
  echo "check_stands_alone.sh: no files found under $root" >&2
  exit 2
fi

failures=0
report() {
  echo "$1" >&2
  failures=$((failures + 1))
}

# True when path $2, cited from file $1, is a file inside the repository.
resolves() {
  local from_dir candidate real
  from_dir=$(dirname "$1")
  for candidate in "$2" "$from_dir/$2"; do
    real=$(realpath -m -- "$candidate")
    if [[ ( $real == "$root"/* ) && -f $real ]]; then
      return 0
    fi
  done
  return 1
}

# 1. Paths into the shared folder.
while IFS= read -r hit; do
  file=${hit%%:*}
  rest=${hit#*:}
  line=${rest%%:*}
  text=${rest#*:}
  # Leave out document citations (check 2 reports those).
  stripped=$(sed -E -e "s#${shared_re}/${doc_re}##g" <<<"$text")
  if grep -qE "$shared_re" <<<"$stripped"; then
    text=$(sed -E 's/^[[:space:]]+//' <<<"$text")
    [[ ${#text} -gt 120 ]] && text="${text:0:117}..."
    report "$file:$line: points into the shared folder beside the checkout: $text"
  fi
done < <(printf '%s\0' "${files[@]}" | xargs -0 grep -nIHE "$shared_re" -- 2>/dev/null || true)

# 2. Citations of a design, papers or style document that is not in the repository.
while IFS= read -r hit; do
  file=${hit%%:*}
  rest=${hit#*:}
  line=${rest%%:*}
  cited=${rest#*:}
  if ! resolves "$file" "$cited"; then
    report "$file:$line: cites $cited, which is not in the repository (the project's documents are in docs/)"
  fi
done < <(printf '%s\0' "${files[@]}" | xargs -0 grep -noIHE "$doc_re" -- 2>/dev/null || true)

if [[ $failures -gt 0 ]]; then
  echo "check_stands_alone.sh: $failures line(s) cite something outside the repository; cite docs/ instead (docs/README.md lists it)" >&2
  exit 1
fi
echo "check_stands_alone.sh: ${#files[@]} files, no citation outside the repository"
