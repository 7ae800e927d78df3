#!/usr/bin/env bash
# The C++ sources follow the repository's .clang-format (Debian 12's clang-format 14, which
# install_deps.sh installs): lists every file that differs and how to fix it. One
# clang-format process checks many files (--dry-run -Werror): a process per file took a
# minute of CI's time, this takes seconds.
set -euo pipefail
root="$1"
cd "$root"
command -v clang-format >/dev/null || {
  echo "format_check: clang-format not found; ./install_deps.sh installs it" >&2
  exit 1
}
mapfile -t files < <(find src include apps tests scaling \
  \( -name '*.cpp' -o -name '*.hpp' -o -name '*.cpp.in' \) -type f | sort)
report=$(printf '%s\0' "${files[@]}" |
  xargs -0 clang-format --style=file --dry-run -Werror 2>&1) && status=0 || status=$?
# Each difference is reported as "FILE:LINE:COL: error: code should be clang-formatted".
mapfile -t bad < <(printf '%s\n' "$report" |
  sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u)
if [ ${#bad[@]} -gt 0 ]; then
  printf 'format_check: %s is not formatted\n' "${bad[@]}" >&2
  echo "format_check: run: clang-format -i --style=file ${bad[*]}" >&2
  exit 1
fi
if [ "$status" -ne 0 ]; then
  # clang-format failed without naming a difference (a file it cannot read or parse).
  printf '%s\n' "$report" >&2
  echo "format_check: clang-format exited with $status" >&2
  exit 1
fi
echo "format_check: ${#files[@]} files formatted"
