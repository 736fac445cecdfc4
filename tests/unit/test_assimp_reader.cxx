// The assimp reader: its extensions held to assimp's registry, small files
// of three formats written here (materials, a node's transform, a texture,
// vertex colours, an index out of range), files of Debian's
// assimp-testmodels whose counts and materials their text gives, bad input
// under several extensions, and files that crash assimp.
#include "mesh_reader_fixture.h"
#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabAssimpReader.h"
#include "vtkShadelabMeshReader.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <assimp/Importer.hpp>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace
{
using namespace shadelab::test;

const fs::path Models = "/usr/share/assimp/models";

std::set<std::string> Words(const std::string& text)
{
  std::istringstream in(text);
  std::set<std::string> words;
  for (std::string word; in >> word;)
  {
    words.insert(word);
  }
  return words;
}

std::array<double, 3> PartTuple(vtkPolyData* mesh, const char* name, int part)
{
  std::array<double, 3> tuple{};
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  EXPECT_NE(array, nullptr) << name;
  if (array && part < array->GetNumberOfTuples())
  {
    for (int c = 0; c < array->GetNumberOfComponents() && c < 3; ++c)
    {
      tuple[c] = array->GetComponent(part, c);
    }
  }
  return tuple;
}

std::string PartName(vtkPolyData* mesh, int part)
{
  auto* names = vtkStringArray::SafeDownCast(
    mesh->GetFieldData()->GetAbstractArray(shadelab::PartMaterialsArrayName));
  return names && part < names->GetNumberOfValues() ? names->GetValue(part) : "(none)";
}

void ExpectNear3(const std::array<double, 3>& got, const std::array<double, 3>& expected)
{
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(got[c], expected[c], 1e-6) << "component " << c;
  }
}

ReadResult ReadModel(const std::string& relative)
{
  return Read(Models / relative);
}

// An AC3D file: one material, one object moved by its "loc", a quad.
std::string Ac3d(const std::string& refs)
{
  return "AC3Db\n"
         "MATERIAL \"red\" rgb 1 0 0  amb 0.2 0.3 0.4  emis 0 0 0  spec 0.5 0.25 0.125  shi 10  "
         "trans 0\n"
         "OBJECT world\nkids 1\nOBJECT poly\nname \"quad\"\nloc 10 20 30\nnumvert 4\n"
         "0 0 0\n1 0 0\n1 1 0\n0 1 0\nnumsurf 1\nSURF 0x10\nmat 0\nrefs 4\n" +
    refs + "kids 0\n";
}
const std::string AcRefs = "0 0 0\n1 1 0\n2 1 1\n3 0 1\n";

// A DirectX .x text file: a material with a texture, a frame's transform.
std::string DirectX(const std::string& faces)
{
  return "xof 0303txt 0032\n"
         "Frame Root {\n FrameTransformMatrix {\n  1.0,0.0,0.0,0.0,\n  0.0,1.0,0.0,0.0,\n  "
         "0.0,0.0,1.0,0.0,\n  10.0,20.0,30.0,1.0;;\n }\n"
         " Mesh Quad {\n  4;\n  0;0;0;, 1;0;0;, 1;1;0;, 0;1;0;;\n  1;\n" +
    faces +
    "  MeshMaterialList { 1; 1; 0;;\n   Material Red { 1.0;0.0;0.0;1.0;; 20.0; 0.5;0.5;0.5;; "
    "0.0;0.0;0.0;; TextureFilename { \"tex.png\"; } }\n  }\n"
    "  MeshTextureCoords { 4; 0;0;, 1;0;, 1;1;, 0;1;; }\n }\n}\n";
}
const std::string XFaces = "  4;0,1,2,3;;\n";

// A COLLADA square of two triangles, its node moved by 10 20 30.
const std::string Collada = R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
 <library_geometries><geometry id="g"><mesh>
  <source id="p"><float_array id="pa" count="12">0 0 0 1 0 0 1 1 0 0 1 0</float_array>
   <technique_common><accessor source="#pa" count="4" stride="3"><param name="X" type="float"/>
    <param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common>
  </source>
  <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
  <triangles count="2"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2 0 2 3</p></triangles>
 </mesh></geometry></library_geometries>
 <library_visual_scenes><visual_scene id="s"><node id="n"><translate>10 20 30</translate>
  <instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
 <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";

