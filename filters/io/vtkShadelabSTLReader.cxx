#include "vtkShadelabSTLReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"

#include <vtkByteSwap.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

vtkStandardNewMacro(vtkShadelabSTLReader);

namespace
{
using shadelab::MeshReadError;
using shadelab::Quote;
using shadelab::TextScanner;

constexpr std::size_t HeaderBytes = 84; // 80 bytes of text, then the uint32 count
constexpr std::size_t TriangleBytes = 50;

// Makes one point of all corners with exactly equal coordinates.
class Welder
{
public:
  explicit Welder(shadelab::PolygonMesh& mesh)
    : Mesh(mesh)
  {
  }

  void AddCorner(const double xyz[3])
  {
    // -0 == +0, and std::hash<double> must (and does) give them one hash.
    const Key key{ xyz[0], xyz[1], xyz[2] };
    const auto [it, added] =
      this->Index.try_emplace(key, static_cast<vtkIdType>(this->Mesh.Points.size() / 3));
    if (added)
    {
      this->Mesh.Points.insert(this->Mesh.Points.end(), { key.X, key.Y, key.Z });
    }
    this->Mesh.FaceIds.push_back(it->second);
  }

  void EndTriangle()
  {
    this->Mesh.FaceOffsets.push_back(static_cast<vtkIdType>(this->Mesh.FaceIds.size()));
  }

private:
  struct Key
  {
    double X, Y, Z;
    bool operator==(const Key& other) const
    {
      return this->X == other.X && this->Y == other.Y && this->Z == other.Z;
    }
  };
  struct KeyHash
  {
    std::size_t operator()(const Key& key) const
    {
      const std::hash<double> hash;
      std::size_t h = hash(key.X);
      h ^= hash(key.Y) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
      h ^= hash(key.Z) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
      return h;
    }
  };

  shadelab::PolygonMesh& Mesh;
  std::unordered_map<Key, vtkIdType, KeyHash> Index;
};

// Empty when all three are finite; NaN would never weld (NaN != NaN).
std::string NonFinite(const double xyz[3], std::uint64_t triangle)
{
  for (int c = 0; c < 3; ++c)
  {
    if (!std::isfinite(xyz[c]))
    {
      return std::string(std::isnan(xyz[c]) ? "NaN" : "infinite") + " coordinate in triangle " +
        std::to_string(triangle);
    }
  }
  return {};
}

std::uint32_t DeclaredTriangles(std::string_view bytes)
{
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + 80, sizeof count);
  vtkByteSwap::SwapLE(&count);
  return count;
}

bool IsBinary(std::string_view bytes)
{
  return bytes.size() >= HeaderBytes &&
    HeaderBytes + TriangleBytes * std::uint64_t{ DeclaredTriangles(bytes) } == bytes.size();
}

bool IsAscii(std::string_view bytes)
{
  return bytes.substr(0, 5) == "solid" && bytes.find('\0') == std::string_view::npos;
}

void ReadBinary(std::string_view bytes, Welder& welder)
{
  const std::uint32_t count = DeclaredTriangles(bytes);
  const char* triangle = bytes.data() + HeaderBytes;
  for (std::uint32_t t = 0; t < count; ++t, triangle += TriangleBytes)
  {
    for (int corner = 0; corner < 3; ++corner)
    {
      float coordinates[3];
      std::memcpy(
        coordinates, triangle + 12 * (corner + 1), sizeof coordinates); // after the normal
      vtkByteSwap::SwapLERange(coordinates, 3);
      const double xyz[3] = { coordinates[0], coordinates[1], coordinates[2] };
      const std::string problem = NonFinite(xyz, t);
      if (!problem.empty())
      {
        throw MeshReadError(problem);
      }
      welder.AddCorner(xyz);
    }
    welder.EndTriangle();
  }
}

// Moves to the next line and checks that it starts with `words`.
void ExpectLine(
  TextScanner& scanner, std::initializer_list<std::string_view> words, std::uint64_t triangle)
{
  std::string expected;
  for (const std::string_view word : words)
  {
    expected += (expected.empty() ? "" : " ") + std::string(word);
  }
  if (!scanner.NextLine())
  {
    throw MeshReadError("truncated: the file ends inside triangle " + std::to_string(triangle),
      vtkErrorCode::PrematureEndOfFileError);
  }
  for (const std::string_view word : words)
  {
    const std::string_view token = scanner.NextToken();
    if (token != word)
    {
      scanner.Fail("expected '" + expected + "', found " + Quote(token));
    }
  }
}

// solid NAME, then facets (facet normal n n n / outer loop / 3 x vertex x y z
// / endloop / endfacet), then endsolid NAME; several solids may follow.
void ReadAscii(std::string_view text, Welder& welder)
{
  TextScanner scanner(text);
  bool inSolid = false;
  std::uint64_t triangle = 0;
  while (scanner.NextLine())
  {
    const std::string_view keyword = scanner.NextToken();
    if (!inSolid)
    {
      if (keyword != "solid")
      {
        scanner.Fail("expected 'solid', found " + Quote(keyword));
      }
      inSolid = true; // the rest of the line is the solid's name
      continue;
    }
    if (keyword == "endsolid")
    {
      inSolid = false;
      continue;
    }
    if (keyword != "facet" || scanner.NextToken() != "normal")
    {
      scanner.Fail("expected 'facet normal' or 'endsolid', found " + Quote(keyword));
    }
    for (int c = 0; c < 3; ++c)
    {
      scanner.ReadDouble("normal component");
    }
    scanner.ExpectLineEnd("the facet normal");
    ExpectLine(scanner, { "outer", "loop" }, triangle);
    for (int corner = 0; corner < 3; ++corner)
    {
      ExpectLine(scanner, { "vertex" }, triangle);
      double xyz[3];
      for (double& value : xyz)
      {
        value = scanner.ReadDouble("vertex coordinate");
      }
      scanner.ExpectLineEnd("a vertex");
      const std::string problem = NonFinite(xyz, triangle);
      if (!problem.empty())
      {
        scanner.Fail(problem);
      }
      welder.AddCorner(xyz);
    }
    ExpectLine(scanner, { "endloop" }, triangle);
    ExpectLine(scanner, { "endfacet" }, triangle);
    welder.EndTriangle();
    ++triangle;
  }
  if (inSolid)
  {
    throw MeshReadError(
      "truncated: the file ends before 'endsolid'", vtkErrorCode::PrematureEndOfFileError);
  }
}
}

void vtkShadelabSTLReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const std::string bytes = ReadFileBytes(fileName);
  shadelab::PolygonMesh mesh;
  Welder welder(mesh);
  if (IsBinary(bytes))
  {
    ReadBinary(bytes, welder);
  }
  else if (IsAscii(bytes))
  {
    ReadAscii(bytes, welder);
  }
  else if (bytes.size() < HeaderBytes)
  {
    throw MeshReadError("not an STL file: " + std::to_string(bytes.size()) +
      " bytes, neither ASCII nor the 84 bytes that a binary header takes");
  }
  else
  {
    const std::uint64_t count = DeclaredTriangles(bytes);
    throw MeshReadError("binary STL header declares " + std::to_string(count) +
      " triangles, which take " + std::to_string(HeaderBytes + TriangleBytes * count) +
      " bytes, but the file has " + std::to_string(bytes.size()) + " bytes");
  }
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(std::move(mesh)), triangles);
}
