// Bad input (doc/design.md, "Command line"): a one-line error on stderr naming
// the input and the problem, a non-zero exit, no crash and no output file.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

using namespace shadelab_test;

namespace
{
struct BadCase
{
  const char* Name;
  // Writes the input into dir and returns the command's arguments after
  // "render"; "OUT" stands for the output path.
  std::vector<std::string> (*Make)(const TempDir& dir);
  int ExitCode;
  std::vector<const char*> Words; // each must appear in the error line
};

void MakeFifo(const std::filesystem::path& path)
{
  if (mkfifo(path.c_str(), 0600) != 0)
  {
    throw std::runtime_error("mkfifo " + path.string() + " failed");
  }
}

std::string Binary(const void* data, size_t size)
{
  return std::string(static_cast<const char*>(data), size);
}

std::vector<std::string> WithMesh(const TempDir& dir, const std::string& name,
  const std::string& content, std::vector<std::string> extra = {})
{
  WriteText(dir / name, content);
  std::vector<std::string> args = { (dir / name).string(), "-o", "OUT" };
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

const std::string Tetrahedron =
  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

// Two triangles with normals and texture coordinates (OFF's ST and N).
const std::string TexturedQuad = "STNOFF\n4 2 0\n0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n"
                                 "1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 1\n3 0 1 2\n3 0 2 3\n";

// A square of two triangles with texture coordinates, of material t in t.mtl.
const std::string TexturedObj = "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl t\n"
                                "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";

std::string BinaryPlyHeader(const std::string& counts)
{
  return "ply\nformat binary_little_endian 1.0\n" + counts +
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
}

const BadCase Cases[] = {
  { "MissingFile",
    [](const TempDir& d) {
      return std::vector<std::string>{ (d / "nope.obj").string(), "-o", "OUT" };
    },
    1, { "nope.obj", "No such file" } },
  { "UnknownMeshFormat", [](const TempDir& d) { return WithMesh(d, "mesh.xyz", "1 2 3\n"); }, 1,
    { "mesh.xyz", ".xyz" } },
  { "EmptyObj", [](const TempDir& d) { return WithMesh(d, "empty.obj", ""); }, 1,
    { "empty.obj", "triangles" } },
  { "ObjOnlyVertices",
    [](const TempDir& d) { return WithMesh(d, "points.obj", "v 0 0 0\nv 1 0 0\n"); }, 1,
    { "points.obj", "triangles" } },
  { "ObjNaNCoordinate",
    [](const TempDir& d)
    { return WithMesh(d, "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"); },
    1, { "nan.obj" } },
  { "ObjIndexOutOfRange",
    [](const TempDir& d)
    { return WithMesh(d, "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"); },
    1, { "range.obj", "9" } },
  { "ObjMalformedMaterialLibrary",
    [](const TempDir& d)
    {
      WriteText(d / "bad.mtl", "newmtl a\nKd 1 nope 0\n");
      return WithMesh(d, "lib.obj", "mtllib bad.mtl\nusemtl a\n" + Tetrahedron);
    },
    1, { "lib.obj", "material library 'bad.mtl' line 2: malformed Kd 'nope'" } },
  { "ObjMalformedTextureMap",
    [](const TempDir& d)
    {
      WriteText(d / "maps.mtl", "newmtl a\nmap_Kd -clamp sometimes wood.png\n");
      return WithMesh(d, "maps.obj", "mtllib maps.mtl\nusemtl a\n" + Tetrahedron);
    },
    1, { "maps.obj", "material library 'maps.mtl' line 2: malformed map_Kd -clamp 'sometimes'" } },
  { "ObjTextureCoordinateOutOfRange",
    [](const TempDir& d)
    { return WithMesh(d, "vt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n"); },
    1, { "vt.obj", "line 5", "texture coordinate 2" } },
  { "ObjZeroIndex",
    [](const TempDir& d)
    { return WithMesh(d, "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"); },
    1, { "zero.obj" } },
  { "ObjMalformedNumber",
    [](const TempDir& d)
    { return WithMesh(d, "garbage.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n"); },
    1, { "garbage.obj", "line 2" } },
  { "PlyTruncated",
    [](const TempDir& d)
    {
      std::string ply = BinaryPlyHeader("element vertex 3\n");
      const float v[6] = { 0, 0, 0, 1, 0, 0 }; // two of three vertices
      return WithMesh(d, "short.ply", ply + Binary(v, sizeof v));
    },
    1, { "short.ply" } },
  { "PlyLyingHeader",
    [](const TempDir& d)
    { return WithMesh(d, "liar.ply", BinaryPlyHeader("element vertex 4000000000\n")); },
    1, { "liar.ply", "4000000000" } },
  { "StlTruncated",
    [](const TempDir& d)
    {
      std::string stl(80, ' ');
      const uint32_t count = 1000000;
      stl += Binary(&count, 4) + std::string(100, '\0');
      return WithMesh(d, "short.stl", stl);
    },
    1, { "short.stl" } },
  { "OffHeaderLies",
    [](const TempDir& d)
    { return WithMesh(d, "liar.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"); },
    1, { "liar.off", "truncated", "2 faces" } },
  { "OffIndexOutOfRange",
    [](const TempDir& d)
    { return WithMesh(d, "range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"); },
    1, { "range.off", "line 6", "vertex 3" } },
  { "OffNaN",
    [](const TempDir& d)
    { return WithMesh(d, "nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"); },
    1, { "nan.off", "NaN" } },
  { "GltfMalformedJson",
    [](const TempDir& d) { return WithMesh(d, "broken.gltf", "{\"asset\": {\"version\": "); }, 1,
    { "broken.gltf", "not JSON" } },
  { "GltfMissingBin",
    [](const TempDir& d)
    {
      return WithMesh(d, "lonely.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"gone.bin\", "
        "\"byteLength\": 36}]}");
    },
    1, { "lonely.gltf", "gone.bin", "No such file" } },
  { "GltfAccessorBeyondItsView",
    [](const TempDir& d)
    {
      // 36 bytes: three float positions; the accessor says 30.
      const float xyz[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
      WriteText(d / "tri.bin", Binary(xyz, sizeof xyz));
      return WithMesh(d, "tri.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"tri.bin\", "
        "\"byteLength\": 36}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}], "
        "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 30, "
        "\"type\": \"VEC3\"}], \"meshes\": [{\"primitives\": [{\"attributes\": "
        "{\"POSITION\": 0}}]}]}");
    },
    1, { "tri.gltf", "accessor 0 needs 30 elements" } },
  { "GltfTextureImageOutOfRange",
    [](const TempDir& d)
    {
      const float xyz[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
      WriteText(d / "tri.bin", Binary(xyz, sizeof xyz));
      return WithMesh(d, "textured.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"tri.bin\", "
        "\"byteLength\": 36}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 36}], "
        "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, "
        "\"type\": \"VEC3\"}], \"meshes\": [{\"primitives\": [{\"attributes\": "
        "{\"POSITION\": 0}, \"material\": 0}]}], \"materials\": [{\"pbrMetallicRoughness\": "
        "{\"baseColorTexture\": {\"index\": 0}}}], \"textures\": [{\"source\": 2}]}");
    },
    1, { "textured.gltf", "texture 0 refers to images[2]" } },
  { "GlbTruncated",
    [](const TempDir& d)
    {
      const std::uint32_t header[5] = { 0x46546C67, 2, 4096, 64, 0x4E4F534A };
      return WithMesh(d, "cut.glb", Binary(header, sizeof header) + "{\"asset\"");
    },
    1, { "cut.glb", "truncated" } },
  { "UnknownImageFormat",
    [](const TempDir& d)
    {
      WriteText(d / "t.obj", Tetrahedron);
      return std::vector<std::string>{ (d / "t.obj").string(), "-o",
        (d / "out.notaformat").string() };
    },
    1, { "out.notaformat", "format" } },
  { "UnwritableFolder",
    [](const TempDir& d)
    {
      WriteText(d / "t.obj", Tetrahedron);
      return std::vector<std::string>{ (d / "t.obj").string(), "-o",
        (d / "no" / "such" / "dir.png").string() };
    },
    1, { "dir.png", "cannot write" } },
  { "FloatIntoJpeg",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--pixel-type", "float" });
    },
    1, { "OUT", "float" } },
  { "CameraAtFocalPoint",
    [](const TempDir& d)
    {
      return WithMesh(
        d, "t.obj", Tetrahedron, { "--camera-position", "1,1,1", "--camera-focal-point", "1,1,1" });
    },
    1, { "camera", "focal point" } },
  { "ViewUpAlongViewDirection",
    [](const TempDir& d)
    {
      return WithMesh(d, "t.obj", Tetrahedron,
        { "--camera-position", "0,5,0", "--camera-focal-point", "0,0,0", "--camera-view-up",
          "0,1,0" });
    },
    1, { "view-up", "parallel" } },
  { "FileNormalsMissing",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--normals", "file" });
    },
    1, { "t.obj", "normals" } },
  { "SizeZero",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--size", "0x10" });
    },
    2, { "--size", "0x10" } },
  { "SizeHuge",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--size", "100000x100000" });
    },
    2, { "--size" } },
  { "SizeGarbage",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--size", "big" });
    },
    2, { "--size", "big" } },
  { "ColourTwoNumbers",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--ka", "1,2" });
    },
    2, { "--ka", "1,2" } },
  { "ColourNegative",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--kd", "1,-2,0" });
    },
    2, { "--kd", "negative" } },
  { "ColourNaN",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--ambient", "nan,0,0" });
    },
    2, { "--ambient", "nan" } },
  { "UnknownLightKind",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--light", "laser:1,2,3" });
    },
    2, { "--light", "laser" } },
  { "SpotWithoutAngle",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--light", "spot:0,0,5:0,0,-1" });
    },
    2, { "--light", "spot" } },
  { "SpotAngleTooWide",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--light", "spot:0,0,5:0,0,-1:120" });
    },
    2, { "--light", "120" } },
  { "DirectionZero",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--light", "directional:0,0,0" });
    },
    2, { "--light", "zero" } },
  { "AttenuationAllZero",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--attenuation", "0,0,0" });
    },
    2, { "--attenuation", "all zero" } },
  { "AttenuationNegative",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--attenuation", "1,-0.5,0" });
    },
    2, { "--attenuation", "negative" } },
  { "AttenuationNotATriple",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--attenuation", "1,0" });
    },
    2, { "--attenuation", "C0,C1,C2" } },
  { "LightsOwnAttenuationNegative",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--light", "point:0,0,5@0,0,-1" });
    },
    2, { "--light", "negative" } },
  { "FogEndNotBeyondStart",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--fog", "linear:10,2" });
    },
    2, { "--fog", "not beyond" } },
  { "TranslucencyOutOfRange",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--translucency", "1.5" });
    },
    2, { "--translucency", "not in range" } },
  { "PeelsNegative",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--peels", "-1" });
    },
    2, { "--peels", "not in range" } },
  { "ShadowMapSizeZero",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--shadows", "--shadow-map-size", "0" });
    },
    2, { "--shadow-map-size", "not in range" } },
  // Within the option's range, over llvmpipe's 16384: found as the maps are made.
  { "ShadowMapSizeOverOpenGLsLimit",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--shadows", "--shadow-map-size", "20000" });
    },
    1, { "--shadow-map-size 20000", "limit of 16384" } },
  // Within OpenGL's limit, over llvmpipe's 1 GiB a texture (a 9000 cube
  // map is 1.8 GiB): OpenGL is out of memory for it.
  { "ShadowMapOutOfMemory",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--shadows", "--shadow-map-size", "9000" });
    },
    1, { "--shadow-map-size 9000", "no memory" } },
  { "ReflectionsNegative",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--shading", "raytrace", "--reflections", "-1" });
    },
    2, { "--reflections", "not in range" } },
  // The ray tracer traces the surface: edges and points are the raster's.
  { "RaytraceWireframe",
    [](const TempDir& d)
    {
      return WithMesh(
        d, "t.obj", Tetrahedron, { "--shading", "raytrace", "--representation", "wireframe" });
    },
    1, { "--representation wireframe", "traces the surface alone" } },
  { "RaytraceEdges",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--shading", "raytrace", "--edges" });
    },
    1, { "--edges", "traces the surface alone" } },
  { "LightsShadowsNotABoolean",
    [](const TempDir& d)
    {
      WriteText(d / "t.obj", Tetrahedron);
      WriteText(d / "s.json",
        R"({"mesh": "t.obj", "output": "out.png", "lights": [{"kind": "point", "position": [0, 0, 5], "shadows": 1}]})");
      return std::vector<std::string>{ "--scene", (d / "s.json").string() };
    },
    1, { "lights[0].shadows", "true or false" } },
  { "FogDensityNegative",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--fog", "exp2:-1" });
    },
    2, { "--fog", "negative" } },
  { "RepresentationUnknown",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--representation", "lines" });
    },
    2, { "--representation", "lines" } },
  { "LineWidthNotWhole",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--line-width", "1.5" });
    },
    2, { "--line-width", "1.5" } },
  { "PointSizeOutOfRange",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--point-size", "0" });
    },
    2, { "--point-size", "0" } },
  { "ViewAngleOutOfRange",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--view-angle", "200" });
    },
    2, { "--view-angle", "200" } },
  { "ParallelScaleZero",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--parallel-scale", "0" });
    },
    2, { "--parallel-scale" } },
  { "UnknownMaterial",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--material", "unobtainium" });
    },
    2, { "--material", "unobtainium" } },
  { "UnknownShading",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--shading", "wobbly" });
    },
    2, { "--shading", "wobbly" } },
  { "NegativeShininess",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--ns", "-1" });
    },
    2, { "--ns" } },
  { "UnknownOption",
    [](const TempDir& d) { return WithMesh(d, "t.obj", Tetrahedron, { "--frobnicate" }); }, 2,
    { "--frobnicate" } },
  // A binary STL whose header and size agree on 2^31 triangles: 107 GB, sparse
  // (no disk used), more than any test machine's memory. It must be refused
  // before anything is allocated, not meet the OOM killer.
  { "MeshTooLargeForMemory",
    [](const TempDir& d)
    {
      const std::uint32_t count = 1u << 31;
      WriteText(d / "huge.stl", std::string(80, 'x') + Binary(&count, sizeof count));
      std::filesystem::resize_file(d / "huge.stl", 84 + 50 * std::uintmax_t{ count });
      return std::vector<std::string>{ (d / "huge.stl").string(), "-o", "OUT" };
    },
    1, { "huge.stl", "is 102400 MiB; reading it needs more than the", "MiB of memory available" } },
  // A stage of one's own: the file named with its problem.
  { "ShaderStageMissing",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--fragment-shader", (d / "nope.frag").string() });
    },
    1, { "nope.frag", "No such file" } },
  { "ShaderStageFolder",
    [](const TempDir& d)
    {
      std::filesystem::create_directory(d / "stage.vert");
      return WithMesh(d, "t.obj", Tetrahedron, { "--vertex-shader", (d / "stage.vert").string() });
    },
    1, { "stage.vert", "Is a directory" } },
  { "ShaderStageEmpty",
    [](const TempDir& d)
    {
      WriteText(d / "empty.frag", "");
      return WithMesh(
        d, "t.obj", Tetrahedron, { "--fragment-shader", (d / "empty.frag").string() });
    },
    1, { "empty.frag", "is empty" } },
  { "ShaderStageUnderRaytrace",
    [](const TempDir& d)
    {
      WriteText(d / "mine.frag", "#version 150\nvoid main() {}\n");
      return WithMesh(d, "t.obj", Tetrahedron,
        { "--shading", "raytrace", "--fragment-shader", (d / "mine.frag").string() });
    },
    1, { "mine.frag", "runs no shader stage" } },
  // --texture: the image named with its problem, and a mesh without texture
  // coordinates named with the contract's words.
  { "TextureMissing",
    [](const TempDir& d) {
      return WithMesh(d, "st.off", TexturedQuad, { "--texture", (d / "nope.png").string() });
    },
    1, { "nope.png", "No such file" } },
  { "TextureUnreadable",
    [](const TempDir& d)
    {
      WriteText(d / "text.png", "not a picture\n");
      return WithMesh(d, "st.off", TexturedQuad, { "--texture", (d / "text.png").string() });
    },
    1, { "text.png", "not an image OpenImageIO can read" } },
  { "TextureOnMeshWithoutCoordinates",
    [](const TempDir& d)
    {
      WriteImage8(d / "one.png", 1, 1, { 255, 128, 0 });
      return WithMesh(d, "t.obj", Tetrahedron, { "--texture", (d / "one.png").string() });
    },
    1, { "t.obj: --texture needs texture coordinates, and the mesh has none" } },
  // The file's own textures: the image its MTL names, or the one a glTF
  // holds (named after the mesh), with the problem.
  { "FileTextureMissing",
    [](const TempDir& d)
    {
      WriteText(d / "t.mtl", "newmtl t\nKd 1 1 1\nmap_Kd nope.png\n");
      return WithMesh(d, "t.obj", TexturedObj);
    },
    1, { "nope.png", "No such file" } },
  { "FileTextureUnreadable",
    [](const TempDir& d)
    {
      WriteText(d / "text.png", "not a picture\n");
      WriteText(d / "t.mtl", "newmtl t\nKd 1 1 1\nmap_Kd text.png\n");
      return WithMesh(d, "t.obj", TexturedObj);
    },
    1, { "text.png", "not an image OpenImageIO can read" } },
  // libpng printed its own "libpng error: IHDR: Read error" line first.
  { "TextureTruncatedPng",
    [](const TempDir& d)
    {
      WriteImage8(d / "whole.png", 4, 4, { 255, 128, 0 });
      const std::string png = Slurp(d / "whole.png");
      WriteText(d / "cut.png", png.substr(0, 20));
      return WithMesh(d, "st.off", TexturedQuad, { "--texture", (d / "cut.png").string() });
    },
    1, { "cut.png" } },
  { "FileTextureEmbeddedUnreadable",
    [](const TempDir& d)
    {
      // One triangle with TEXCOORD_0; its image a data URI of "not an image".
      const float data[15] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1 };
      WriteText(d / "tri.bin", Binary(data, sizeof data));
      return WithMesh(d, "embedded.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"tri.bin\", "
        "\"byteLength\": 60}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 60}], "
        "\"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": 3, "
        "\"type\": \"VEC3\"}, {\"bufferView\": 0, \"byteOffset\": 36, \"componentType\": "
        "5126, \"count\": 3, \"type\": \"VEC2\"}], \"meshes\": [{\"primitives\": "
        "[{\"attributes\": {\"POSITION\": 0, \"TEXCOORD_0\": 1}, \"material\": 0}]}], "
        "\"materials\": [{\"pbrMetallicRoughness\": {\"baseColorTexture\": {\"index\": "
        "0}}}], \"textures\": [{\"source\": 0}], \"images\": [{\"uri\": "
        "\"data:image/png;base64,bm90IGFuIGltYWdl\"}]}");
    },
    1, { "embedded.gltf (texture 0)", "embedded image: neither PNG nor JPEG" } },
  { "TextureWrapUnknown",
    [](const TempDir& d) {
      return WithMesh(d, "st.off", TexturedQuad, { "--texture-wrap", "wobble" });
    },
    2, { "--texture-wrap", "wobble" } },
  { "TextureFilterUnknown",
    [](const TempDir& d) {
      return WithMesh(d, "st.off", TexturedQuad, { "--texture-filter", "trilinear" });
    },
    2, { "--texture-filter", "trilinear" } },
  // --environment: the image named with its problem (it needs no texture
  // coordinates); the ray tracer, which reflects by its rays, refuses it.
  { "EnvironmentMissing",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--environment", (d / "nope.png").string() });
    },
    1, { "nope.png", "No such file" } },
  { "EnvironmentIsAFolder",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--environment", d.path().string() });
    },
    1, { "Is a directory" } },
  { "EnvironmentUnreadable",
    [](const TempDir& d)
    {
      WriteText(d / "text.png", "not a picture\n");
      return WithMesh(d, "t.obj", Tetrahedron, { "--environment", (d / "text.png").string() });
    },
    1, { "text.png", "not an image OpenImageIO can read" } },
  { "EnvironmentUpUnknown",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--environment-up", "sideways" });
    },
    2, { "--environment-up", "sideways" } },
  { "EnvironmentUnderRaytrace",
    [](const TempDir& d)
    {
      WriteImage8(d / "sky.png", 1, 1, { 255, 128, 0 });
      return WithMesh(d, "t.obj", Tetrahedron,
        { "--shading", "raytrace", "--environment", (d / "sky.png").string() });
    },
    1, { "sky.png", "reflects the mesh by its rays" } },
  // --normal-map: a mesh without texture coordinates named with that
  // problem, the image with its own; a grey image is a height map.
  { "NormalMapWithoutTextureCoordinates",
    [](const TempDir& d)
    {
      WriteImage8(d / "n.png", 1, 1, { 128, 128, 255 });
      return WithMesh(d, "t.obj", Tetrahedron, { "--normal-map", (d / "n.png").string() });
    },
    1, { "t.obj", "--normal-map needs texture coordinates" } },
  { "NormalMapMissing",
    [](const TempDir& d) {
      return WithMesh(d, "st.off", TexturedQuad, { "--normal-map", (d / "nope.png:2").string() });
    },
    1, { "nope.png", "No such file" } },
  { "NormalMapUnreadable",
    [](const TempDir& d)
    {
      WriteText(d / "text.png", "not a picture\n");
      return WithMesh(d, "st.off", TexturedQuad, { "--normal-map", (d / "text.png").string() });
    },
    1, { "text.png", "not an image OpenImageIO can read" } },
  { "NormalMapGrey",
    [](const TempDir& d)
    {
      WriteImage8(d / "height.png", 2, 1, { 10, 10, 10, 200, 200, 200 });
      return WithMesh(d, "st.off", TexturedQuad, { "--normal-map", (d / "height.png").string() });
    },
    1, { "height.png", "a height map rather than a normal map" } },
  { "NormalMapNamesNoImage",
    [](const TempDir& d) {
      return WithMesh(d, "st.off", TexturedQuad, { "--normal-map", ":2" });
    },
    2, { "--normal-map", "names no image" } },
  { "NormalMapUnderRaytrace",
    [](const TempDir& d)
    {
      WriteImage8(d / "n.png", 1, 1, { 128, 128, 255 });
      return WithMesh(d, "st.off", TexturedQuad,
        { "--shading", "raytrace", "--normal-map", (d / "n.png").string() });
    },
    1, { "n.png", "not a normal map's" } },
  // --background environment names no image of its own: it needs --environment.
  { "EnvironmentBackgroundWithoutAnEnvironment",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--background", "environment" });
    },
    1, { "--background", "needs --environment" } },
  // --bump-map: a mesh without texture coordinates, an image that is not
  // grey (a normal map's), both maps at once; under the ray tracer.
  { "BumpMapWithoutTextureCoordinates",
    [](const TempDir& d)
    {
      WriteImage8(d / "h.png", 1, 1, { 90, 90, 90 });
      return WithMesh(d, "t.obj", Tetrahedron, { "--bump-map", (d / "h.png").string() });
    },
    1, { "t.obj", "--bump-map needs texture coordinates" } },
  { "BumpMapNotGrey",
    [](const TempDir& d)
    {
      WriteImage8(d / "n.png", 1, 1, { 128, 128, 255 });
      return WithMesh(d, "st.off", TexturedQuad, { "--bump-map", (d / "n.png").string() + ":3" });
    },
    1, { "n.png", "is not grey, so not a height map" } },
  { "BumpMapWithANormalMap",
    [](const TempDir& d)
    {
      WriteImage8(d / "h.png", 1, 1, { 90, 90, 90 });
      WriteImage8(d / "n.png", 1, 1, { 128, 128, 255 });
      return WithMesh(d, "st.off", TexturedQuad,
        { "--bump-map", (d / "h.png").string(), "--normal-map", (d / "n.png").string() });
    },
    1, { "--bump-map", "--normal-map is given too" } },
  { "BumpMapUnderRaytrace",
    [](const TempDir& d)
    {
      WriteImage8(d / "h.png", 1, 1, { 90, 90, 90 });
      return WithMesh(d, "st.off", TexturedQuad,
        { "--shading", "raytrace", "--bump-map", (d / "h.png").string() });
    },
    1, { "h.png", "not a bump map's" } },
  // Files that are no regular files: read forever (/dev/zero) or block in
  // open() (a FIFO) unless refused first.
  { "MeshIsALinkToDevZero",
    [](const TempDir& d)
    {
      std::filesystem::create_symlink("/dev/zero", d / "zero.obj");
      return std::vector<std::string>{ (d / "zero.obj").string(), "-o", "OUT" };
    },
    1, { "zero.obj", "is not a regular file but a character device" } },
  { "MeshIsAFifo",
    [](const TempDir& d)
    {
      MakeFifo(d / "pipe.stl");
      return std::vector<std::string>{ (d / "pipe.stl").string(), "-o", "OUT" };
    },
    1, { "pipe.stl", "is not a regular file but a FIFO" } },
  { "VtpIsAFifo",
    [](const TempDir& d)
    {
      MakeFifo(d / "pipe.vtp");
      return std::vector<std::string>{ (d / "pipe.vtp").string(), "-o", "OUT" };
    },
    1, { "pipe.vtp", "FIFO" } },
  { "TextureOptionIsDevZero",
    [](const TempDir& d) {
      return WithMesh(d, "st.off", TexturedQuad, { "--texture", "/dev/zero" });
    },
    1, { "/dev/zero", "is not a regular file but a character device" } },
  { "TextureOptionIsAFifo",
    [](const TempDir& d)
    {
      MakeFifo(d / "pipe.png");
      return WithMesh(d, "st.off", TexturedQuad, { "--texture", (d / "pipe.png").string() });
    },
    1, { "pipe.png", "FIFO" } },
  { "MtlMapIsAFifo",
    [](const TempDir& d)
    {
      MakeFifo(d / "wood.png");
      WriteText(d / "t.mtl", "newmtl t\nmap_Kd wood.png\n");
      return WithMesh(d, "fifo_map.obj", TexturedObj);
    },
    1, { "wood.png", "FIFO" } },
  // Files named by a mesh stay in its folder: no /etc/passwd read, quoted
  // or leaked through an error about its bytes.
  { "MtlMapOutsideTheFolder",
    [](const TempDir& d)
    {
      WriteText(d / "t.mtl", "newmtl t\nmap_Kd ../../../../../../etc/passwd\n");
      return WithMesh(d, "outside_map.obj", TexturedObj);
    },
    1,
    { "outside_map.obj", "'t.mtl'", "map '../../../", "lies outside the mesh's folder",
      "--allow-outside-references" } },
  { "MtlMapLinkedOutsideTheFolder",
    [](const TempDir& d)
    {
      std::filesystem::create_symlink("/dev/zero", d / "wood.png");
      WriteText(d / "t.mtl", "newmtl t\nmap_Kd wood.png\n");
      return WithMesh(d, "linked_map.obj", TexturedObj);
    },
    1, { "linked_map.obj", "'wood.png' lies outside the mesh's folder" } },
  { "MtlMapDevZeroAllowedOutsideIsStillNoRegularFile",
    [](const TempDir& d)
    {
      WriteText(d / "t.mtl", "newmtl t\nmap_Kd /dev/zero\n");
      return WithMesh(d, "zero_map.obj", TexturedObj, { "--allow-outside-references" });
    },
    1, { "/dev/zero", "is not a regular file but a character device" } },
  { "GltfBufferOutsideTheFolder",
    [](const TempDir& d)
    {
      return WithMesh(d, "passwd.gltf",
        R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "../../../../../../etc/passwd",
            "byteLength": 12}]})");
    },
    1, { "passwd.gltf", "buffer 0", "lies outside the mesh's folder" } },
  { "GltfPercentEncodedBufferOutsideTheFolder",
    [](const TempDir& d)
    {
      return WithMesh(d, "escaped.gltf",
        R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "%2e%2e/%2E%2E/%2e%2e/etc/passwd",
            "byteLength": 12}]})");
    },
    1, { "escaped.gltf", "buffer 0", "lies outside the mesh's folder" } },
  { "GltfImageOutsideTheFolder",
    [](const TempDir& d)
    {
      return WithMesh(d, "image.gltf",
        R"({"asset": {"version": "2.0"}, "images": [{"uri": "../elsewhere.png"}]})");
    },
    1, { "image.gltf", "image 0", "lies outside the mesh's folder" } },
  // Pictures that would be blank: said, not drawn.
  { "ObjSpanBeyondDoubles",
    [](const TempDir& d)
    { return WithMesh(d, "huge.obj", "v -1e308 0 0\nv 1e308 0 0\nv 0 1 0\nf 1 2 3\n"); },
    1, { "huge.obj", "span more than a double can measure" } },
  { "GltfNodeMatrixOfZeros",
    [](const TempDir& d)
    {
      const float xyz[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
      WriteText(d / "tri.bin", Binary(xyz, sizeof xyz));
      return WithMesh(d, "zeros.gltf",
        R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "tri.bin", "byteLength": 36}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 0]}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "nodes": [{"mesh": 0, "matrix": [0,0,0,0, 0,0,0,0, 0,0,0,0, 0,0,0,0]}],
            "scenes": [{"nodes": [0]}], "scene": 0})");
    },
    1, { "zeros.gltf", "no triangle has an area" } },
  { "FeatureAngleNaN",
    [](const TempDir& d) {
      return WithMesh(d, "t.obj", Tetrahedron, { "--feature-angle", "nan" });
    },
    2, { "--feature-angle", "'nan' is not a finite number" } },
  // JSON nested 70,000 deep: once crashed in the message's quoting of it.
  { "SceneFileNestedTooDeep",
    [](const TempDir& d)
    {
      WriteText(d / "deep.json", std::string(70000, '[') + std::string(70000, ']'));
      return std::vector<std::string>{ "--scene", (d / "deep.json").string() };
    },
    1, { "deep.json", "nested deeper than 256 levels" } },
  { "GltfNestedTooDeep",
    [](const TempDir& d)
    {
      return WithMesh(d, "deep.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + std::string(70000, '[') +
          std::string(70000, ']') + "}");
    },
    1, { "deep.gltf", "nested deeper than 256 levels" } },
  { "SceneFileIsAFifo",
    [](const TempDir& d)
    {
      MakeFifo(d / "scene.json");
      return std::vector<std::string>{ "--scene", (d / "scene.json").string() };
    },
    1, { "scene.json", "FIFO" } },
};

