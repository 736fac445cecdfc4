#include "shadelabXMLArraySizes.h"

#include "shadelabMeshReadError.h"
#include "vtkShadelabFileReader.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkBase64Utilities.h>
#include <vtkCommand.h>
#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstring>
#include <initializer_list>
#include <istream>
#include <limits>
#include <optional>
#include <streambuf>
#include <string>
#include <tuple>
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
    if (n == 0)
    {
      return true;
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
  if (blocks > 0 && (header.BlockSize == 0 || header.LastBlockSize > header.BlockSize))
  {
    // VTK divides by the block size and finds the last block by the two.
    throw ArrayProblem(where,
      "its compression header's block sizes (" + std::to_string(header.BlockSize) + ", last " +
        std::to_string(header.LastBlockSize) + ") are not a block size and a remainder");
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

// How VTK holds a value of the array's type: bytes in the file (Bit arrays
// pack eight values a byte) and bytes in memory (a String is a std::string).
struct ValueType
{
  Bytes FileBits = 0; // 0: a type VTK does not read
  Bytes MemoryBytes = 0;
  bool Integer = false;
};

ValueType TypeOf(vtkXMLDataElement* array)
{
  const char* attribute = array->GetAttribute("type");
  const std::string_view name = attribute ? attribute : "";
  for (const auto& [type, bytes, integer] :
    std::initializer_list<std::tuple<const char*, Bytes, bool>>{ { "Int8", 1, true },
      { "UInt8", 1, true }, { "Char", 1, true }, { "Int16", 2, true }, { "UInt16", 2, true },
      { "Int32", 4, true }, { "UInt32", 4, true }, { "Float32", 4, false }, { "Int64", 8, true },
      { "UInt64", 8, true }, { "Float64", 8, false } })
  {
    if (name == type)
    {
      return { 8 * bytes, bytes, integer };
    }
  }
  if (name == "Bit")
  {
    return { 1, 1, false };
  }
  if (name == "String")
  {
    return { 8, sizeof(std::string), false }; // at least its terminating NUL in the file
  }
  return {};
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

// The encoded data of an array that VTK reads as binary, decided as VTK
// decides it: an offset attribute makes it appended whatever its format
// says (an offset VTK cannot parse is 0), else format "binary" is inline
// base64; nothing for the rest, which VTK reads as ASCII.
std::optional<Encoded> BinaryData(
  const FileLayout& layout, vtkXMLDataElement* array, const std::string& where)
{
  if (!array->GetAttribute("offset"))
  {
    const char* format = array->GetAttribute("format");
    if (format && std::string_view(format) == "binary")
    {
      return Encoded(InlineText(layout, array), true);
    }
    return std::nullopt;
  }
  if (!layout.HasAppended)
  {
    throw ArrayProblem(where, "it has an offset, but the file has no appended data");
  }
  long long offset = 0;
  array->GetScalarAttribute("offset", offset);
  if (offset < 0 || static_cast<Bytes>(offset) >= layout.Appended.size())
  {
    throw ArrayProblem(where,
      "its offset " + std::to_string(offset) + " lies outside the appended data (0 to " +
        std::to_string(layout.Appended.size()) + " bytes)");
  }
  return Encoded(layout.Appended.substr(static_cast<std::size_t>(offset)), layout.AppendedBase64);
}

// The first `count` whitespace-separated integers of an ASCII array (VTK
// reads that many and ignores the rest); nothing if there are fewer.
std::optional<long long> AsciiValue(std::string_view text, Bytes index)
{
  const char* at = text.data();
  const char* const end = at + text.size();
  long long value = 0;
  for (Bytes i = 0; i <= index; ++i)
  {
    while (at < end && std::isspace(static_cast<unsigned char>(*at)))
    {
      ++at;
    }
    const auto [next, problem] = std::from_chars(at, end, value);
    if (problem != std::errc())
    {
      return std::nullopt;
    }
    at = next;
  }
  return value;
}

class ArrayChecker
{
public:
  explicit ArrayChecker(const FileLayout& layout)
    : Layout(layout)
  {
  }

  /**
   * Checks that one array holds the `values` values (tuples times
   * components) VTK will read from it, without counting what VTK allocates
   * for them: Allocate does.
   */
  void Check(vtkXMLDataElement* array, Bytes values, const std::string& where)
  {
    const ValueType type = TypeOf(array);
    if (type.FileBits == 0)
    {
      return; // VTK refuses the type itself
    }
    const std::optional<Encoded> data = BinaryData(this->Layout, array, where);
    if (!data)
    {
      const Bytes room = (InlineText(this->Layout, array).size() + 1) / 2;
      if (values > room)
      {
        throw ArrayProblem(where,
          "declares " + std::to_string(values) + " values, but its text holds at most " +
            std::to_string(room));
      }
      return;
    }
    const Header header = ReadHeader(this->Layout, *data, where);
    const Bytes need = (Times(values, type.FileBits) + 7) / 8;
    // A String's values are as long as they are: at least a NUL each.
    if (type.MemoryBytes == sizeof(std::string) ? header.Size < need : header.Size != need)
    {
      throw ArrayProblem(where,
        "it decodes to " + std::to_string(header.Size) + " bytes, but its " +
          std::to_string(values) + " values of " + array->GetAttribute("type") + " are " +
          std::to_string(need));
    }
    // Decoding holds a block at a time beside the array.
    this->Add(header.BlockSize, where);
    this->Remove(header.BlockSize);
  }

  /** Counts what VTK allocates for `values` values of the array's type. */
  void Allocate(vtkXMLDataElement* array, Bytes values, const std::string& where)
  {
    const ValueType type = TypeOf(array);
    this->Add(type.FileBits == 1 ? (values + 7) / 8 : Times(values, type.MemoryBytes), where);
  }

  /**
   * The last of an offsets array's `values` integers (checked before): the
   * connectivity's length, as VTK will read it.
   */
  Bytes LastValue(vtkXMLDataElement* array, Bytes values, const std::string& where)
  {
    const ValueType type = TypeOf(array);
    if (!type.Integer)
    {
      throw ArrayProblem(where, "its type is not an integer type");
    }
    const Bytes wordSize = type.MemoryBytes;
    const auto negative = [&]() -> Bytes
    { throw ArrayProblem(where, "its last offset is negative"); };
    const auto unreadable = [&]() -> Bytes
    { throw ArrayProblem(where, "its last value cannot be decoded"); };
    const std::optional<Encoded> data = BinaryData(this->Layout, array, where);
    if (!data)
    {
      const std::optional<long long> last = AsciiValue(InlineText(this->Layout, array), values - 1);
      return !last ? unreadable() : *last < 0 ? negative() : static_cast<Bytes>(*last);
    }
    const Header header = ReadHeader(this->Layout, *data, where);
    const Bytes at = (values - 1) * wordSize;
    unsigned char word[8] = {};
    if (!this->Layout.Compressor)
    {
      if (!data->Read(header.HeaderBytes + at, wordSize, word))
      {
        return unreadable();
      }
    }
    else
    {
      // The block that holds the last value, decompressed: no bigger than
      // the array, whose size Check has held to its count.
      const Bytes block = at / header.BlockSize;
      if (block >= header.Blocks.size())
      {
        return unreadable();
      }
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
        return unreadable();
      }
      std::memcpy(word, decoded.data() + at % header.BlockSize, wordSize);
    }
    const Bytes raw = Word(word, static_cast<unsigned>(wordSize), this->Layout.BigEndian);
    const char* name = array->GetAttribute("type");
    const bool isSigned = name[0] == 'I';
    return isSigned && (raw >> (8 * wordSize - 1)) ? negative() : raw;
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

  void Remove(Bytes bytes) { this->Total -= std::min(bytes, this->Total); }

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

// The file's bytes as a stream that VTK's parser can seek in, uncopied.
class ViewBuffer : public std::streambuf
{
public:
  explicit ViewBuffer(std::string_view bytes)
  {
    char* begin = const_cast<char*>(bytes.data());
    this->setg(begin, begin, begin + bytes.size());
  }

protected:
  pos_type seekoff(off_type offset, std::ios_base::seekdir from, std::ios_base::openmode) override
  {
    char* base = from == std::ios_base::beg ? this->eback()
      : from == std::ios_base::cur          ? this->gptr()
                                            : this->egptr();
    if (offset < this->eback() - base || offset > this->egptr() - base)
    {
      return pos_type(off_type(-1));
    }
    this->setg(this->eback(), base + offset, this->egptr());
    return pos_type(this->gptr() - this->eback());
  }

  pos_type seekpos(pos_type position, std::ios_base::openmode mode) override
  {
    return this->seekoff(off_type(position), std::ios_base::beg, mode);
  }
};

// The parser's first error as one line; its warnings dropped (VTK's reader
// gives them again when it reads the file).
struct FirstError
{
  explicit FirstError(vtkObject* parser)
  {
    parser->AddObserver(vtkCommand::ErrorEvent, this, &FirstError::Catch);
    parser->AddObserver(vtkCommand::WarningEvent, this, &FirstError::Ignore);
  }
  void Catch(vtkObject*, unsigned long, void* text)
  {
    if (this->Text.empty())
    {
      this->Text = vtkShadelabOutputWindow::OneLine(static_cast<const char*>(text));
    }
  }
  void Ignore(vtkObject*, unsigned long, void*) {}
  std::string Text;
};

// The one DataArray named `name` of a cells element: VTK takes the first
// of its time step, so a second one (time steps) is not read at all.
vtkXMLDataElement* CellArray(vtkXMLDataElement* cells, const char* name, const std::string& where)
{
  vtkXMLDataElement* found = nullptr;
  for (int a = 0; a < cells->GetNumberOfNestedElements(); ++a)
  {
    vtkXMLDataElement* array = cells->GetNestedElement(a);
    const char* arrayName = array->GetAttribute("Name");
    if (arrayName && std::string_view(arrayName) == name)
    {
      if (found)
      {
        throw MeshReadError(where + " has more than one " + name + " array (time steps?)");
      }
      found = array;
    }
  }
  return found;
}

void CheckCells(
  ArrayChecker& arrays, vtkXMLDataElement* cells, Bytes count, const std::string& piece)
{
  const std::string kind = cells->GetName();
  vtkXMLDataElement* offsets = CellArray(cells, "offsets", kind + " of " + piece);
  vtkXMLDataElement* connectivity = CellArray(cells, "connectivity", kind + " of " + piece);
  if (!offsets || !connectivity || count == 0)
  {
    return; // VTK names a missing array itself
  }
  const std::string where = kind + " offsets of " + piece;
  arrays.Check(offsets, count, where);
  arrays.Allocate(offsets, Plus(count, 1), where);
  const Bytes length = arrays.LastValue(offsets, count, where);
  const std::string connectivityWhere = kind + " connectivity of " + piece;
  arrays.Check(connectivity, length, connectivityWhere);
  arrays.Allocate(connectivity, length, connectivityWhere);
}

// The point and cell counts of all pieces: VTK allocates the first piece's
// arrays for all of them at once.
struct Totals
{
  Bytes Points = 0;
  Bytes Cells = 0;
};

Bytes CellCount(vtkXMLDataElement* piece, const std::string& where)
{
  Bytes cells = 0;
  for (const char* cellKind : { "Verts", "Lines", "Strips", "Polys" })
  {
    cells = Plus(cells, Count(piece, (std::string("NumberOf") + cellKind).c_str(), where));
  }
  return cells;
}

Totals CountAll(vtkXMLDataElement* polyData)
{
  Totals totals;
  for (int p = 0, number = 0; p < polyData->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* piece = polyData->GetNestedElement(p);
    if (std::string_view(piece->GetName()) == "Piece")
    {
      const std::string where = "piece " + std::to_string(++number);
      totals.Points = Plus(totals.Points, Count(piece, "NumberOfPoints", where));
      totals.Cells = Plus(totals.Cells, CellCount(piece, where));
    }
  }
  return totals;
}
}

void CheckXMLPolyDataArrays(std::string_view file)
{
  // A parser of its own: VTK's reader reads the FieldData arrays already
  // when it reads the elements.
  ViewBuffer buffer(file);
  std::istream stream(&buffer);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&stream);
  FirstError errors(parser);
  if (!parser->Parse())
  {
    throw MeshReadError(errors.Text.empty() ? "cannot be parsed as XML" : errors.Text);
  }
  vtkXMLDataElement* root = parser->GetRootElement();
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
  const Totals totals = CountAll(polyData);
  int pieceNumber = 0;
  for (int p = 0; p < polyData->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* element = polyData->GetNestedElement(p);
    const std::string_view kind = element->GetName();
    if (kind == "FieldData")
    {
      for (int a = 0; a < element->GetNumberOfNestedElements(); ++a)
      {
        vtkXMLDataElement* array = element->GetNestedElement(a);
        const std::string where = "FieldData array " + ArrayName(array);
        const Bytes values = Times(Count(array, "NumberOfTuples", where), Components(array));
        arrays.Check(array, values, where);
        arrays.Allocate(array, values, where);
      }
      continue;
    }
    if (kind != "Piece")
    {
      continue;
    }
    const std::string piece = "piece " + std::to_string(++pieceNumber);
    const Bytes points = Count(element, "NumberOfPoints", piece);
    const Bytes cells = CellCount(element, piece);
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
          if (pieceNumber == 1)
          {
            arrays.Allocate(
              array, Times(pointArrays ? totals.Points : totals.Cells, Components(array)), where);
          }
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
