#!/usr/bin/env bash
# The C++ sources follow the repository's .clang-format (Debian 12's clang-format 14, which
# install_deps.sh installs): lists every file that differs and how to fix it.
set -euo pipefail
root="$1"
cd "$root"
command -v clang-format >/dev/null || {
  echo "format_check: clang-format not found; ./install_deps.sh installs it" >&2
  exit 1
}
mapfile -t files < <(find src include apps tests scaling \
  \( -name '*.cpp' -o -name '*.hpp' -o -name '*.cpp.in' \) -type f | sort)
bad=()
for f in "${files[@]}"; do
  clang-format --style=file "$f" | cmp -s - "$f" || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  printf 'format_check: %s is not formatted\n' "${bad[@]}" >&2
  echo "format_check: run: clang-format -i --style=file ${bad[*]}" >&2
  exit 1
fi
echo "format_check: ${#files[@]} files formatted"
