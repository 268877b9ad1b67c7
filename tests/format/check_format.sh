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
bad=()
for f in "${files[@]}"; do
  "$format" --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
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
