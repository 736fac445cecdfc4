#include "shadelabPLYPlainBody.h"

#include "shadelabPLYBinarySource.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace shadelab::ply
{
namespace
{
bool IsSmallInteger(Scalar type)
{
  return IsInteger(type) && SizeOf(type) <= 4;
}

bool IsPlainVertex(const Element& element)
{
  return std::all_of(element.Properties.begin(), element.Properties.end(),
    [](const Property& property)
    {
      return !property.IsList &&
        (property.Role == Use::Skip ||
          (property.Role >= Use::X && property.Role <= Use::Z && property.Type == Scalar::Float32));
    });
}

bool IsPlainFace(const Element& element)
{
  if (element.Properties.size() != 1)
  {
    return false;
  }
  const Property& list = element.Properties.front();
  return list.IsList && list.Role == Use::Indices && IsSmallInteger(list.CountType) &&
    IsSmallInteger(list.Type);
}

// One vertex element, plain, and one face element, plain; others skipped.
bool IsPlain(const Header& header)
{
  int vertices = 0;
  int faces = 0;
  for (const Element& element : header.Elements)
  {
    switch (element.Role)
    {
      case Kind::Vertex:
        vertices += IsPlainVertex(element) ? 1 : 2;
        break;
      case Kind::Face:
        faces += IsPlainFace(element) ? 1 : 2;
        break;
      case Kind::Strips:
        return false;
      case Kind::Other:
        break;
    }
  }
  return header.Format != Encoding::Ascii && vertices == 1 && faces == 1;
}

// The vertex element's x y z as float; false where the body ends first.
bool ReadPoints(std::string_view& body, const Element& element, bool bigEndian, vtkPoints* points)
{
  std::size_t itemBytes = 0;
  std::size_t offset[3] = { 0, 0, 0 };
  for (const Property& property : element.Properties)
  {
    if (property.Role != Use::Skip)
    {
      offset[static_cast<int>(property.Role) - static_cast<int>(Use::X)] = itemBytes;
    }
    itemBytes += SizeOf(property.Type);
  }
  if (element.Count > body.size() / itemBytes)
  {
    return false;
  }
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(static_cast<vtkIdType>(element.Count));
  float* out = xyz->GetPointer(0);
  const auto* item = reinterpret_cast<const unsigned char*>(body.data());
  for (std::uint64_t i = 0; i < element.Count; ++i, item += itemBytes)
  {
    for (int c = 0; c < 3; ++c)
    {
      *out++ = LoadValue<float>(item + offset[c], bigEndian);
    }
  }
  points->SetData(xyz);
  body.remove_prefix(element.Count * itemBytes);
  return true;
}

// The face element's lists as 32-bit offsets and ids, for a list of
// Count values of type Index each; false where the body ends first or a
// value does not fit.
template <typename Count, typename Index>
bool ReadFaces(std::string_view& body, std::uint64_t faces, bool bigEndian, vtkCellArray* cells)
{
  constexpr auto largest = std::numeric_limits<vtkTypeInt32>::max();
  const auto* in = reinterpret_cast<const unsigned char*>(body.data());
  const auto* const end = in + body.size();
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(faces + 1));
  vtkTypeInt32* offset = offsets->GetPointer(0);
  *offset++ = 0;
  // Triangles, most often; more room is made if the lists are longer.
  vtkNew<vtkTypeInt32Array> ids;
  vtkIdType room = static_cast<vtkIdType>(std::min<std::uint64_t>(3 * faces, largest));
  ids->SetNumberOfValues(room);
  vtkTypeInt32* id = ids->GetPointer(0);
  vtkIdType used = 0;
  for (std::uint64_t f = 0; f < faces; ++f)
  {
    if (static_cast<std::size_t>(end - in) < sizeof(Count))
    {
      return false;
    }
    const Count count = LoadValue<Count>(in, bigEndian);
    in += sizeof(Count);
    const auto length = static_cast<vtkIdType>(count);
    if (length < 0 || length > largest - used ||
      static_cast<std::size_t>(end - in) / sizeof(Index) < static_cast<std::size_t>(length))
    {
      return false;
    }
    if (used + length > room)
    {
      room = std::min<vtkIdType>(std::max(2 * room, used + length), largest);
      ids->Resize(room);
      id = ids->GetPointer(0) + used;
    }
    for (vtkIdType k = 0; k < length; ++k, in += sizeof(Index))
    {
      const Index value = LoadValue<Index>(in, bigEndian);
      if constexpr (std::is_same_v<Index, std::uint32_t>)
      {
        if (value > static_cast<std::uint32_t>(largest))
        {
          return false;
        }
      }
      *id++ = static_cast<vtkTypeInt32>(value);
    }
    used += length;
    *offset++ = static_cast<vtkTypeInt32>(used);
  }
  ids->SetNumberOfValues(used);
  cells->SetData(offsets, ids);
  body.remove_prefix(
    static_cast<std::size_t>(in - reinterpret_cast<const unsigned char*>(body.data())));
  return true;
}

// Calls `read` with a value of the integer type that `type` names (at most
// 32 bits: IsPlainFace checked it).
template <typename Read>
bool WithInteger(Scalar type, Read&& read)
{
  switch (type)
  {
    case Scalar::Int8:
      return read(std::int8_t{});
    case Scalar::UInt8:
      return read(std::uint8_t{});
    case Scalar::Int16:
      return read(std::int16_t{});
    case Scalar::UInt16:
      return read(std::uint16_t{});
    case Scalar::Int32:
      return read(std::int32_t{});
    case Scalar::UInt32:
      return read(std::uint32_t{});
    case Scalar::Int64:
    case Scalar::UInt64:
    case Scalar::Float32:
    case Scalar::Float64:
      break; // not a plain face's (IsPlainFace)
  }
  return false;
}

bool ReadFaceElement(
  std::string_view& body, const Element& element, bool bigEndian, vtkCellArray* cells)
{
  const Property& list = element.Properties.front();
  return WithInteger(list.CountType,
    [&](auto count)
    {
      return WithInteger(list.Type,
        [&](auto index) {
          return ReadFaces<decltype(count), decltype(index)>(body, element.Count, bigEndian, cells);
        });
    });
}
}

vtkSmartPointer<vtkPolyData> ReadPlainBody(std::string_view body, const Header& header)
{
  if (!IsPlain(header))
  {
    return nullptr;
  }
  const bool bigEndian = header.Format == Encoding::BigEndian;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> faces;
  for (const Element& element : header.Elements)
  {
    bool read = true;
    if (element.Role == Kind::Vertex)
    {
      read = ReadPoints(body, element, bigEndian, points);
    }
    else if (element.Role == Kind::Face)
    {
      read = ReadFaceElement(body, element, bigEndian, faces);
    }
    else
    {
      BinarySource source(body, bigEndian);
      source.SkipItems(element); // throws as the general parser would here
      body = source.Rest();
    }
    if (!read)
    {
      return nullptr;
    }
  }
  auto polygons = vtkSmartPointer<vtkPolyData>::New();
  polygons->SetPoints(points);
  polygons->SetPolys(faces);
  return polygons;
}
}
