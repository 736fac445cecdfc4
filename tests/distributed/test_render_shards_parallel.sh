#!/usr/bin/env bash
# scripts/render-shards-parallel (GNU parallel): a 200-shot scene over 4
# jobs gives every picture, byte-identical to one process's; the jobs
# stopped mid-run (SIGTERM to the process group) leave the set
# short, and the script run again with --skip-existing completes it without
# rendering again the pictures that were there.
#   test_render_shards_parallel.sh SHADELAB SOURCE_DIR MESH
# Exits 77 (skipped) when GNU parallel is not installed.
set -euo pipefail
export SHADELAB=$1
source_dir=$2
mesh=$3
here=$(dirname "$0")
command -v parallel >/dev/null || {
  echo "SKIP: GNU parallel is missing (scripts/setup installs parallel)"
  exit 77
}
source "$here/shards_common.sh"

work=$(mktemp -d)
export PARALLEL_HOME=$work/parallel-home # parallel's own files, not in $HOME
group=""
cleanup() {
  [[ -z $group ]] || kill -KILL -- "-$group" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

write_scene "$work" "$mesh"
render_reference "$work"
script=$source_dir/scripts/render-shards-parallel

mkdir "$work/run"
(cd "$work/run" && "$script" $shards "../the scene.json") || fail "render-shards-parallel failed"
check_complete "$work/run" "$work/reference"

# Stopped as a shutdown stops it: SIGTERM to the script, parallel and every
# shadelab, once the first pictures are there. (Not SIGINT: a background
# job of a script starts with SIGINT ignored.)
rm -rf "$work/run/out"
(cd "$work/run" && exec setsid "$script" $shards "../the scene.json") &
group=$!
started() {
  [[ $(ls "$work/run/out" 2>/dev/null | wc -l) -ge $shards ]]
}
for ((i = 0; i < 1200; i++)); do
  started && break
  sleep 0.05
done
started || fail "the jobs wrote nothing"
kill -TERM -- "-$group"
status=0
wait "$group" || status=$?
# The script is gone; parallel and the shadelab processes finish their
# pictures before they go.
for ((i = 0; i < 600; i++)); do
  kill -0 -- "-$group" 2>/dev/null || break
  sleep 0.05
done
! kill -0 -- "-$group" 2>/dev/null || fail "the jobs did not stop within 30 s of SIGTERM"
group=""
((status != 0)) || fail "the interrupted run exited 0"
written=$(find "$work/run/out" -name '*.png' | wc -l)
((written < shots)) || fail "the jobs finished ($written pictures) before the interrupt"
before=$(mtimes "$work/run")

(cd "$work/run" && "$script" $shards "../the scene.json" --skip-existing) ||
  fail "the rerun with --skip-existing failed"
check_complete "$work/run" "$work/reference"
unchanged=$(comm -12 <(echo "$before") <(mtimes "$work/run") | wc -l)
((unchanged == $(wc -l <<<"$before"))) || fail "the rerun wrote again $(($(wc -l <<<"$before") - unchanged)) pictures that existed"
echo "OK: $shots shots over $shards GNU parallel jobs ($written before the interrupt), completed by a rerun"
