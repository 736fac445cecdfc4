#include "vtkShadelabOFFReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkShadelabOFFReader);

namespace
{
using shadelab::MeshReadError;
using shadelab::Quote;
using shadelab::TextScanner;

// What the keyword says each vertex carries, and the counts after it.
struct OffHeader
{
  bool Normals = false;
  bool Colors = false;
  bool TextureCoordinates = false;
  std::uint64_t Vertices = 0;
  std::uint64_t Faces = 0;
};

const char* KeywordHelp = "(OFF, with any of the prefixes ST, C, N)";

// [ST][C][N]OFF, the prefixes in any order; "OFF" may run into the first
// count (ModelNet's "OFF1234"), which goes to `glued`.
OffHeader ReadKeyword(std::string_view keyword, std::string_view& glued, const TextScanner& scanner)
{
  const auto off = keyword.find("OFF");
  if (off == std::string_view::npos)
  {
    throw MeshReadError(
      "not an OFF file: the first word is " + Quote(keyword) + ", not a keyword " + KeywordHelp);
  }
  OffHeader header;
  std::string_view prefixes = keyword.substr(0, off);
  const auto take = [&](std::string_view prefix, bool& flag)
  {
    if (prefixes.substr(0, prefix.size()) != prefix)
    {
      return false;
    }
    if (flag)
    {
      scanner.Fail("keyword " + Quote(keyword) + " repeats " + std::string(prefix));
    }
    flag = true;
    prefixes.remove_prefix(prefix.size());
    return true;
  };
  while (!prefixes.empty())
  {
    if (prefixes[0] == '4' || prefixes[0] == 'n')
    {
      scanner.Fail("keyword " + Quote(keyword) + ": " + (prefixes[0] == '4' ? "4D" : "nD") +
        " vertices are not supported");
    }
    if (!take("ST", header.TextureCoordinates) && !take("C", header.Colors) &&
      !take("N", header.Normals))
    {
      scanner.Fail("unknown keyword " + Quote(keyword) + " " + KeywordHelp);
    }
  }
  glued = keyword.substr(off + 3);
  if (!glued.empty() &&
    !std::all_of(glued.begin(), glued.end(), [](char c) { return c >= '0' && c <= '9'; }))
  {
    scanner.Fail("unknown keyword " + Quote(keyword) + " " + KeywordHelp);
  }
  return header;
}

// A count of the header line; `token` may be the one glued to the keyword.
std::uint64_t ReadCount(std::string_view token, const char* what, const TextScanner& scanner)
{
  long long value = 0;
  if (token.empty())
  {
    scanner.Fail(std::string("missing ") + what + " count");
  }
  if (!shadelab::ParseNumber(token, value) || value < 0)
  {
    scanner.Fail(std::string("malformed ") + what + " count " + Quote(token));
  }
  return static_cast<std::uint64_t>(value);
}

// The smallest vertex line is "0 0 0\n", the smallest face "3 0 1 2\n"; the
// last line may lack its newline.
void CheckCounts(const OffHeader& header, std::size_t fileSize)
{
  constexpr std::uint64_t vertexBytes = 6, faceBytes = 8;
  const std::uint64_t room = fileSize + 1;
  if (header.Vertices > room / vertexBytes || header.Faces > room / faceBytes ||
    vertexBytes * header.Vertices + faceBytes * header.Faces > room)
  {
    throw MeshReadError("header declares " + std::to_string(header.Vertices) + " vertices and " +
      std::to_string(header.Faces) + " faces, more than a " + std::to_string(fileSize) +
      "-byte file can hold");
  }
}

OffHeader ReadHeader(TextScanner& scanner, std::size_t fileSize)
{
  if (!scanner.NextLine())
  {
    throw MeshReadError("not an OFF file: it has no keyword " + std::string(KeywordHelp));
  }
  std::string_view glued;
  OffHeader header = ReadKeyword(scanner.NextToken(), glued, scanner);
  std::string_view token = glued.empty() ? scanner.NextToken() : glued;
  if (token == "BINARY")
  {
    scanner.Fail("binary OFF is not supported");
  }
  if (token.empty() && !scanner.NextLine())
  {
    throw MeshReadError("truncated: the file ends before the vertex and face counts",
      vtkErrorCode::PrematureEndOfFileError);
  }
  header.Vertices = ReadCount(token.empty() ? scanner.NextToken() : token, "vertex", scanner);
  header.Faces = ReadCount(scanner.NextToken(), "face", scanner);
  const std::string_view edges = scanner.NextToken();
  if (!edges.empty())
  {
    ReadCount(edges, "edge", scanner);
  }
  scanner.ExpectLineEnd("the counts");
  CheckCounts(header, fileSize);
  return header;
}

[[noreturn]] void Truncated(std::uint64_t declared, const char* kinds, std::uint64_t found)
{
  throw MeshReadError("truncated: the header declares " + std::to_string(declared) + " " + kinds +
      " but the file ends after " + std::to_string(found),
    vtkErrorCode::PrematureEndOfFileError);
}

// A vertex line is x y z [nx ny nz] [r g b [a]] [s t]: the number of colour
// values on a line of `count` values (0, 3 or 4), or -1 if it fits none.
int ColorValues(const OffHeader& header, std::size_t count)
{
  const std::size_t fixed = 3 + (header.Normals ? 3 : 0) + (header.TextureCoordinates ? 2 : 0);
  if (!header.Colors)
  {
    return count == fixed ? 0 : -1;
  }
  return count == fixed + 3 ? 3 : count == fixed + 4 ? 4 : -1;
}

std::string DescribeVertex(const OffHeader& header)
{
  return std::string("x y z") + (header.Normals ? " nx ny nz" : "") +
    (header.Colors ? " r g b [a]" : "") + (header.TextureCoordinates ? " s t" : "");
}

// Whether a colour value is written as a float ("0.5", "1e-1") rather than
// an integer: Geomview's rule for 0..1 against 0..255.
bool WrittenAsFloat(std::string_view token)
{
  return token.find_first_of(".eE") != std::string_view::npos;
}

// The alpha of a vertex with r g b only, until the scale is known: no value
// read can be NaN (ReadVertex refuses them).
constexpr float NoAlpha = std::numeric_limits<float>::quiet_NaN();

struct Parsed
{
  shadelab::PolygonMesh Mesh;
  bool FloatColors = false;
};

void ReadVertex(TextScanner& scanner, const OffHeader& header, std::uint64_t v, Parsed& parsed)
{
  constexpr std::size_t maxValues = 12; // x y z, nx ny nz, r g b a, s t
  std::string_view tokens[maxValues + 1];
  std::size_t count = 0;
  for (std::string_view token = scanner.NextToken(); !token.empty(); token = scanner.NextToken())
  {
    tokens[std::min(count, maxValues)] = token;
    ++count;
  }
  const int colorValues = ColorValues(header, count);
  if (colorValues < 0)
  {
    scanner.Fail("vertex " + std::to_string(v) + " has " + std::to_string(count) + " values, not " +
      DescribeVertex(header));
  }
  double values[maxValues];
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!shadelab::ParseNumber(tokens[k], values[k]))
    {
      scanner.Fail("malformed number " + Quote(tokens[k]) + " in vertex " + std::to_string(v));
    }
    if (!std::isfinite(values[k]))
    {
      scanner.Fail(std::string(std::isnan(values[k]) ? "NaN" : "infinite") + " value " +
        Quote(tokens[k]) + " in vertex " + std::to_string(v));
    }
  }
  shadelab::PolygonMesh& mesh = parsed.Mesh;
  const double* value = values;
  mesh.Points.insert(mesh.Points.end(), value, value + 3);
  value += 3;
  if (header.Normals)
  {
    mesh.Normals.insert(mesh.Normals.end(), value, value + 3);
    value += 3;
  }
  if (header.Colors)
  {
    for (int c = 0; c < colorValues; ++c)
    {
      parsed.FloatColors = parsed.FloatColors || WrittenAsFloat(tokens[value - values + c]);
    }
    mesh.Colors.insert(mesh.Colors.end(), value, value + colorValues);
    if (colorValues == 3)
    {
      mesh.Colors.push_back(NoAlpha); // opaque, set once the scale is known
    }
    value += colorValues;
  }
  if (header.TextureCoordinates)
  {
    mesh.TextureCoordinates.insert(mesh.TextureCoordinates.end(), value, value + 2);
  }
}

