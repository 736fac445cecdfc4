#include "shadelabPLYHeader.h"

#include "shadelabMeshReadError.h"

#include <algorithm>
#include <cstring>

namespace shadelab::ply
{
namespace
{
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

// The rest of a "format" line: the encoding, then version 1.0.
Encoding ReadFormatLine(TextScanner& scanner)
{
  const std::string_view name = scanner.NextToken();
  Encoding format = Encoding::Ascii;
  if (name == "ascii")
  {
    format = Encoding::Ascii;
  }
  else if (name == "binary_little_endian")
  {
    format = Encoding::LittleEndian;
  }
  else if (name == "binary_big_endian")
  {
    format = Encoding::BigEndian;
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
  return format;
}

// The rest of an "element" line: its name and count.
Element ReadElementLine(TextScanner& scanner)
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
  return element;
}

// The rest of a "property" line: a scalar type or "list" and two types,
// then the name.
Property ReadPropertyLine(TextScanner& scanner)
{
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
  return property;
}

void AssignVertexRoles(Element& element)
{
  constexpr std::string_view names[] = { "x", "y", "z", "nx", "ny", "nz", "red", "green", "blue",
    "alpha" };
  constexpr int count = static_cast<int>(std::size(names));
  int found[count] = {};
  for (Property& property : element.Properties)
  {
    for (int k = 0; k < count; ++k)
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
  for (int k = 0; k < count; ++k)
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
  const bool hasColors = found[6] && found[7] && found[8];
  for (Property& property : element.Properties)
  {
    // A partial normal is no normal, a partial colour no colour.
    if ((!hasNormals && property.Role >= Use::NX && property.Role <= Use::NZ) ||
      (!hasColors && property.Role >= Use::Red && property.Role <= Use::Alpha))
    {
      property.Role = Use::Skip;
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

}

void NewlinesForBareCarriageReturns(std::string& bytes)
{
  if (bytes.compare(0, 4, "ply\r") != 0 || bytes.compare(0, 5, "ply\r\n") == 0)
  {
    return;
  }
  const std::size_t endHeader = bytes.find("\rend_header\r");
  const std::size_t headerEnd =
    endHeader == std::string::npos ? bytes.size() : endHeader + std::strlen("\rend_header\r");
  const bool ascii = bytes.find("\rformat ascii ") < headerEnd;
  std::replace(bytes.begin(),
    ascii ? bytes.end() : bytes.begin() + static_cast<std::ptrdiff_t>(headerEnd), '\r', '\n');
}

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
      header.Format = ReadFormatLine(scanner);
      hasFormat = true;
    }
    else if (keyword == "element")
    {
      header.Elements.push_back(ReadElementLine(scanner));
    }
    else if (keyword == "property")
    {
      if (header.Elements.empty())
      {
        scanner.Fail("property before any element");
      }
      header.Elements.back().Properties.push_back(ReadPropertyLine(scanner));
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
}
