#!/usr/bin/env bash
# Every C++ file of the project as .clang-format lays it out: prints the files that differ
# (clang-format -i on them fixes it) and fails if there are any.
set -u
root=${1:?usage: format_check.sh SOURCE_DIR}
cd "$root" || exit 2
command -v clang-format > /dev/null || { echo "clang-format is not installed (setup.sh installs it)"; exit 1; }
report=$(find src export tests examples -path '*/node_modules' -prune -o \
              \( -name '*.cpp' -o -name '*.h' \) -type f -print0 |
         xargs -0 clang-format --style=file --dry-run 2>&1 | grep -E '^[^ ]+:[0-9]+:[0-9]+: ' |
         cut -d: -f1 | sort -u)
if [ -n "$report" ]; then
  printf 'differs from .clang-format: %s\n' $report
  echo "$(echo "$report" | wc -l) files differ from .clang-format"
  exit 1
fi
echo "every C++ file is laid out as .clang-format says"
