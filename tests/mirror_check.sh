#!/usr/bin/env bash
# Tests mirror headers: every header under src/ and export/ that holds logic (it has a .cpp
# beside it) has tests/<name>_test.cpp. The command line is tested by running the built
# program (tests/cli_test.sh) and the Python module by importing it (tests/python), so src/cli/
# and src/python/ are not listed.
set -u
root=${1:?usage: mirror_check.sh SOURCE_DIR}
cd "$root" || exit 2
missing=0
for header in $(find src export -name '*.h' -not -path 'src/cli/*' -not -path 'src/python/*' | sort); do
  base=${header%.h}
  name=$(basename "$base")
  [ -f "$base.cpp" ] || compgen -G "${base}_*.cpp" > /dev/null || continue  # no logic
  if [ ! -f "tests/${name}_test.cpp" ]; then
    echo "no tests/${name}_test.cpp for $header"
    missing=$((missing + 1))
  fi
done
echo "$missing headers with logic have no test file of their own"
[ "$missing" -eq 0 ]