class BadInput : public testing::TestWithParam<BadCase>
{
};

void PrintTo(const BadCase& c, std::ostream* os)
{
  *os << c.Name;
}
}

TEST_P(BadInput, OneLineErrorNonZeroExitNoOutput)
{
  TempDir dir;
  std::vector<std::string> args = GetParam().Make(dir);
  const std::string out = (dir / "out.jpg").string();
  std::replace(args.begin(), args.end(), std::string("OUT"), out);
  args.insert(args.begin(), "render");
  const auto before = dir.Files();

  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, GetParam().ExitCode) << r.Stderr;
  ASSERT_FALSE(r.Stderr.empty());
  EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
  EXPECT_LT(r.Stderr.size(), 600u) << "not a line: " << r.Stderr.substr(0, 600);
  EXPECT_EQ(r.Stderr.rfind("shadelab: error: ", 0), 0u) << r.Stderr;
  for (const char* word : GetParam().Words)
  {
    const std::string expected = std::strcmp(word, "OUT") == 0 ? out : word;
    EXPECT_NE(r.Stderr.find(expected), std::string::npos)
      << "'" << expected << "' missing from: " << r.Stderr;
  }
  EXPECT_EQ(dir.Files(), before) << "an output or temporary file was left behind";
}

INSTANTIATE_TEST_SUITE_P(Render, BadInput, testing::ValuesIn(Cases),
  [](const testing::TestParamInfo<BadCase>& info) { return std::string(info.param.Name); });

