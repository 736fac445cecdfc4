#!/usr/bin/env bash
# installed_render.sh INSTALLED REFERENCE MESH WORKDIR: renders MESH with the
# installed program INSTALLED and with the build tree's REFERENCE; the two
# PNG files must be identical bytes (same code, same llvmpipe, same encoder),
# which also shows the installed program found its installed helpers. Both
# run as `shadelab` from PATH into out.png of a folder of their own, so that
# the command line the picture's metadata records is the same.
set -euo pipefail
installed=$1 reference=$2 mesh=$3 work=$4
rm -rf "$work" && mkdir -p "$work/installed" "$work/reference"
render() { # render PROGRAM FOLDER
  (cd "$2" && env -u LD_LIBRARY_PATH PATH="$(dirname "$1"):$PATH" \
    shadelab render "$mesh" -o out.png --size 64x64 --shading phong --material gold --quiet)
}
render "$installed" "$work/installed"
render "$reference" "$work/reference"
cmp "$work/installed/out.png" "$work/reference/out.png"
echo "the installed program rendered $mesh as the build tree's does"
