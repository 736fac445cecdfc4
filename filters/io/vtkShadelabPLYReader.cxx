#include "vtkShadelabPLYReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabScalarType.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

vtkStandardNewMacro(vtkShadelabPLYReader);

namespace
{
using shadelab::MeshReadError;
using shadelab::Quote;
using shadelab::TextScanner;

using Scalar = shadelab::ScalarType;
using shadelab::IsInteger;
using shadelab::SizeOf;

// Every PLY scalar is read as a double; a count or an index converts to an
// integer only where int64 holds it (a uint64 can say 1.8e19, and the cast
// of a double beyond the range is undefined: a finding of fuzz_ply).
bool FitsInt64(double value)
{
  return value >= -0x1p63 && value < 0x1p63;
}

struct ScalarName
{
  std::string_view Name;
  Scalar Type;
};

constexpr ScalarName ScalarNames[] = { { "char", Scalar::Int8 }, { "int8", Scalar::Int8 },
  { "uchar", Scalar::UInt8 }, { "uint8", Scalar::UInt8 }, { "short", Scalar::Int16 },
  { "int16", Scalar::Int16 }, { "ushort", Scalar::UInt16 }, { "uint16", Scalar::UInt16 },
  { "int", Scalar::Int32 }, { "int32", Scalar::Int32 }, { "uint", Scalar::UInt32 },
  { "uint32", Scalar::UInt32 }, { "float", Scalar::Float32 }, { "float32", Scalar::Float32 },
  { "double", Scalar::Float64 }, { "float64", Scalar::Float64 } };

// What the reader does with a property's values; X .. NZ in this order.
enum class Use
{
  Skip,
  X,
  Y,
  Z,
  NX,
  NY,
  NZ,
  Indices
};

struct Property
{
  std::string Name;
  Scalar Type = Scalar::Float32;
  bool IsList = false;
  Scalar CountType = Scalar::UInt8;
  Use Role = Use::Skip;
};

enum class Kind
{
  Other,
  Vertex,
  Face,
  Strips
};

struct Element
{
  std::string Name;
  std::uint64_t Count = 0;
  std::vector<Property> Properties;
  Kind Role = Kind::Other;
};

enum class Encoding
{
  Ascii,
  LittleEndian,
  BigEndian
};

struct Header
{
  Encoding Format = Encoding::Ascii;
  std::vector<Element> Elements;
};

std::string Plural(const std::string& name)
{
  if (name == "vertex")
  {
    return "vertices";
  }
  return !name.empty() && name.back() == 's' ? name : name + "s";
}

Scalar ToScalar(std::string_view token, const TextScanner& scanner)
{
  for (const ScalarName& entry : ScalarNames)
  {
    if (token == entry.Name)
    {
      return entry.Type;
    }
  }
  scanner.Fail(token.empty() ? "missing property type" : "unknown property type " + Quote(token));
}

// Reads the header's lines and leaves `scanner` before the body's first line.
Header ReadHeader(std::string_view bytes, TextScanner& scanner)
{
  if (bytes.substr(0, 4) != "ply\n" && bytes.substr(0, 5) != "ply\r\n")
  {
    throw MeshReadError("not a PLY file: the first line is not \"ply\"");
  }
  scanner.NextLine();
  Header header;
  bool hasFormat = false;
  while (scanner.NextLine())
  {
    const std::string_view keyword = scanner.NextToken();
    if (keyword == "comment" || keyword == "obj_info")
    {
      continue;
    }
    if (keyword == "format")
    {
      const std::string_view name = scanner.NextToken();
      if (name == "ascii")
      {
        header.Format = Encoding::Ascii;
      }
      else if (name == "binary_little_endian")
      {
        header.Format = Encoding::LittleEndian;
      }
      else if (name == "binary_big_endian")
      {
        header.Format = Encoding::BigEndian;
      }
      else
      {
        scanner.Fail("unknown PLY format " + Quote(name));
      }
      const std::string_view version = scanner.NextToken();
      if (version != "1.0")
      {
        scanner.Fail("unsupported PLY version " + Quote(version));
      }
      scanner.ExpectLineEnd("the format");
      hasFormat = true;
    }
    else if (keyword == "element")
    {
      Element element;
      element.Name = std::string(scanner.NextToken());
      const long long count = scanner.ReadInteger("element count");
      if (count < 0)
      {
        scanner.Fail("negative element count");
      }
      element.Count = static_cast<std::uint64_t>(count);
      scanner.ExpectLineEnd("the element count");
      header.Elements.push_back(std::move(element));
    }
    else if (keyword == "property")
    {
      if (header.Elements.empty())
      {
        scanner.Fail("property before any element");
      }
      Property property;
      const std::string_view type = scanner.NextToken();
      if (type == "list")
      {
        property.IsList = true;
        property.CountType = ToScalar(scanner.NextToken(), scanner);
        property.Type = ToScalar(scanner.NextToken(), scanner);
      }
      else
      {
        property.Type = ToScalar(type, scanner);
      }
      property.Name = std::string(scanner.NextToken());
      if (property.Name.empty())
      {
        scanner.Fail("missing property name");
      }
      scanner.ExpectLineEnd("the property name");
      header.Elements.back().Properties.push_back(std::move(property));
    }
    else if (keyword == "end_header")
    {
      scanner.ExpectLineEnd("end_header");
      if (!hasFormat)
      {
        scanner.Fail("end_header before any format line");
      }
      return header;
    }
    else
    {
      scanner.Fail("unknown header line " + Quote(keyword));
    }
  }
  throw MeshReadError("the header has no end_header line");
}

void AssignVertexRoles(Element& element)
{
  constexpr std::string_view names[] = { "x", "y", "z", "nx", "ny", "nz" };
  int found[6] = {};
  for (Property& property : element.Properties)
  {
    for (int k = 0; k < 6; ++k)
    {
      if (property.Name == names[k])
      {
        if (property.IsList)
        {
          throw MeshReadError("vertex property '" + property.Name + "' is a list");
        }
        property.Role = static_cast<Use>(static_cast<int>(Use::X) + k);
        ++found[k];
      }
    }
  }
  for (int k = 0; k < 6; ++k)
  {
    if (found[k] > 1)
    {
      throw MeshReadError("vertex property '" + std::string(names[k]) + "' appears twice");
    }
  }
  if (!found[0] || !found[1] || !found[2])
  {
    throw MeshReadError("the vertex element lacks x, y or z");
  }
  const bool hasNormals = found[3] && found[4] && found[5];
  for (Property& property : element.Properties)
  {
    if (!hasNormals && property.Role >= Use::NX)
    {
      property.Role = Use::Skip; // a partial normal is no normal
    }
  }
}

void AssignIndexRole(Element& element)
{
  for (Property& property : element.Properties)
  {
    if (property.IsList &&
      (property.Name == "vertex_indices" ||
        (element.Role == Kind::Face && property.Name == "vertex_index")))
    {
      if (!IsInteger(property.CountType) || !IsInteger(property.Type))
      {
        throw MeshReadError(
          "the " + element.Name + " list '" + property.Name + "' does not hold integers");
      }
      property.Role = Use::Indices;
      return;
    }
  }
  throw MeshReadError("the " + element.Name + " element has no vertex_indices list");
}

void AssignRoles(Header& header)
{
  bool hasVertex = false;
  for (Element& element : header.Elements)
  {
    if (element.Properties.empty())
    {
      throw MeshReadError("element '" + element.Name + "' has no properties");
    }
    if (element.Name == "vertex")
    {
      if (hasVertex)
      {
        throw MeshReadError("two vertex elements");
      }
      hasVertex = true;
      element.Role = Kind::Vertex;
      AssignVertexRoles(element);
    }
    else if (element.Name == "face" || element.Name == "tristrips")
    {
      element.Role = element.Name == "face" ? Kind::Face : Kind::Strips;
      AssignIndexRole(element);
    }
  }
  if (!hasVertex)
  {
    throw MeshReadError("no vertex element");
  }
}

// Each item needs at least its fixed bytes (binary: scalars and list counts)
// or, in ASCII, a character and a separator per property. A count that the
// whole file could not hold is refused before anything is allocated for it;
// a file that is merely cut short is reported as truncated while reading.
void CheckCounts(const Header& header, std::size_t fileSize)
{
  for (const Element& element : header.Elements)
  {
    std::uint64_t itemBytes = 0;
    for (const Property& property : element.Properties)
    {
      itemBytes += header.Format == Encoding::Ascii
        ? 2
        : SizeOf(property.IsList ? property.CountType : property.Type);
    }
    if (element.Count > fileSize / itemBytes)
    {
      throw MeshReadError("header declares " + std::to_string(element.Count) + " " +
        Plural(element.Name) + ", more than a " + std::to_string(fileSize) + "-byte file can hold");
    }
  }
}

[[noreturn]] void Truncated(const Element& element, std::uint64_t items)
{
  throw MeshReadError("truncated: header declares " + std::to_string(element.Count) + " " +
      Plural(element.Name) + " but the file ends after " + std::to_string(items),
    vtkErrorCode::PrematureEndOfFileError);
}

class BinarySource
{
public:
  BinarySource(std::string_view body, bool bigEndian)
    : Position(reinterpret_cast<const unsigned char*>(body.data()))
    , End(Position + body.size())
    , BigEndian(bigEndian)
  {
  }

