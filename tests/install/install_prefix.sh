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
  share/shadelab/materials.json share/shadelab/scene.schema.json share/shadelab/spot.obj
  share/shadelab/scenes/spot-lights.json
)
[[ -n $python_dir ]] && expected+=("$python_dir/shadelab/__init__.py")
for path in "${expected[@]}"; do
  [[ -e $prefix/$path ]] || { echo "missing from the install: $path"; exit 1; }
done
[[ ! -e $prefix/bin/shadelab-image-writer ]] || { echo "a helper in bin/"; exit 1; }
for binary in "$prefix"/bin/* "$prefix"/libexec/shadelab/* "$libdir"/*.so; do
  if readelf -d "$binary" | grep -F "$build"; then
    echo "$binary points into the build tree"
    exit 1
  fi
done
echo "installed into $prefix"
