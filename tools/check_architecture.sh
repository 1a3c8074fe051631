#!/usr/bin/env bash
# Holds the library to doc/architecture.md's two layout rules: every header in libvoxelfair/, and
# every .cpp without a header of its own name, is named in the doc's file index (so a reader
# finds each idea's file from the stage it belongs to), and no file in libvoxelfair/ is over 500
# lines. Prints what breaks a rule and exits 1; exit 0 when both hold.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
doc=$here/doc/architecture.md
status=0
cd "$here"
while IFS= read -r file; do
  case $file in
    *.cpp) [ -f "${file%.cpp}.h" ] && continue ;;
  esac
  name=$(basename "$file")
  if ! grep -q "\`$name\`" "$doc"; then
    echo "doc/architecture.md does not name $file"
    status=1
  fi
done < <(find libvoxelfair -name '*.h' -o -name '*.cpp' | sort)
while IFS= read -r line; do
  echo "over 500 lines: $line"
  status=1
done < <(find libvoxelfair -name '*.h' -o -name '*.cpp' | xargs wc -l | awk '$2 != "total" && $1 > 500 {print $2 " (" $1 ")"}')
[ $status -eq 0 ] && echo "architecture: every library file named in doc/architecture.md, none over 500 lines"
exit $status