// Non-manifold and degenerate faces are not errors: they render.
TEST(AwkwardInput, NonManifoldAndDegenerateFacesRender)
{
  TempDir dir;
  // Three triangles sharing one edge (non-manifold), one zero-area triangle.
  WriteText(dir / "fin.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 2 0 0\n"
    "f 1 2 3\nf 1 2 4\nf 1 2 5\nf 1 2 6\n");
  const RunResult r = RunShadelab(
    { "render", (dir / "fin.obj").string(), "-o", (dir / "fin.png").string(), "--size", "64x64" });
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(ReadImage(dir / "fin.png").Width, 64);
}

TEST(AwkwardInput, ViewWithoutADisplayIsAOneLineError)
{
  // RunShadelab unsets DISPLAY: no X server to open a window on.
  const RunResult run = RunShadelab({ "view", TestMesh("teapot.obj").string() });
  EXPECT_EQ(run.ExitCode, 1);
  EXPECT_NE(run.Stderr.find("shadelab: error: view: cannot open the display"), std::string::npos)
    << run.Stderr;
  EXPECT_EQ(std::count(run.Stderr.begin(), run.Stderr.end(), '\n'), 1) << run.Stderr;
  const RunResult bad =
    RunShadelab({ "view", TestMesh("teapot.obj").string(), "--interactive-shading", "fast" });
  EXPECT_EQ(bad.ExitCode, 2) << bad.Stderr;
}

