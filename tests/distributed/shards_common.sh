# shellcheck shell=bash
# What the distributed tests share, sourced by them: a 200-shot scene, its
# pictures rendered by one process, and the checks on a sharded run's.
#
# The work folder holds "the scene.json" (a space in its name, as a user's
# may have) and a folder per run; each run renders from its own folder with
# the same relative scene path, so that the pictures' metadata (which names
# the command line) is the same and their bytes can be compared.

shots=200
shards=4

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# write_scene DIR MESH: 200 shots of MESH at 64x48 turning about it, the
# three shading rules in turn, into out/{index}.png.
write_scene() {
  local i separator=""
  {
    printf '{ "mesh": "%s", "output": "out/{index}.png", "size": [64, 48], "shots": [' "$2"
    for ((i = 0; i < shots; i++)); do
      printf '%s{ "camera": { "azimuth": %d }, "shading": "%s" }' "$separator" \
        $((i * 360 / shots)) "$(echo flat gouraud phong | cut -d' ' -f$((i % 3 + 1)))"
      separator=,
    done
    printf '] }\n'
  } >"$1/the scene.json"
}

# render_reference DIR: the scene rendered by one process into
# DIR/reference/out, each picture whole: a PNG to its last chunk (IEND).
render_reference() {
  local file
  mkdir -p "$1/reference"
  (cd "$1/reference" && "$SHADELAB" render --scene "../the scene.json") ||
    fail "the single-process run failed"
  for file in "$1"/reference/out/*; do
    [[ $(tail -c 8 "$file" | od -An -tx1 | tr -d ' \n') == 49454e44ae426082 ]] ||
      fail "$file does not end with a PNG's IEND chunk"
  done
}

# The output names of shard I of N (shot k goes to shard k mod N).
shard_files() {
  local k
  for ((k = $1; k < shots; k += $2)); do
    printf 'out/%03d.png\n' "$k"
  done
}

# check_complete RUN_DIR REFERENCE_DIR: every picture there, whole and
# byte-identical to the single process's, and nothing else (no temporaries).
check_complete() {
  local run=$1 reference=$2 count
  count=$(find "$run/out" -type f | wc -l)
  ((count == shots)) || fail "$run/out holds $count files, not $shots: $(ls "$run/out" | grep -v '^[0-9]*\.png$' | head -3)"
  diff -r "$reference/out" "$run/out" >/dev/null || fail "$run/out differs from the single process's pictures"
}

# mtimes RUN_DIR: each picture's name and modification time, to the nanosecond.
mtimes() {
  (cd "$1" && find out -name '*.png' -printf '%p %T@\n' | sort)
}