void ReadFace(TextScanner& scanner, const OffHeader& header, std::uint64_t f, Parsed& parsed)
{
  const std::string name = "face " + std::to_string(f);
  const long long size = scanner.ReadInteger((name + "'s vertex count").c_str());
  if (size < 3)
  {
    scanner.Fail(name + " has " + std::to_string(size) + " vertices, at least 3 are needed");
  }
  shadelab::PolygonMesh& mesh = parsed.Mesh;
  for (long long k = 0; k < size; ++k)
  {
    const std::string_view token = scanner.NextToken();
    long long index = 0;
    if (token.empty())
    {
      scanner.Fail(name + " ends after " + std::to_string(k) + " of its " + std::to_string(size) +
        " vertex indices");
    }
    if (!shadelab::ParseNumber(token, index))
    {
      scanner.Fail("malformed vertex index " + Quote(token) + " in " + name);
    }
    if (index < 0 || static_cast<std::uint64_t>(index) >= header.Vertices)
    {
      scanner.Fail(name + " refers to vertex " + std::to_string(index) + ", but only " +
        std::to_string(header.Vertices) + " vertices are defined");
    }
    mesh.FaceIds.push_back(static_cast<vtkIdType>(index));
  }
  mesh.FaceOffsets.push_back(static_cast<vtkIdType>(mesh.FaceIds.size()));
  // The face's colour, ignored: none, a colour-map index, or r g b [a].
  int colorValues = 0;
  for (std::string_view token = scanner.NextToken(); !token.empty(); token = scanner.NextToken())
  {
    double value;
    if (!shadelab::ParseNumber(token, value))
    {
      scanner.Fail("malformed colour value " + Quote(token) + " after " + name + "'s vertices");
    }
    ++colorValues;
  }
  if (colorValues == 2 || colorValues > 4)
  {
    scanner.Fail(name + " has " + std::to_string(colorValues) +
      " values after its vertex indices; a face colour has 1, 3 or 4");
  }
}

