// What the mesh readers' tests share: reading a file as `shadelab render`
// does (its one error line, warnings and error code), the shape every read
// must give, and a fixture with a temporary folder for hand-made files.
#ifndef shadelab_mesh_reader_fixture_h
#define shadelab_mesh_reader_fixture_h

#include "vtkShadelabFileReader.h"

#include <vtkByteSwap.h>
#include <vtkErrorCode.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace shadelab::test
{
namespace fs = std::filesystem;

/** The meshes shadelab makes itself (meshes/). */
inline const fs::path TestMeshes = fs::path(SHADELAB_TEST_MESHES);
/** Debian's assimp-testmodels. */
inline const fs::path DebianModels = fs::path(SHADELAB_DEBIAN_MODELS);

struct ReadResult
{
  bool Ok = false;
  vtkSmartPointer<vtkPolyData> Mesh;
  std::string Error;
  unsigned long ErrorCode = vtkErrorCode::NoError;
  std::vector<std::string> Warnings;
};

/** Reads `path` with `reader` inside a MessageScope of its own. */
ReadResult ReadWith(vtkShadelabFileReader* reader, const fs::path& path);

/** Reads `path` with vtkShadelabMeshReader, as the program does. */
ReadResult Read(const fs::path& path);

/** The mesh's triangles (every cell must be one). */
std::vector<std::array<vtkIdType, 3>> Triangles(vtkPolyData* mesh);

/** The un-normalised normal: its length is twice the triangle's area. */
std::array<double, 3> AreaNormal(vtkPolyData* mesh, const std::array<vtkIdType, 3>& triangle);

/**
 * What every successful read must give: triangles only, double points, all
 * finite, no verts/lines/strips, and no point data but the normals and the
 * readers' named attributes (shadelabTriangleMesh.h), each one tuple per
 * point, file vertices at their copies' positions.
 */
void ExpectTriangleMesh(vtkPolyData* mesh);

/** Each MTL text of `mistakes` fails ParseMtl with exactly its message. */
void ExpectMtlErrors(const std::vector<std::pair<std::string, std::string>>& mistakes);

/** Appends `value` in the given byte order (host-independent). */
template <typename T>
void Put(std::string& bytes, T value, bool bigEndian = false)
{
  if (bigEndian)
  {
    vtkByteSwap::SwapBE(&value);
  }
  else
  {
    vtkByteSwap::SwapLE(&value);
  }
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

class MeshReaders : public ::testing::Test
{
protected:
  void SetUp() override;
  void TearDown() override;

  fs::path Write(const std::string& name, const std::string& bytes) const;

  // Reads `bytes` as file `name` and checks that it fails the way bad input
  // must: request failed, an error code, an empty output, and one line that
  // contains every key word.
  void ExpectError(
    const std::string& name, const std::string& bytes, std::initializer_list<const char*> keyWords);
  void ExpectError(const fs::path& path, std::initializer_list<const char*> keyWords);

  fs::path Dir;
};
}

#endif
