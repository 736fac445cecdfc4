/**
 * @brief   the header of a PLY file: its format, elements and properties
 *
 * ReadHeader parses the header's lines, AssignRoles says what the reader
 * does with each element and property, and CheckCounts refuses counts that
 * the file could not hold, before anything is allocated for them.
 */
#ifndef shadelabPLYHeader_h
#define shadelabPLYHeader_h

#include "shadelabScalarType.h"
#include "shadelabTextScanner.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab::ply
{
using Scalar = ScalarType;

// What the reader does with a property's values; X .. Alpha in this order.
enum class Use
{
  Skip,
  X,
  Y,
  Z,
  NX,
  NY,
  NZ,
  Red,
  Green,
  Blue,
  Alpha,
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

/**
 * A file whose lines end in a bare CR (Rhinoceros 6's exports): its
 * header's CRs become LFs in place, and an ASCII body's too (the same
 * length, so every offset stays); a binary body is left as it is. Files
 * whose lines end in LF or CRLF are left alone.
 */
void NewlinesForBareCarriageReturns(std::string& bytes);

/** Reads the header's lines and leaves `scanner` before the body's first line. */
Header ReadHeader(std::string_view bytes, TextScanner& scanner);

/**
 * Marks the vertex element's x, y, z (and nx, ny, nz when all three are
 * there; red, green, blue and an optional alpha likewise) and the index lists of face and tristrips
 * elements; throws MeshReadError on a header that lacks them or has them twice.
 */
void AssignRoles(Header& header);

/** Throws MeshReadError on a count that a file of `fileSize` bytes could not hold. */
void CheckCounts(const Header& header, std::size_t fileSize);

/** Throws "truncated: header declares N <element>s but the file ends after M". */
[[noreturn]] void Truncated(const Element& element, std::uint64_t items);

}

#endif