// The square with a colour per vertex (COLLADA's COLOR input of <vertices>).
std::string ColladaColours()
{
  std::string text = Collada;
  text.replace(text.find("  <vertices"), 0,
    R"(  <source id="c"><float_array id="ca" count="12">1 0 0 0 1 0 0 0 1 0.25 0.5 0.75</float_array>
   <technique_common><accessor source="#ca" count="4" stride="3"><param name="R" type="float"/>
    <param name="G" type="float"/><param name="B" type="float"/></accessor></technique_common>
  </source>
)");
  text.replace(text.find("</vertices>"), 0, R"(<input semantic="COLOR" source="#c"/>)");
  return text;
}

TEST(AssimpReader, TakesEveryExtensionOfAssimpThatShadelabDoesNotReadItself)
{
  Assimp::Importer importer;
  std::string list;
  importer.GetExtensionList(list); // "*.3d;*.3ds;..."
  std::set<std::string> assimp;
  std::istringstream in(list);
  for (std::string pattern; std::getline(in, pattern, ';');)
  {
    // As the mesh reader sees a name: its last extension (".mesh.xml" is ".xml").
    assimp.insert(pattern.substr(pattern.find_last_of('.')));
  }
  const std::set<std::string> own = Words(vtkShadelabMeshReader::GetKnownExtensions());
  std::set<std::string> expected;
  for (const std::string& extension : assimp)
  {
    if (!own.count(extension))
    {
      expected.insert(extension);
    }
  }
  EXPECT_EQ(Words(vtkShadelabAssimpReader::GetExtensions()), expected);
}

TEST_F(MeshReaders, AssimpAc3dMaterialAndTransform)
{
  const ReadResult result = Read(this->Write("quad.ac", Ac3d(AcRefs)));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 2);
  double bounds[6];
  result.Mesh->GetBounds(bounds);
  EXPECT_DOUBLE_EQ(bounds[0], 10); // loc moved it
  EXPECT_DOUBLE_EQ(bounds[1], 11);
  EXPECT_DOUBLE_EQ(bounds[2], 20);
  EXPECT_DOUBLE_EQ(bounds[3], 21);
  EXPECT_DOUBLE_EQ(bounds[4], 30);
  ASSERT_NE(result.Mesh->GetCellData()->GetArray(shadelab::PartArrayName), nullptr);
  EXPECT_EQ(PartName(result.Mesh, 0), "red");
  ExpectNear3(PartTuple(result.Mesh, shadelab::PartKaArrayName, 0), { 0.2, 0.3, 0.4 });
  ExpectNear3(PartTuple(result.Mesh, shadelab::PartKdArrayName, 0), { 1, 0, 0 });
  ExpectNear3(PartTuple(result.Mesh, shadelab::PartKsArrayName, 0), { 0.5, 0.25, 0.125 });
  EXPECT_DOUBLE_EQ(PartTuple(result.Mesh, shadelab::PartNsArrayName, 0)[0], 10);
}

TEST_F(MeshReaders, AssimpDirectXTextureTransformAndNormalsSetting)
{
  const ReadResult result = Read(this->Write("quad.x", DirectX(XFaces)));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 2);
  double bounds[6];
  result.Mesh->GetBounds(bounds);
  EXPECT_DOUBLE_EQ(bounds[0], 10); // the frame's translation, applied
  EXPECT_DOUBLE_EQ(bounds[1], 11);
  EXPECT_DOUBLE_EQ(bounds[2], 20);
  EXPECT_DOUBLE_EQ(bounds[3], 21);
  EXPECT_DOUBLE_EQ(std::abs(bounds[4]), 30); // .x is left-handed: assimp turns z over
  EXPECT_EQ(PartName(result.Mesh, 0), "Red");
  ExpectNear3(PartTuple(result.Mesh, shadelab::PartKdArrayName, 0), { 1, 0, 0 });
  ExpectNear3(PartTuple(result.Mesh, shadelab::PartKsArrayName, 0), { 0.5, 0.5, 0.5 });
  EXPECT_DOUBLE_EQ(PartTuple(result.Mesh, shadelab::PartNsArrayName, 0)[0], 20);
  const std::vector<shadelab::Texture> textures = shadelab::MeshTextures(result.Mesh);
  ASSERT_EQ(textures.size(), 1u);
  EXPECT_EQ(textures[0].Source, (this->Dir / "tex.png").string());
  EXPECT_EQ(PartTuple(result.Mesh, shadelab::PartKdTextureArrayName, 0)[0], 0);
  EXPECT_EQ(PartTuple(result.Mesh, shadelab::PartKaTextureArrayName, 0)[0], 0);
  EXPECT_NE(result.Mesh->GetPointData()->GetArray(shadelab::TextureCoordinatesArrayName), nullptr);
}

