#!/usr/bin/env bash
# The bash completion (doc/shadelab-completion.bash) run as bash runs it:
# COMP_WORDS and COMP_CWORD set, _shadelab called, COMPREPLY checked: the
# commands, each command's options, the choices of an option's value, and
# file names for meshes, outputs and folders.
#   test_completion.sh SHADELAB COMPLETION_SCRIPT
set -uo pipefail
shadelab=$(realpath "$1")
script=$(realpath "$2")
helpers=/usr/share/bash-completion/bash_completion
[[ -r $helpers ]] || { echo "FAIL: $helpers is missing (apt-get install bash-completion)" >&2; exit 1; }
source "$(dirname "$0")/help_text.sh"
export LC_ALL=C # the order sort gives
# The completion runs `shadelab` as typed: the one under test first on PATH.
PATH=$(dirname "$shadelab"):$PATH
source "$helpers"
source "$script"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mkdir folder
touch bunny.obj teapot.ply scene.json

failed=0
# complete WORD... : the sorted candidates for the last word of the line.
complete_line() {
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMP_LINE="$*"
  COMP_POINT=${#COMP_LINE}
  COMPREPLY=()
  _shadelab
  printf '%s\n' "${COMPREPLY[@]}" | sort | xargs
}
# expect "CANDIDATES" WORD...
expect() {
  local want=$1 got
  shift
  got=$(complete_line "$@")
  [[ $got == "$want" ]] || {
    echo "FAIL: '$*': got '$got', want '$want'" >&2
    failed=1
  }
}

expect "--help --version advise bench check-shader compare normals probe profile render view" shadelab ""
expect "render" shadelab re
expect "--shading --shadow-map-size --shadows --shard" shadelab render --sh
expect "--modes" shadelab compare --mo
expect "auto compute file" shadelab render --normals ""
expect "flat gouraud none phong raytrace" shadelab render --shading ""
expect "gouraud" shadelab render --shading=g
expect "flat gouraud none phong" shadelab view --interactive-shading ""
expect "blinn phong" shadelab probe -q --reflection ""
expect "sphere tight" shadelab compare --fit ""
expect "+X +Y +Z -X -Y -Z" shadelab render --up ""
expect "environment transparent" shadelab render --background ""
expect "angle area loop max uniform" shadelab normals bunny.obj --weighting ""
expect "" shadelab render --size ""
expect "" shadelab render --ns ""
expect "bunny.obj folder scene.json teapot.ply" shadelab render ""
expect "bunny.obj" shadelab render --edges bu
expect "teapot.ply" shadelab render bunny.obj -o te
expect "scene.json" shadelab render --scene sc
expect "folder" shadelab bench --out ""
expect "bunny.obj folder scene.json teapot.ply" shadelab advise --measurements ""
# Every option of every command, as its --help lists it.
for command in $(help_commands shadelab); do
  expect "$(help_options shadelab "$command" | sort | xargs)" shadelab "$command" -
done
exit $failed
