#include "vtkShadelabPLYReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabPLYAsciiSource.h"
#include "shadelabPLYBinarySource.h"
#include "shadelabPLYHeader.h"
#include "shadelabPLYPlainBody.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkShadelabPLYReader);

namespace
{
using namespace shadelab::ply;
using shadelab::FitsInt64;
using shadelab::MeshReadError;

// Where the items of a vertex, face or tristrips element go in the mesh.
class ElementTarget
{
public:
  ElementTarget(const Element& element, shadelab::PolygonMesh& mesh)
    : Mesh(mesh)
    , Role(element.Role)
    , Offsets(element.Role == Kind::Strips ? mesh.StripOffsets : mesh.FaceOffsets)
    , Ids(element.Role == Kind::Strips ? mesh.StripIds : mesh.FaceIds)
    , HasNormals(Has(element, Use::NX))
    , HasColors(Has(element, Use::Red))
  {
    if (this->Role == Kind::Vertex)
    {
      mesh.Points.reserve(3 * element.Count);
      mesh.Normals.reserve(this->HasNormals ? 3 * element.Count : 0);
      mesh.Colors.reserve(this->HasColors ? 4 * element.Count : 0);
    }
    else
    {
      this->Offsets.reserve(this->Offsets.size() + element.Count);
      // Triangles, most often: the ids then never move while they grow.
      this->Ids.reserve(this->Ids.size() + (this->Role == Kind::Face ? 3 * element.Count : 0));
    }
  }

  /**
   * A vertex property's value of `type`: x y z nx ny nz red green blue
   * alpha by its Use; an integer colour is a fraction of its type's largest
   * value (uchar 255 is 1).
   */
  void SetCoordinate(Use role, Scalar type, double value)
  {
    if (role >= Use::Red && IsInteger(type))
    {
      value /= LargestValue(type);
    }
    this->Vertex[static_cast<int>(role) - static_cast<int>(Use::X)] = value;
  }

  /** An index of the list; -1 in a strip ends the strip. */
  void AddIndex(double value)
  {
    if (this->Role == Kind::Strips && value == -1)
    {
      this->EndStrip();
    }
    else
    {
      // Beyond int64 (a uint64 index can say 1.8e19): out of range as -1 is.
      this->Ids.push_back(FitsInt64(value) ? static_cast<vtkIdType>(value) : vtkIdType{ -1 });
    }
  }

  /** Adds the item: the vertex, or ends the face or strip. */
  void EndItem()
  {
    if (this->Role == Kind::Vertex)
    {
      this->Mesh.Points.insert(this->Mesh.Points.end(), this->Vertex, this->Vertex + 3);
      if (this->HasNormals)
      {
        this->Mesh.Normals.insert(this->Mesh.Normals.end(), this->Vertex + 3, this->Vertex + 6);
      }
      if (this->HasColors)
      {
        this->Mesh.Colors.insert(this->Mesh.Colors.end(), this->Vertex + 6, this->Vertex + 10);
      }
    }
    else if (this->Role == Kind::Strips)
    {
      this->EndStrip();
    }
    else
    {
      this->Offsets.push_back(static_cast<vtkIdType>(this->Ids.size()));
    }
  }

private:
  static bool Has(const Element& element, Use role)
  {
    return std::any_of(element.Properties.begin(), element.Properties.end(),
      [role](const Property& property) { return property.Role == role; });
  }

  void EndStrip()
  {
    if (static_cast<vtkIdType>(this->Ids.size()) > this->Offsets.back())
    {
      this->Offsets.push_back(static_cast<vtkIdType>(this->Ids.size()));
    }
  }

  shadelab::PolygonMesh& Mesh;
  Kind Role;
  std::vector<vtkIdType>& Offsets;
  std::vector<vtkIdType>& Ids;
  bool HasNormals;
  bool HasColors;
  // x y z nx ny nz red green blue alpha, indexed by Use - Use::X; alpha 1
  // unless the file has it.
  double Vertex[10] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 1 };
};

// A list property of item i: its length, then its values, kept if they are
// the element's indices.
template <class Source>
void ReadList(Source& source, const Element& element, std::uint64_t i, const Property& property,
  ElementTarget& target)
{
  double value = 0;
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
    return;
  }
  for (std::uint64_t k = 0; k < length; ++k)
  {
    if (!source.Read(property.Type, value))
    {
      Truncated(element, i);
    }
    target.AddIndex(value);
  }
}

// Property `property` of item i, kept if the reader uses it.
template <class Source>
void ReadProperty(Source& source, const Element& element, std::uint64_t i, const Property& property,
  ElementTarget& target)
{
  if (property.IsList)
  {
    ReadList(source, element, i, property, target);
    return;
  }
  double value = 0;
  if (!source.Read(property.Type, value))
  {
    Truncated(element, i);
  }
  if (property.Role != Use::Skip)
  {
    target.SetCoordinate(property.Role, property.Type, value);
  }
}

template <class Source>
void ReadElement(Source& source, const Element& element, shadelab::PolygonMesh& mesh)
{
  if (element.Role == Kind::Other)
  {
    source.SkipItems(element);
    return;
  }
  ElementTarget target(element, mesh);
  for (std::uint64_t i = 0; i < element.Count; ++i)
  {
    if (!source.BeginItem())
    {
      Truncated(element, i);
    }
    for (const Property& property : element.Properties)
    {
      ReadProperty(source, element, i, property, target);
    }
    source.EndItem();
    target.EndItem();
  }
}

template <class Source>
void ReadBody(Source&& source, const Header& header, shadelab::PolygonMesh& mesh)
{
  for (const Element& element : header.Elements)
  {
    ReadElement(source, element, mesh);
  }
}
}

void vtkShadelabPLYReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  vtkSmartPointer<vtkPolyData> plain;
  shadelab::PolygonMesh mesh;
  {
    // The file's bytes go before the mesh is converted: not held beside it.
    std::string bytes = ReadFileBytes(fileName);
    NewlinesForBareCarriageReturns(bytes);
    shadelab::TextScanner scanner(bytes);
    Header header = ReadHeader(bytes, scanner);
    AssignRoles(header);
    CheckCounts(header, bytes.size());
    const std::string_view body = std::string_view(bytes).substr(scanner.GetNextLineOffset());
    if (header.Format == Encoding::Ascii)
    {
      ReadBody(AsciiSource(scanner), header, mesh);
    }
    else if (!(plain = ReadPlainBody(body, header)))
    {
      // Binary 32-bit coordinates stay float: exactly the file's values (an
      // ASCII file's decimals are parsed to double, which float would round).
      mesh.FloatPoints = std::all_of(header.Elements.begin(), header.Elements.end(),
        [](const Element& element)
        {
          return element.Role != Kind::Vertex ||
            std::all_of(element.Properties.begin(), element.Properties.end(),
              [](const Property& property) {
                return property.Role < Use::X || property.Role > Use::Z ||
                  property.Type == Scalar::Float32;
              });
        });
      ReadBody(BinarySource(body, header.Format == Encoding::BigEndian), header, mesh);
    }
  }
  shadelab::MakeTriangleMesh(plain ? plain : shadelab::ToPolyData(std::move(mesh)), triangles);
}