TEST_F(MeshReaders, AssimpColladaNodeTranslation)
{
  const ReadResult result = Read(this->Write("square.dae", Collada));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 2);
  double bounds[6];
  result.Mesh->GetBounds(bounds);
  const double expected[6] = { 10, 11, 20, 21, 30, 30 };
  for (int k = 0; k < 6; ++k)
  {
    EXPECT_DOUBLE_EQ(bounds[k], expected[k]) << k;
  }
  // No material in the file: assimp's stand-in is a part without one.
  EXPECT_EQ(PartName(result.Mesh, 0), "");
  EXPECT_EQ(PartTuple(result.Mesh, shadelab::PartMaterialIndicesArrayName, 0)[0], -1);
}

TEST_F(MeshReaders, AssimpTextureOutsideTheFolderIsRefusedUnlessAllowed)
{
  std::string text = DirectX(XFaces);
  text.replace(text.find("\"tex.png\""), 9, "\"../tex.png\"");
  this->ExpectError(
    "outside.x", text, { "texture", "../tex.png", "lies outside the mesh's folder" });
}

TEST_F(MeshReaders, AssimpNormalsFollowReadNormals)
{
  const fs::path path = Models / "Collada" / "cube_triangulate.dae";
  vtkNew<vtkShadelabAssimpReader> reader;
  ReadResult with = ReadWith(reader, path);
  ASSERT_TRUE(with.Ok) << with.Error;
  EXPECT_NE(with.Mesh->GetPointData()->GetNormals(), nullptr);
  reader->ReadNormalsOff();
  ReadResult without = ReadWith(reader, path);
  ASSERT_TRUE(without.Ok) << without.Error;
  EXPECT_EQ(without.Mesh->GetPointData()->GetNormals(), nullptr);
}

// cube_triangulate.dae: <triangles count="12" material="BlueSG">, material
// "Blue" with diffuse 0.137255 0.403922 0.870588, specular 0.5 0.5 0.5 and
// shininess 16 (lines 85-155 of the file).
TEST_F(MeshReaders, AssimpColladaCubeCountsAndMaterial)
{
  const ReadResult result = ReadModel("Collada/cube_triangulate.dae");
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 12);
  EXPECT_EQ(PartName(result.Mesh, 0), "Blue");
  ExpectNear3(
    PartTuple(result.Mesh, shadelab::PartKdArrayName, 0), { 0.137255, 0.403922, 0.870588 });
  ExpectNear3(PartTuple(result.Mesh, shadelab::PartKsArrayName, 0), { 0.5, 0.5, 0.5 });
  EXPECT_DOUBLE_EQ(PartTuple(result.Mesh, shadelab::PartNsArrayName, 0)[0], 16);
}

// Cubes of 6 quads (12 triangles) in 3MF, FBX, Blender and 3DS; the 3DS
// one names its texture TEST.PNG (the file's text holds the name).
TEST_F(MeshReaders, AssimpCubesOfSeveralFormats)
{
  for (const char* file : { "3MF/box.3mf", "FBX/box.fbx", "BLEND/box.blend" })
  {
    const ReadResult result = ReadModel(file);
    ASSERT_TRUE(result.Ok) << file << ": " << result.Error;
    ExpectTriangleMesh(result.Mesh);
    EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 12) << file;
  }
  const ReadResult textured = ReadModel("3DS/cube_with_diffuse_texture.3DS");
  ASSERT_TRUE(textured.Ok) << textured.Error;
  EXPECT_EQ(textured.Mesh->GetNumberOfPolys(), 12);
  const std::vector<shadelab::Texture> textures = shadelab::MeshTextures(textured.Mesh);
  ASSERT_EQ(textures.size(), 1u);
  EXPECT_EQ(textures[0].Source, (Models / "3DS" / "TEST.PNG").string());
}

