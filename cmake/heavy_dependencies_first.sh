#!/usr/bin/env bash
# Prints, one per line, the sonames an executable linking LIBRARY should
# name ahead of it on its link line, so that its start-up spends less time
# looking up symbols, while every strong symbol binds where it did:
#
#   heavy_dependencies_first.sh LIBRARY
#
# The dynamic loader resolves each symbol a library refers to by searching
# the loaded libraries in breadth-first order from the executable. Debian's
# OpenImageIO loads 261 of them, and a library far down that order whose
# tens of thousands of references point into itself (GDAL at place 121,
# 48,000) makes each lookup pass a hundred libraries first. Named first on
# the link line, such a library is found at once.
#
# Printed, in this order:
#   1. the C and C++ runtime, as the compiler driver links it (unchanged
#      among themselves, ahead of everything as they are ahead of every
#      dependency of LIBRARY);
#   2. every library that defines a strong symbol another one defines too
#      (strlcat in libbsd and libnetcdf, lsame_ in BLAS and LAPACK, ...),
#      in their breadth-first order from LIBRARY, so that the first of each
#      such pair stays first;
#   3. the heavy ones: each library whose symbol references times its place
#      in the order make up at least 1% of the sum over all of them.
# Only weak definitions (inline and template code that many libraries carry
# copies of) may then bind to another copy: tests/linkage checks that.
set -euo pipefail
library=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# LIBRARY's dependencies in the loader's order.
ldd "$library" | awk '$3 ~ /^\// { print $3 }' >"$dir/closure"
touch "$dir/strong" "$dir/cost"

runtime=(libstdc++.so.6 libm.so.6 libgcc_s.so.1 libc.so.6)
printf '%s\n' "${runtime[@]}"

# One pass of readelf over them all: from each library's dynamic section
# the number of its relocations that name a symbol (all, less the relative
# ones, which need no lookup), from its dynamic symbols the strong
# definitions (global, neither undefined nor absolute as version names are),
# less the linker's own markers, which every library has and nothing binds to.
# (Given several files, readelf heads each one's part with "File: PATH".)
# shellcheck disable=SC2046 # one path per word
readelf -W --dynamic --dyn-syms $(cat "$dir/closure") 2>/dev/null |
  awk -v strong="$dir/strong" -v cost="$dir/cost" '
  function flush() {
    if (lib != "") print (rela / entry - relative + plt / entry) * place, lib >cost
  }
  BEGIN { place = 1 }
  /^File: / {
    flush()
    lib = $2; sub(/.*\//, "", lib); place++; rela = plt = relative = 0; entry = 24
  }
  $2 == "(RELASZ)" { rela = $3 }
  $2 == "(PLTRELSZ)" { plt = $3 }
  $2 == "(RELAENT)" { entry = $3 }
  $2 == "(RELACOUNT)" { relative = $3 }
  $1 ~ /^[0-9]+:$/ && NF >= 8 && $5 == "GLOBAL" && $7 != "UND" && $7 != "ABS" {
    name = $8; sub(/@.*/, "", name)
    if (name !~ /^(_edata|_end|__bss_start)$/) print name, lib >strong
  }
  END { flush() }'

sort -u "$dir/strong" | awk '{ n[$1]++; libs[$1] = libs[$1] " " $2 }
  END { for (s in n) if (n[s] > 1) print libs[s] }' | tr ' ' '\n' | sed '/^$/d' |
  sort -u >"$dir/shared"
xargs -n1 basename <"$dir/closure" | grep -xF -f "$dir/shared" |
  grep -vxF -f <(printf '%s\n' "${runtime[@]}") || true

awk '{ total += $1; cost[NR] = $1; name[NR] = $2 }
  END { for (i = 1; i <= NR; i++) if (cost[i] * 100 >= total) print cost[i], name[i] }' \
  "$dir/cost" | sort -rn | awk '{ print $2 }' |
  grep -vxF -f <(cat "$dir/shared" <(printf '%s\n' "${runtime[@]}")) || true