  bool BeginItem() { return true; }
  void EndItem() {}

  /** False when the file ends first. */
  bool Read(Scalar type, double& value)
  {
    const std::size_t size = SizeOf(type);
    if (static_cast<std::size_t>(this->End - this->Position) < size)
    {
      return false;
    }
    value = shadelab::LoadScalar(this->Position, type, this->BigEndian);
    this->Position += size;
    return true;
  }

  bool Skip(Scalar type, std::uint64_t count)
  {
    const std::uint64_t left = static_cast<std::uint64_t>(this->End - this->Position);
    if (count > left / SizeOf(type))
    {
      return false;
    }
    this->Position += count * SizeOf(type);
    return true;
  }

  /** Skips a whole element by its sizes: in one step when it has no lists. */
  void SkipItems(const Element& element)
  {
    const bool fixed = std::none_of(element.Properties.begin(), element.Properties.end(),
      [](const Property& property) { return property.IsList; });
    if (fixed)
    {
      std::uint64_t itemBytes = 0;
      for (const Property& property : element.Properties)
      {
        itemBytes += SizeOf(property.Type);
      }
      const std::uint64_t left = static_cast<std::uint64_t>(this->End - this->Position);
      if (element.Count * itemBytes > left) // no overflow: CheckCounts bounded the product
      {
        Truncated(element, left / itemBytes);
      }
      this->Position += element.Count * itemBytes;
      return;
    }
    double length = 0;
    for (std::uint64_t i = 0; i < element.Count; ++i)
    {
      for (const Property& property : element.Properties)
      {
        const bool ok = property.IsList
          ? this->Read(property.CountType, length) && FitsInt64(length) && length >= 0 &&
            this->Skip(property.Type, static_cast<std::uint64_t>(length))
          : this->Skip(property.Type, 1);
        if (!ok)
        {
          Truncated(element, i);
        }
      }
    }
  }

private:
  const unsigned char* Position;
  const unsigned char* End;
  bool BigEndian;
};

class AsciiSource
{
public:
  explicit AsciiSource(TextScanner& scanner)
    : Scanner(scanner)
  {
  }

