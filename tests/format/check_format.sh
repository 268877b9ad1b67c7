#!/bin/bash
# The format check (issue 17): every C++ file of the tree is as clang-format (Debian's
# clang-format-14, .clang-format: Google style, 100 columns) writes it, and every header uses
# `#pragma once`. Prints the files that differ and how to fix them.
# usage: check_format.sh SOURCE_DIR
set -u
root=$1
format=$(command -v clang-format-14 || command -v clang-format) || {
  echo "FAIL: clang-format-14 not found (deploy/install-deps.sh installs it)"
  exit 1
}
cd "$root" || exit 1
mapfile -t files < <(find services clients tests -name node_modules -prune -o \( -name '*.cc' -o -name '*.h' \) -print | sort)
# One clang-format per batch of files, not per file: it reports each unformatted file as
# "FILE:LINE:COL: error" and carries on, and a process per file took minutes on a busy machine.
report=$(printf '%s\0' "${files[@]}" | xargs -0 -n 200 "$format" --dry-run --Werror 2>&1)
status=$?
mapfile -t bad < <(grep -oE '^[^: ]+\.(cc|h):[0-9]+:[0-9]+: error' <<<"$report" | cut -d: -f1 | sort -u)
if ((status != 0 && ${#bad[@]} == 0)); then
  echo "FAIL: $format failed without naming a file:"
  head -20 <<<"$report"
  exit 1
fi
guards=()
for f in "${files[@]}"; do
  [[ $f == *.h ]] && ! grep -q '^#pragma once' "$f" && guards+=("$f")
done
if ((${#bad[@]} + ${#guards[@]} > 0)); then
  ((${#bad[@]})) && printf 'not formatted: %s\n' "${bad[@]}" && echo "fix: $format -i FILE..."
  ((${#guards[@]})) && printf 'header without #pragma once: %s\n' "${guards[@]}"
  exit 1
fi
echo "${#files[@]} files formatted, every header with #pragma once"
