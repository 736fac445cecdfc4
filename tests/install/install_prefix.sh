#!/usr/bin/env bash
# install_prefix.sh BUILD PREFIX PYTHON_DIR: installs BUILD into a fresh
# PREFIX and checks the layout (GNUInstallDirs, the helpers in
# libexec/shadelab) and that no installed binary points into the build tree.
set -euo pipefail
build=$1 prefix=$2 python_dir=$3
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
libdir=$(find "$prefix" -name 'libshadelab_filters.so' -printf '%h\n')
expected=(
  bin/shadelab
  libexec/shadelab/shadelab-image-writer libexec/shadelab/shadelab-view
  "${libdir#"$prefix"/}"/libshadelab_illumination.so
  include/shadelab/vtkShadelabMeshNormals.h include/shadelab/shadelabIllumination.h
  "${libdir#"$prefix"/}"/cmake/shadelab/shadelabConfig.cmake
  share/shadelab/materials.json share/shadelab/scene.schema.json share/shadelab/teapot.obj
  share/shadelab/scenes/teapot-lights.json
)
[[ -n $python_dir ]] && expected+=("$python_dir/shadelab/__init__.py")
for path in "${expected[@]}"; do
  [[ -e $prefix/$path ]] || { echo "missing from the install: $path"; exit 1; }
done
[[ ! -e $prefix/bin/shadelab-image-writer ]] || { echo "a helper in bin/"; exit 1; }
# The headers: the public classes' (vtk*.h, the modules' export headers) and
# what they include, nothing else; and everything they include is there.
include=$prefix/include/shadelab
needed=$(cd "$include" && ls vtk*.h *Module.h)
queue=$needed
while [[ -n $queue ]]; do
  next=""
  for header in $queue; do
    [[ -e $include/$header ]] || { echo "installed headers include $header, not installed"; exit 1; }
    for inner in $(sed -n 's/^#include "\(.*\)".*/\1/p' "$include/$header"); do
      grep -qx "$inner" <<<"$needed" || { needed+=$'\n'"$inner"; next+=" $inner"; }
    done
  done
  queue=$next
done
extra=$(cd "$include" && ls | grep -vxF -f <(echo "$needed") || true)
[[ -z $extra ]] || { echo "installed headers no public class includes:" $extra; exit 1; }
for binary in "$prefix"/bin/* "$prefix"/libexec/shadelab/* "$libdir"/*.so; do
  if readelf -d "$binary" | grep -F "$build"; then
    echo "$binary points into the build tree"
    exit 1
  fi
done
echo "installed into $prefix"