// The window draws the raster rules live; asked for raytrace as its rule
// it says so in one line, before it looks for a display (the comparison
// layout takes raytrace as a mode: test_view_raytrace).
TEST(AwkwardInput, ViewRefusesRaytraceWithOneLine)
{
  const RunResult run =
    RunShadelab({ "view", TestMesh("teapot.obj").string(), "--shading", "raytrace" });
  EXPECT_EQ(run.ExitCode, 2) << run.Stderr;
  EXPECT_NE(run.Stderr.find("view: raytrace is drawn in the window only as a mode of the "
                            "comparison layout (--modes)"),
    std::string::npos)
    << run.Stderr;
  EXPECT_EQ(std::count(run.Stderr.begin(), run.Stderr.end(), '\n'), 1) << run.Stderr;
}

// An MTL library outside the mesh's folder is refused like a missing one (a
// warning; the default material draws), and nothing of it is read: its
// "Kd hunter2" once came back in an error.
TEST(AwkwardInput, MaterialLibraryOutsideTheFolderIsNotRead)
{
  TempDir dir;
  std::filesystem::create_directory(dir / "mesh");
  WriteText(dir / "secret.mtl", "newmtl t\nKd hunter2\n");
  WriteText(dir / "mesh" / "m.obj", "mtllib ../secret.mtl\nusemtl t\n" + Tetrahedron);
  const std::vector<std::string> args{ "render", (dir / "mesh" / "m.obj").string(), "-o",
    (dir / "m.png").string(), "--size", "32x32" };
  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_NE(r.Stderr.find("material library '../secret.mtl': lies outside the mesh's folder"),
    std::string::npos)
    << r.Stderr;
  EXPECT_EQ(r.Stderr.find("hunter2"), std::string::npos) << r.Stderr;
  // Trusted, it is read (and its malformed Kd said, as for any library).
  std::vector<std::string> trusted = args;
  trusted.push_back("--allow-outside-references");
  const RunResult t = RunShadelab(trusted);
  EXPECT_EQ(t.ExitCode, 1) << t.Stderr;
  EXPECT_NE(t.Stderr.find("malformed Kd"), std::string::npos) << t.Stderr;
}