  /** An item is one line; false when the text ends first. */
  bool BeginItem() { return this->Scanner.NextLine(); }
  void EndItem() { this->Scanner.ExpectLineEnd("the values the header declares"); }

  bool Read(Scalar type, double& value)
  {
    value = IsInteger(type) ? static_cast<double>(this->Scanner.ReadInteger("integer value"))
                            : this->Scanner.ReadDouble("number");
    return true;
  }

  bool Skip(Scalar type, std::uint64_t count)
  {
    double value;
    for (std::uint64_t k = 0; k < count; ++k)
    {
      this->Read(type, value);
    }
    return true;
  }

  /** Skips a whole element: one line per item. */
  void SkipItems(const Element& element)
  {
    for (std::uint64_t i = 0; i < element.Count; ++i)
    {
      if (!this->Scanner.NextLine())
      {
        Truncated(element, i);
      }
    }
  }

private:
  TextScanner& Scanner;
};

template <class Source>
void ReadElement(Source& source, const Element& element, shadelab::PolygonMesh& mesh)
{
  if (element.Role == Kind::Other)
  {
    source.SkipItems(element);
    return;
  }
  const bool strips = element.Role == Kind::Strips;
  std::vector<vtkIdType>& offsets = strips ? mesh.StripOffsets : mesh.FaceOffsets;
  std::vector<vtkIdType>& ids = strips ? mesh.StripIds : mesh.FaceIds;
  const bool hasNormals = std::any_of(element.Properties.begin(), element.Properties.end(),
    [](const Property& property) { return property.Role == Use::NX; });
  if (element.Role == Kind::Vertex)
  {
    mesh.Points.reserve(3 * element.Count);
    mesh.Normals.reserve(hasNormals ? 3 * element.Count : 0);
  }
  else
  {
    offsets.reserve(offsets.size() + element.Count);
  }
  const auto endStrip = [&]
  {
    if (static_cast<vtkIdType>(ids.size()) > offsets.back())
    {
      offsets.push_back(static_cast<vtkIdType>(ids.size()));
    }
  };

  double vertex[6] = {}; // x y z nx ny nz, indexed by Use - Use::X
  double value = 0;
  for (std::uint64_t i = 0; i < element.Count; ++i)
  {
    if (!source.BeginItem())
    {
      Truncated(element, i);
    }
    for (const Property& property : element.Properties)
    {
      if (!property.IsList)
      {
        if (!source.Read(property.Type, value))
        {
          Truncated(element, i);
        }
        if (property.Role != Use::Skip)
        {
          vertex[static_cast<int>(property.Role) - static_cast<int>(Use::X)] = value;
        }
        continue;
      }
      if (!source.Read(property.CountType, value))
      {
        Truncated(element, i);
      }
      if (value < 0)
      {
        throw MeshReadError(element.Name + " " + std::to_string(i) + " has a negative list length");
      }
      if (!FitsInt64(value))
      {
        Truncated(element, i); // a list that long cannot be in the file
      }
      const auto length = static_cast<std::uint64_t>(value);
      if (property.Role != Use::Indices)
      {
        if (!source.Skip(property.Type, length))
        {
          Truncated(element, i);
        }
        continue;
      }
      for (std::uint64_t k = 0; k < length; ++k)
      {
        if (!source.Read(property.Type, value))
        {
          Truncated(element, i);
        }
        if (strips && value == -1)
        {
          endStrip();
        }
        else
        {
          // Beyond int64 (a uint64 index can say 1.8e19): out of range as -1 is.
          ids.push_back(FitsInt64(value) ? static_cast<vtkIdType>(value) : vtkIdType{ -1 });
        }
      }
    }
    source.EndItem();
    if (element.Role == Kind::Vertex)
    {
      mesh.Points.insert(mesh.Points.end(), vertex, vertex + 3);
      if (hasNormals)
      {
        mesh.Normals.insert(mesh.Normals.end(), vertex + 3, vertex + 6);
      }
    }
    else if (strips)
    {
      endStrip();
    }
    else
    {
      offsets.push_back(static_cast<vtkIdType>(ids.size()));
    }
  }
}
}

void vtkShadelabPLYReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const std::string bytes = ReadFileBytes(fileName);
  TextScanner scanner(bytes);
  Header header = ReadHeader(bytes, scanner);
  AssignRoles(header);
  CheckCounts(header, bytes.size());

  shadelab::PolygonMesh mesh;
  if (header.Format == Encoding::Ascii)
  {
    AsciiSource source(scanner);
    for (const Element& element : header.Elements)
    {
      ReadElement(source, element, mesh);
    }
  }
  else
  {
    const std::string_view body = std::string_view(bytes).substr(scanner.GetNextLineOffset());
    BinarySource source(body, header.Format == Encoding::BigEndian);
    for (const Element& element : header.Elements)
    {
      ReadElement(source, element, mesh);
    }
  }
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(mesh), triangles);
}
