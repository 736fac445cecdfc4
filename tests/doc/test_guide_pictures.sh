#!/usr/bin/env bash
# scripts/guide-pictures remakes each picture it names into a folder of its
# own, at the size of the one the guide shows (data/readme/), and names at
# least the three it makes without ../shared/data.
#   test_guide_pictures.sh SCRIPT SHADELAB MESHES COMMITTED_DIR
set -euo pipefail
script=$1 shadelab=$2 meshes=$3 committed=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
bash "$script" --out "$out/pictures" --program "$shadelab" --meshes "$meshes" >"$out/log"
size() { # PNG: its IHDR's width and height
  python3 -c 'import struct, sys; print(*struct.unpack(">II", open(sys.argv[1], "rb").read(24)[16:24]))' "$1"
}
named=$(sed -n 's/^guide-pictures: \([a-z-]*\.png\)$/\1/p' "$out/log")
for name in $named; do
  [ -f "$out/pictures/$name" ] || { echo "$name: named but not made" >&2; exit 1; }
  made=$(size "$out/pictures/$name") shown=$(size "$committed/$name")
  [ "$made" == "$shown" ] || { echo "$name: made $made, the guide's is $shown" >&2; exit 1; }
done
count=$(wc -w <<<"$named")
((count >= 3)) || { echo "only $count pictures named:" >&2; cat "$out/log" >&2; exit 1; }
echo "$count pictures made at their guide sizes"
