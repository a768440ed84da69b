#!/usr/bin/env bash
# Fails when a C, C++ or header file of the project is not clang-format clean.
set -euo pipefail
root=${1:?usage: check_format.sh REPO_ROOT}
cd "$root"
mapfile -t files < <(find src tests bench examples -type f \
  \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.c' \) 2>/dev/null | sort)
clang-format --dry-run -Werror "${files[@]}"
echo "clang-format: ${#files[@]} files clean"
