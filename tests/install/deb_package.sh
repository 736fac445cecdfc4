#!/usr/bin/env bash
# deb_package.sh BUILD WORKDIR REFERENCE MESH PACKAGE...: makes the .deb with
# cpack, checks that its Depends name each PACKAGE (the libraries' packages
# from dpkg-shlibdeps, the Python module's), unpacks it into a scratch root
# and renders from there.
set -euo pipefail
build=$1 work=$2 reference=$3 mesh=$4
shift 4
here=$(dirname "$0")
rm -rf "$work" && mkdir -p "$work"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" ||
  { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for package in "$@"; do
  grep -qE "(^|, )${package}[ ,(]|(^|, )${package}\$" <<<"$depends" || { echo "Depends lacks $package"; exit 1; }
done
dpkg-deb -x "$deb" "$work/root"
"$here/installed_render.sh" "$work/root/usr/bin/shadelab" "$reference" "$mesh" "$work/render"