// assimp's COLLADA importer checks its indices; its AC3D and X importers
// repair a bad one unseen (AC3D with a warning in assimp's log, X not at
// all), so what reaches shadelab is in range.
TEST_F(MeshReaders, AssimpBadIndexIsAOneLineError)
{
  std::string text = Collada;
  text.replace(text.find("0 2 3</p>"), 5, "0 2 7");
  this->ExpectError("range.dae", text, { "Invalid data index (7/4)" });
}

TEST_F(MeshReaders, AssimpBadInputIsOneLineError)
{
  fs::create_directory(this->Dir / "x.fbx");
  this->ExpectError(this->Dir / "x.fbx", { "cannot open", "Is a directory" });
  const std::string garbage = "\x01\x02garbage\xff\xfe not a mesh at all \x7f\n";
  for (const char* name : { "g.fbx", "g.dae", "g.3ds", "g.x", "g.ac", "g.blend", "g.3mf" })
  {
    this->ExpectError(name, garbage, {});
  }
  this->ExpectError("empty.dae", "", {});
  this->ExpectError(Models / "AC" / "openLine.ac", { "no triangles" }); // a line only
  // Files of the collection cut in half.
  for (const char* file :
    { "Collada/cube_triangulate.dae", "FBX/box.fbx", "3DS/fels.3ds", "BLEND/box.blend" })
  {
    std::ifstream in(Models / file, std::ios::binary);
    const std::string bytes{ std::istreambuf_iterator<char>(in), {} };
    ASSERT_GT(bytes.size(), 100u) << file;
    this->ExpectError(
      "cut-" + fs::path(file).filename().string(), bytes.substr(0, bytes.size() / 2), {});
  }
}

TEST_F(MeshReaders, AssimpVertexColoursAreThePointColours)
{
  const ReadResult result = Read(this->Write("colours.dae", ColladaColours()));
  ASSERT_TRUE(result.Ok) << result.Error;
  vtkDataArray* colours = result.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName);
  ASSERT_NE(colours, nullptr);
  ASSERT_EQ(colours->GetNumberOfComponents(), 4);
  // Each point's colour is the one of its position (assimp may reorder points).
  const std::map<std::array<double, 2>, std::array<double, 4>> expected{
    { { 10, 20 }, { 1, 0, 0, 1 } }, { { 11, 20 }, { 0, 1, 0, 1 } }, { { 11, 21 }, { 0, 0, 1, 1 } },
    { { 10, 21 }, { 0.25, 0.5, 0.75, 1 } }
  };
  ASSERT_EQ(result.Mesh->GetNumberOfPoints(), 4);
  for (vtkIdType p = 0; p < 4; ++p)
  {
    const double* xyz = result.Mesh->GetPoint(p);
    const auto found = expected.find({ xyz[0], xyz[1] });
    ASSERT_NE(found, expected.end()) << xyz[0] << " " << xyz[1];
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_FLOAT_EQ(colours->GetComponent(p, c), found->second[c]) << "point " << p << " " << c;
    }
  }
  std::string text = ColladaColours();
  text.replace(text.find("0.25 0.5"), 4, "nan ");
  this->ExpectError("nan-colour.dae", text, { "non-finite colour" });
}

// Inputs that crash assimp 5.2's parsers (found by fuzzing; the fuzz
// targets replay them): the program goes on, with one error.
TEST_F(MeshReaders, AssimpCrashIsAOneLineError)
{
  const fs::path regressions = fs::path(SHADELAB_SOURCE_DIR) / "tests/fuzz/regressions";
  for (const char* file :
    { "fuzz_dae/assimp-segv-float-array-count.dae", "fuzz_x/assimp-segv-misspelt-template.x" })
  {
    this->ExpectError(regressions / file, { "assimp crashed reading it (" });
  }
}
}
