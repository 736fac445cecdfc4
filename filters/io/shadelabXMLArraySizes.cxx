#include "shadelabXMLArraySizes.h"

#include "shadelabMeshReadError.h"
#include "vtkShadelabFileReader.h"

#include <vtkBase64Utilities.h>
#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace shadelab
{
namespace
{
using Bytes = std::uint64_t;
constexpr Bytes Huge = std::numeric_limits<Bytes>::max();

// a * b, or Huge where that overflows: sizes only grow toward a refusal.
Bytes Times(Bytes a, Bytes b)
{
  return (b != 0 && a > Huge / b) ? Huge : a * b;
}

Bytes Plus(Bytes a, Bytes b)
{
  return a > Huge - b ? Huge : a + b;
}

std::string MiB(Bytes bytes)
{
  return std::to_string(bytes >> 20) + " MiB";
}

// An array's encoded data from its first byte to the end of what holds it:
// raw bytes, or base64 characters that decode in groups of four.
class Encoded
{
public:
  Encoded(std::string_view chars, bool base64)
    : Chars(chars)
    , Base64(base64)
  {
  }

  Bytes DecodedSize() const
  {
    return this->Base64 ? this->Chars.size() / 4 * 3 : this->Chars.size();
  }

  /** Decoded bytes [at, at + n) into out; false where they lie past the end. */
  bool Read(Bytes at, Bytes n, unsigned char* out) const
  {
    if (at > this->DecodedSize() || n > this->DecodedSize() - at)
    {
      return false;
    }
    if (!this->Base64)
    {
      std::memcpy(out, this->Chars.data() + at, n);
      return true;
    }
    const Bytes firstGroup = at / 3;
    const Bytes groups = (at + n + 2) / 3 - firstGroup;
    std::vector<unsigned char> decoded(groups * 3);
    const auto* chars = reinterpret_cast<const unsigned char*>(this->Chars.data());
    const std::size_t got = vtkBase64Utilities::DecodeSafely(
      chars + firstGroup * 4, groups * 4, decoded.data(), decoded.size());
    const Bytes skip = at - firstGroup * 3;
    if (got < skip + n)
    {
      return false;
    }
    std::memcpy(out, decoded.data() + skip, n);
    return true;
  }

  /**
   * What follows a stream of `bytes` decoded bytes: VTK starts the
   * compressed blocks as a new stream after the header, which in base64
   * begins at the next group of four characters.
   */
  Encoded After(Bytes bytes) const
  {
    const Bytes skip = this->Base64 ? (bytes + 2) / 3 * 4 : bytes;
    return { this->Chars.substr(std::min<Bytes>(skip, this->Chars.size())), this->Base64 };
  }

private:
  std::string_view Chars;
  bool Base64;
};

// The conventions of the whole file, from its VTKFile element.
struct FileLayout
{
  std::string_view File;
  unsigned HeaderWord = 4;
  bool BigEndian = false;
  vtkSmartPointer<vtkDataCompressor> Compressor;
  std::string_view Appended;
  bool AppendedBase64 = false;
  bool HasAppended = false;
};

Bytes Word(const unsigned char* bytes, unsigned size, bool bigEndian)
{
  Bytes value = 0;
  for (unsigned i = 0; i < size; ++i)
  {
    value |= Bytes(bytes[bigEndian ? i : size - 1 - i]) << (8 * (size - 1 - i));
  }
  return value;
}

// What an array's binary header says: the bytes it decodes to and, when
// compressed, its blocks.
struct Header
{
  Bytes Size = 0;
  Bytes HeaderBytes = 0;
  Bytes BlockSize = 0;
  Bytes LastBlockSize = 0;
  std::vector<Bytes> Blocks;
};

class ArrayProblem : public MeshReadError
{
public:
  ArrayProblem(const std::string& where, const std::string& problem)
    : MeshReadError(where + ": " + problem)
  {
  }
};

std::vector<Bytes> Words(const FileLayout& layout, const Encoded& data, Bytes at, Bytes count,
  const std::string& where, const char* what)
{
  std::vector<unsigned char> raw(count * layout.HeaderWord);
  if (!data.Read(at, raw.size(), raw.data()))
  {
    throw ArrayProblem(where, std::string("its ") + what + " runs past the end of its data");
  }
  std::vector<Bytes> words(count);
  for (Bytes i = 0; i < count; ++i)
  {
    words[i] = Word(raw.data() + i * layout.HeaderWord, layout.HeaderWord, layout.BigEndian);
  }
  return words;
}

Header ReadHeader(const FileLayout& layout, const Encoded& data, const std::string& where)
{
  const Bytes word = layout.HeaderWord;
  Header header;
  if (!layout.Compressor)
  {
    header.HeaderBytes = word;
    header.Size = Words(layout, data, 0, 1, where, "header")[0];
    if (header.Size > data.DecodedSize() - word)
    {
      throw ArrayProblem(where,
        "its header says " + std::to_string(header.Size) + " bytes, but only " +
          std::to_string(data.DecodedSize() - word) + " follow");
    }
    return header;
  }
  const std::vector<Bytes> head = Words(layout, data, 0, 3, where, "compression header");
  const Bytes blocks = head[0];
  header.BlockSize = head[1];
  header.LastBlockSize = head[2];
  if (blocks > (data.DecodedSize() - 3 * word) / word)
  {
    throw ArrayProblem(where,
      "its compression header lists " + std::to_string(blocks) +
        " blocks, more than the file can hold");
  }
  header.Blocks = Words(layout, data, 3 * word, blocks, where, "compression header");
  header.HeaderBytes = (3 + blocks) * word;
  Bytes compressed = 0;
  for (const Bytes size : header.Blocks)
  {
    compressed = Plus(compressed, size);
  }
  const Bytes room = data.After(header.HeaderBytes).DecodedSize();
  if (compressed > room)
  {
    throw ArrayProblem(where,
      "its " + std::to_string(blocks) + " compressed blocks add up to " +
        std::to_string(compressed) + " bytes, but only " + std::to_string(room) + " follow");
  }
  if (blocks > 0)
  {
    header.Size = Plus(Times(blocks - 1, header.BlockSize),
      header.LastBlockSize ? header.LastBlockSize : header.BlockSize);
  }
  return header;
}

unsigned WordSize(const char* type)
{
  const std::string_view name = type ? type : "";
  if (name == "Int8" || name == "UInt8" || name == "Char")
  {
    return 1;
  }
  if (name == "Int16" || name == "UInt16")
  {
    return 2;
  }
  if (name == "Int32" || name == "UInt32" || name == "Float32")
  {
    return 4;
  }
  if (name == "Int64" || name == "UInt64" || name == "Float64")
  {
    return 8;
  }
  return 0; // String and Bit arrays: their header is checked, their size not known here
}

// The text between an element's start tag and the next tag: its inline data,
// found as VTK finds it.
std::string_view InlineText(const FileLayout& layout, vtkXMLDataElement* element)
{
  const std::string_view file = layout.File;
  const auto index =
    static_cast<std::size_t>(std::max<vtkTypeInt64>(element->GetXMLByteIndex(), 0));
  std::size_t begin = file.find('>', std::min(index, file.size()));
  begin =
    std::min(file.find_first_not_of(" \t\r\n", begin == std::string_view::npos ? begin : begin + 1),
      file.size());
  const std::size_t end = std::min(file.find('<', begin), file.size());
  return file.substr(begin, end - begin);
}

std::string_view Format(vtkXMLDataElement* array)
{
  const char* format = array->GetAttribute("format");
  return format ? format : "";
}

// The encoded data of a binary or appended array; nothing for ASCII (and for
// an appended array without an offset, which VTK refuses itself).
std::optional<Encoded> BinaryData(
  const FileLayout& layout, vtkXMLDataElement* array, const std::string& where)
{
  const std::string_view format = Format(array);
  if (format == "binary")
  {
    return Encoded(InlineText(layout, array), true);
  }
  if (format != "appended" || !layout.HasAppended)
  {
    return std::nullopt;
  }
  long long offset = 0;
  if (!array->GetScalarAttribute("offset", offset))
  {
    return std::nullopt;
  }
  if (offset < 0 || static_cast<Bytes>(offset) >= layout.Appended.size())
  {
    throw ArrayProblem(where,
      "its offset " + std::to_string(offset) + " lies outside the appended data (0 to " +
        std::to_string(layout.Appended.size()) + " bytes)");
  }
  return Encoded(layout.Appended.substr(static_cast<std::size_t>(offset)), layout.AppendedBase64);
}

class ArrayChecker
{
public:
  ArrayChecker(const FileLayout& layout)
    : Layout(layout)
  {
  }

  /**
   * Checks one array that VTK will read as `values` values (tuples times
   * components), adding what it decodes to the total.
   */
  void Check(vtkXMLDataElement* array, Bytes values, const std::string& where)
  {
    const Bytes wordSize = WordSize(array->GetAttribute("type"));
    const Bytes need = Times(values, wordSize);
    if (Format(array) == "ascii")
    {
      const Bytes room = (InlineText(this->Layout, array).size() + 1) / 2;
      if (values > room)
      {
        throw ArrayProblem(where,
          "declares " + std::to_string(values) + " values, but its text holds at most " +
            std::to_string(room));
      }
      this->Add(need, where);
      return;
    }
    const std::optional<Encoded> data = BinaryData(this->Layout, array, where);
    if (!data)
    {
      return;
    }
    const Header header = ReadHeader(this->Layout, *data, where);
    if (wordSize != 0 && header.Size != need)
    {
      throw ArrayProblem(where,
        "it decodes to " + std::to_string(header.Size) + " bytes, but its " +
          std::to_string(values) + " values of " + array->GetAttribute("type") + " are " +
          std::to_string(need));
    }
    this->Add(header.Size, where);
  }

  /** The last of an offsets array's `values` integers (checked before): the connectivity's length.
   */
  std::optional<long long> LastValue(
    vtkXMLDataElement* array, Bytes values, const std::string& where)
  {
    const char* type = array->GetAttribute("type");
    const Bytes wordSize = WordSize(type);
    if (values == 0 || wordSize == 0)
    {
      return std::nullopt;
    }
    if (Format(array) == "ascii")
    {
      const std::string text(InlineText(this->Layout, array));
      const std::size_t end = text.find_last_not_of(" \t\r\n");
      if (end == std::string::npos)
      {
        return std::nullopt;
      }
      const std::size_t begin = text.find_last_of(" \t\r\n", end);
      return std::strtoll(text.c_str() + (begin == std::string::npos ? 0 : begin + 1), nullptr, 10);
    }
    const std::optional<Encoded> data = BinaryData(this->Layout, array, where);
    if (!data)
    {
      return std::nullopt;
    }
    const Header header = ReadHeader(this->Layout, *data, where);
    const Bytes at = (values - 1) * wordSize;
    if (this->Layout.Compressor &&
      (header.BlockSize == 0 || at / header.BlockSize >= header.Blocks.size()))
    {
      return std::nullopt; // VTK finds the array too short when it reads it
    }
    unsigned char word[8] = {};
    if (!this->Layout.Compressor)
    {
      data->Read(header.HeaderBytes + at, wordSize, word);
    }
    else
    {
      // The block that holds the last value, decompressed: no bigger than
      // the array, whose size Check has already counted.
      const Bytes block = at / header.BlockSize;
      Bytes start = 0;
      for (Bytes i = 0; i < block; ++i)
      {
        start += header.Blocks[i];
      }
      const bool last = block + 1 == header.Blocks.size();
      const Bytes size = last && header.LastBlockSize ? header.LastBlockSize : header.BlockSize;
      std::vector<unsigned char> compressed(header.Blocks[block]);
      std::vector<unsigned char> decoded(size);
      const Encoded blocks = data->After(header.HeaderBytes);
      if (at % header.BlockSize + wordSize > size ||
        !blocks.Read(start, compressed.size(), compressed.data()) ||
        this->Layout.Compressor->Uncompress(
          compressed.data(), compressed.size(), decoded.data(), decoded.size()) != size)
      {
        return std::nullopt; // VTK says what is wrong when it reads it
      }
      std::memcpy(word, decoded.data() + at % header.BlockSize, wordSize);
    }
    const Bytes raw = Word(word, static_cast<unsigned>(wordSize), this->Layout.BigEndian);
    const bool isSigned = type[0] == 'I';
    if (isSigned && wordSize < 8 && (raw >> (8 * wordSize - 1)))
    {
      return -1; // negative: VTK's check of the offsets refuses it
    }
    return static_cast<long long>(raw);
  }

private:
  void Add(Bytes bytes, const std::string& where)
  {
    this->Total = Plus(this->Total, bytes);
    const Bytes available = vtkShadelabFileReader::AvailableMemory();
    if (available > 0 && this->Total > available / 2)
    {
      throw ArrayProblem(where,
        "the arrays up to here decode to " + MiB(this->Total) +
          "; reading them needs more than the " + MiB(available) + " of memory available");
    }
    const Bytes fileSize = this->Layout.File.size();
    if (this->Total > MinimumBomb && this->Total / MaxExpansion > fileSize)
    {
      throw ArrayProblem(where,
        "the arrays up to here decode to " + MiB(this->Total) + ", more than " +
          std::to_string(MaxExpansion) + " times the file's " + std::to_string(fileSize) +
          " bytes: a decompression bomb, not a mesh");
    }
  }

  const FileLayout& Layout;
  Bytes Total = 0;
};

Bytes Count(vtkXMLDataElement* element, const char* name, const std::string& where)
{
  long long count = 0;
  if (element->GetScalarAttribute(name, count) && count < 0)
  {
    throw MeshReadError(where + ": " + name + " is " + std::to_string(count));
  }
  return static_cast<Bytes>(count);
}

Bytes Components(vtkXMLDataElement* array)
{
  long long components = 1;
  array->GetScalarAttribute("NumberOfComponents", components);
  return components < 1 ? 1 : static_cast<Bytes>(components);
}

std::string ArrayName(vtkXMLDataElement* array)
{
  const char* name = array->GetAttribute("Name");
  return name ? std::string("'") + name + "'" : std::string("without a name");
}

vtkSmartPointer<vtkDataCompressor> CompressorNamed(const char* name)
{
  const std::string_view kind = name ? name : "";
  if (kind.empty())
  {
    return nullptr;
  }
  if (kind == "vtkZLibDataCompressor")
  {
    return vtkSmartPointer<vtkZLibDataCompressor>::New();
  }
  if (kind == "vtkLZ4DataCompressor")
  {
    return vtkSmartPointer<vtkLZ4DataCompressor>::New();
  }
  if (kind == "vtkLZMADataCompressor")
  {
    return vtkSmartPointer<vtkLZMADataCompressor>::New();
  }
  throw MeshReadError("its compressor \"" + std::string(kind).substr(0, 60) +
    "\" is none of VTK's (vtkZLibDataCompressor, vtkLZ4DataCompressor, vtkLZMADataCompressor)");
}

void CheckCells(
  ArrayChecker& arrays, vtkXMLDataElement* cells, Bytes count, const std::string& piece)
{
  const std::string kind = cells->GetName();
  vtkXMLDataElement* offsets =
    cells->FindNestedElementWithNameAndAttribute("DataArray", "Name", "offsets");
  vtkXMLDataElement* connectivity =
    cells->FindNestedElementWithNameAndAttribute("DataArray", "Name", "connectivity");
  if (!offsets || !connectivity || count == 0)
  {
    return; // VTK names a missing array itself
  }
  const std::string where = kind + " offsets of " + piece;
  arrays.Check(offsets, count, where);
  const std::optional<long long> length = arrays.LastValue(offsets, count, where);
  if (length && *length >= 0)
  {
    arrays.Check(connectivity, static_cast<Bytes>(*length), kind + " connectivity of " + piece);
  }
}
}

void CheckXMLPolyDataArrays(vtkXMLDataParser* parser, std::string_view file)
{
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* polyData = root ? root->FindNestedElementWithName("PolyData") : nullptr;
  if (!polyData)
  {
    return; // not PolyData: VTK's reader says so
  }
  FileLayout layout;
  layout.File = file;
  const char* headerType = root->GetAttribute("header_type");
  layout.HeaderWord = headerType && std::string_view(headerType) == "UInt64" ? 8 : 4;
  const char* byteOrder = root->GetAttribute("byte_order");
  layout.BigEndian = byteOrder && std::string_view(byteOrder) == "BigEndian";
  layout.Compressor = CompressorNamed(root->GetAttribute("compressor"));
  if (vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData"))
  {
    const vtkTypeInt64 start = parser->GetAppendedDataPosition();
    if (start >= 0 && static_cast<Bytes>(start) <= file.size())
    {
      const char* encoding = appended->GetAttribute("encoding");
      layout.AppendedBase64 = !encoding || std::string_view(encoding) != "raw";
      layout.Appended = file.substr(static_cast<std::size_t>(start));
      if (layout.AppendedBase64)
      {
        layout.Appended = layout.Appended.substr(0, layout.Appended.find('<'));
      }
      layout.HasAppended = true;
    }
  }

  ArrayChecker arrays(layout);
  const int pieceCount = polyData->GetNumberOfNestedElements();
  int pieceNumber = 0;
  for (int p = 0; p < pieceCount; ++p)
  {
    vtkXMLDataElement* element = polyData->GetNestedElement(p);
    const std::string_view kind = element->GetName();
    if (kind == "FieldData")
    {
      for (int a = 0; a < element->GetNumberOfNestedElements(); ++a)
      {
        vtkXMLDataElement* array = element->GetNestedElement(a);
        const std::string where = "FieldData array " + ArrayName(array);
        arrays.Check(array, Times(Count(array, "NumberOfTuples", where), Components(array)), where);
      }
      continue;
    }
    if (kind != "Piece")
    {
      continue;
    }
    const std::string piece = "piece " + std::to_string(++pieceNumber);
    const Bytes points = Count(element, "NumberOfPoints", piece);
    Bytes cells = 0;
    for (const char* cellKind : { "Verts", "Lines", "Strips", "Polys" })
    {
      cells = Plus(cells, Count(element, (std::string("NumberOf") + cellKind).c_str(), piece));
    }
    for (int s = 0; s < element->GetNumberOfNestedElements(); ++s)
    {
      vtkXMLDataElement* section = element->GetNestedElement(s);
      const std::string name = section->GetName();
      const bool pointArrays = name == "Points" || name == "PointData";
      if (pointArrays || name == "CellData")
      {
        for (int a = 0; a < section->GetNumberOfNestedElements(); ++a)
        {
          vtkXMLDataElement* array = section->GetNestedElement(a);
          const std::string where = name + " array " + ArrayName(array) + " of " + piece;
          arrays.Check(array, Times(pointArrays ? points : cells, Components(array)), where);
        }
      }
      else if (name == "Verts" || name == "Lines" || name == "Strips" || name == "Polys")
      {
        CheckCells(arrays, section, Count(element, ("NumberOf" + name).c_str(), piece), piece);
      }
    }
  }
}
}