// A UTF-8 byte order mark, as Windows editors write it, is no keyword.
TEST(AwkwardInput, ByteOrderMarkIsSkipped)
{
  TempDir dir;
  WriteText(dir / "bom.obj", "\xEF\xBB\xBF" + Tetrahedron);
  const RunResult r = RunShadelab(
    { "render", (dir / "bom.obj").string(), "-o", (dir / "bom.png").string(), "--size", "32x32" });
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(r.Stderr, "");
}

// Names that are not UTF-8 (a Latin-1 MTL, as assimp's regr01.obj has) go
// into the picture's metadata and probe's JSON with U+FFFD in their place;
// they once aborted the program from nlohmann-json's dump.
TEST(AwkwardInput, MaterialNamesThatAreNotUtf8)
{
  TempDir dir;
  WriteText(dir / "l.mtl", "newmtl caf\xE9\nKd 0.8 0.2 0.2\n");
  WriteText(dir / "latin1.obj", "mtllib l.mtl\nusemtl caf\xE9\n" + Tetrahedron);
  const RunResult r = RunShadelab(
    { "render", (dir / "latin1.obj").string(), "-o", (dir / "l.png").string(), "--size", "32x32" });
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  const RunResult p = RunShadelab(
    { "probe", (dir / "latin1.obj").string(), "--pixel", "16,16", "--size", "32x32", "--json" });
  EXPECT_EQ(p.ExitCode, 0) << p.Stderr;
  EXPECT_EQ(p.Stdout.find('\xE9'), std::string::npos) << "not UTF-8: " << p.Stdout;
}

// Two names of one file are one output: the second would overwrite the first.
TEST(AwkwardInput, AliasedOutputsAreRefused)
{
  TempDir dir;
  std::filesystem::create_directory(dir / "out");
  const std::string mesh = TestMesh("teapot.obj").string();
  WriteText(dir / "scene.json",
    R"({ "mesh": ")" + mesh + R"(", "size": [32, 32], "shots": [ { "output": ")" +
      (dir / "out/x.png").string() + R"(" }, { "output": ")" + (dir / "out/../out/x.png").string() +
      R"(" } ] })");
  const RunResult r = RunShadelab({ "render", "--scene", (dir / "scene.json").string() });
  EXPECT_NE(r.ExitCode, 0);
  EXPECT_NE(r.Stderr.find("is also shots[0]'s output"), std::string::npos) << r.Stderr;
  EXPECT_TRUE(FilesIn(dir / "out").empty());
}