// The colours in 0..1: integers were 0..255. Throws on one out of range.
void ScaleColors(Parsed& parsed)
{
  const float top = parsed.FloatColors ? 1.0f : 255.0f;
  std::vector<float>& colors = parsed.Mesh.Colors;
  for (std::size_t i = 0; i < colors.size(); ++i)
  {
    if (std::isnan(colors[i]))
    {
      colors[i] = 1.0f;
      continue;
    }
    if (!(colors[i] >= 0.0f && colors[i] <= top))
    {
      std::ostringstream value;
      value << colors[i];
      throw MeshReadError("colour of vertex " + std::to_string(i / 4) + " has " + value.str() +
        (parsed.FloatColors ? ", outside 0..1 (the file writes its colours as fractions)"
                            : ", outside 0..255 (the file writes its colours as integers)"));
    }
    colors[i] /= top;
  }
}
}

void vtkShadelabOFFReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const std::string bytes = ReadFileBytes(fileName);
  TextScanner scanner(bytes, '#');
  const OffHeader header = ReadHeader(scanner, bytes.size());

  Parsed parsed;
  shadelab::PolygonMesh& mesh = parsed.Mesh;
  mesh.Points.reserve(3 * header.Vertices);
  mesh.Normals.reserve(header.Normals ? 3 * header.Vertices : 0);
  mesh.Colors.reserve(header.Colors ? 4 * header.Vertices : 0);
  mesh.TextureCoordinates.reserve(header.TextureCoordinates ? 2 * header.Vertices : 0);
  mesh.FaceOffsets.reserve(header.Faces + 1);
  mesh.FaceIds.reserve(3 * header.Faces);
  for (std::uint64_t v = 0; v < header.Vertices; ++v)
  {
    if (!scanner.NextLine())
    {
      Truncated(header.Vertices, "vertices", v);
    }
    ReadVertex(scanner, header, v, parsed);
  }
  for (std::uint64_t f = 0; f < header.Faces; ++f)
  {
    if (!scanner.NextLine())
    {
      Truncated(header.Faces, "faces", f);
    }
    ReadFace(scanner, header, f, parsed);
  }
  if (scanner.NextLine())
  {
    scanner.Fail("more than the " + std::to_string(header.Faces) + " faces the header declares");
  }
  ScaleColors(parsed);
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(std::move(mesh)), triangles);
}
