#!/usr/bin/env bash
# Fails, naming each file and line, where a C++ source or header of the repository is not laid out
# as .clang-format says. Fix with: clang-format -i FILE (scripts/setup.sh installs clang-format).
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! command -v clang-format >/dev/null; then
  echo "clang-format is not installed: run scripts/setup.sh" >&2
  exit 1
fi
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else
  mapfile -t files < <(find engine orchestrator tests -name '*.cpp' -o -name '*.hpp')
fi
clang-format --dry-run --Werror "${files[@]}"
echo "${#files[@]} files laid out as .clang-format says"
