#!/usr/bin/env bash
# The image writer names OpenImageIO's heaviest dependencies first on its
# link line (cmake/heavy_dependencies_first.sh). Every symbol reference of
# every library it loads must still bind where it binds with OpenImageIO's
# own order (the same writer, linked plainly), unless both definitions are
# weak or unique (copies of inline and template code, the same code by the
# one-definition rule). The loader reports each binding (LD_DEBUG=bindings).
#   test_writer_bindings.sh WRITER PLAIN_WRITER
set -euo pipefail
writer=$1
plain=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# "FROM SYMBOL@VERSION TO" for each binding made by a library (the two
# executables' own references are not compared: they are two files; a
# definition in the executable, a copy relocation, reads EXECUTABLE).
bindings() {
  LD_DEBUG=bindings LD_DEBUG_OUTPUT="$dir/$2" "$1" </dev/null
  # The loader may write two reports on one line: split before each pid.
  cat "$dir/$2".* | sed -E 's/[[:space:]]+[0-9]+:[[:space:]]+binding file /\nbinding file /g' |
    sed -nE "s/^.*binding file ([^ ]+) \[[0-9]+\] to ([^ ]+) \[[0-9]+\]: normal symbol \`([^']+)'( \[([^]]+)\])?.*/\1 \3@\5 \2/p" |
    awk -v exe="$1" '{ if ($3 == exe) $3 = "EXECUTABLE" } $1 != exe' | sort -u
}
bindings "$writer" ordered >"$dir/ordered"
bindings "$plain" plain >"$dir/plain"
[[ -s $dir/plain ]] || { echo "no bindings reported for $plain"; exit 1; }

# Each reference whose definition moved, with both definers: the bindings
# of one run only, paired by reference. (A reference may bind twice, to two
# definitions: the sanitizer runtime's own lookups of what it intercepts.)
join -j1 <(comm -23 "$dir/plain" "$dir/ordered" | awk '{ print $1 "|" $2, $3 }' | sort) \
  <(comm -13 "$dir/plain" "$dir/ordered" | awk '{ print $1 "|" $2, $3 }' | sort) |
  awk '{ split($1, k, "|"); sub(/@.*/, "", k[2]); print k[2], $2, $3 }' >"$dir/moved"

# Their types in each definer (nm -D: W/V weak, u unique, else strong).
awk '{ print $2; print $3 }' "$dir/moved" | sort -u | grep -vx EXECUTABLE | while read -r lib; do
  nm -D --defined-only "$lib" | awk -v lib="$lib" 'NF == 3 { sub(/@.*/, "", $3); print lib, $3, $2 }'
done >"$dir/types"
awk 'NR == FNR { type[$1 " " $2] = $3; next }
  { for (i = 2; i <= 3; i++) {
      t = type[$i " " $1]
      if (t !~ /^[WVu]$/) {
        print "FAIL: " $1 " binds to " $3 " instead of " $2 ", and " $i " defines it strongly (" t ")"
        failed = 1
      }
    } }
  END { exit failed }' "$dir/types" "$dir/moved" || status=1
echo "$(wc -l <"$dir/plain") bindings compared, $(wc -l <"$dir/moved") moved to another copy"
exit "${status:-0}"
