// VTK XML PolyData: every encoding VTK writes reads back, and a file whose
// numbers lie (offsets, block counts, sizes, counts) is refused in one line
// before VTK allocates what it asks for (shadelabXMLArraySizes.h).
#include "mesh_reader_fixture.h"
#include "shadelabXMLArraySizes.h"

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt64Array.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkZLibDataCompressor.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace
{
using namespace shadelab::test;

// A quad as two triangles, with normals: three arrays and the cells' two.
vtkSmartPointer<vtkPolyData> Quad()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(1, 1, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  polys->InsertNextCell({ 0, 2, 3 });
  vtkNew<vtkFloatArray> normals;
  normals->SetName("N");
  normals->SetNumberOfComponents(3);
  for (int i = 0; i < 4; ++i)
  {
    normals->InsertNextTuple3(0, 0, 1);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetNormals(normals);
  return mesh;
}

enum class Layout
{
  Ascii,
  Binary,
  AppendedRaw,
  AppendedBase64
};

std::string Vtp(vtkPolyData* mesh, Layout layout, bool compressed)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->WriteToOutputStringOn();
  switch (layout)
  {
    case Layout::Ascii:
      writer->SetDataModeToAscii();
      break;
    case Layout::Binary:
      writer->SetDataModeToBinary();
      break;
    case Layout::AppendedRaw:
    case Layout::AppendedBase64:
      writer->SetDataModeToAppended();
      writer->SetEncodeAppendedData(layout == Layout::AppendedBase64);
      break;
  }
  if (!compressed)
  {
    writer->SetCompressor(nullptr);
  }
  EXPECT_TRUE(writer->Write());
  return writer->GetOutputString();
}

// Where the raw appended data start: after the '_' that opens them.
std::size_t AppendedStart(const std::string& vtp)
{
  return vtp.find('_', vtp.find("<AppendedData")) + 1;
}

// The value of the offset attribute of the array named `name`.
std::size_t OffsetOf(const std::string& vtp, const std::string& name)
{
  const std::size_t array = vtp.find("Name=\"" + name + "\"");
  const std::size_t offset = vtp.find("offset=\"", array) + 8;
  return std::stoul(vtp.substr(offset, vtp.find('"', offset) - offset));
}

// Where the raw appended array named `name` starts: its binary header.
std::size_t HeaderOf(const std::string& vtp, const std::string& name)
{
  return AppendedStart(vtp) + OffsetOf(vtp, name);
}

void PutWord(std::string& vtp, std::size_t at, std::uint32_t value)
{
  std::string bytes;
  Put(bytes, value);
  vtp.replace(at, 4, bytes);
}

void Replace(std::string& text, const std::string& from, const std::string& to)
{
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

TEST_F(MeshReaders, VtpInEveryEncodingReadsBack)
{
  for (const Layout layout :
    { Layout::Ascii, Layout::Binary, Layout::AppendedRaw, Layout::AppendedBase64 })
  {
    for (const bool compressed : { false, true })
    {
      SCOPED_TRACE(std::to_string(static_cast<int>(layout)) + (compressed ? " zlib" : " plain"));
      const ReadResult result = Read(this->Write("quad.vtp", Vtp(Quad(), layout, compressed)));
      ASSERT_TRUE(result.Ok) << result.Error;
      ExpectTriangleMesh(result.Mesh);
      EXPECT_EQ(result.Mesh->GetNumberOfCells(), 2);
      EXPECT_EQ(result.Mesh->GetPointData()->GetNormals()->GetTuple3(3)[2], 1.0);
    }
  }
}

// A negative offset made the XML's own text into coordinates.
TEST_F(MeshReaders, VtpOffsetOutsideTheAppendedData)
{
  std::string vtp = Vtp(Quad(), Layout::AppendedRaw, false);
  Replace(vtp, "offset=\"" + std::to_string(OffsetOf(vtp, "N")) + "\"", "offset=\"-40\"");
  this->ExpectError("negative.vtp", vtp,
    { "PointData array 'N' of piece 1", "offset -40 lies outside the appended data" });

  vtp = Vtp(Quad(), Layout::AppendedRaw, false);
  Replace(vtp, "offset=\"0\"", "offset=\"100000\"");
  this->ExpectError("past.vtp", vtp, { "offset 100000 lies outside the appended data" });
}

// 581 bytes whose zlib header claimed 2^28 blocks reached 2.1 GB.
TEST_F(MeshReaders, VtpBlockCountBeyondTheFile)
{
  std::string vtp = Vtp(Quad(), Layout::AppendedRaw, true);
  PutWord(vtp, HeaderOf(vtp, "N"), 1u << 28);
  this->ExpectError("blocks.vtp", vtp,
    { "PointData array 'N'", "lists 268435456 blocks, more than the file can hold" });

  vtp = Vtp(Quad(), Layout::AppendedRaw, true);
  const std::size_t header = HeaderOf(vtp, "N");
  PutWord(vtp, header + 12, 1u << 30); // the one block's compressed size
  this->ExpectError("compressed.vtp", vtp, { "compressed blocks add up to 1073741824 bytes" });
}

// A header that decodes to more (or less) than the piece's counts need: VTK
// allocated each block and array for what it was told.
TEST_F(MeshReaders, VtpArraySizesMustMatchTheCounts)
{
  std::string vtp = Vtp(Quad(), Layout::AppendedRaw, true);
  const std::size_t header = HeaderOf(vtp, "N");
  PutWord(vtp, header + 4, 3u << 30); // its one block, of 3 GiB
  PutWord(vtp, header + 8, 3u << 30);
  this->ExpectError(
    "block.vtp", vtp, { "it decodes to 3221225472 bytes, but its 12 values of Float32 are 48" });

  vtp = Vtp(Quad(), Layout::AppendedRaw, false);
  PutWord(vtp, HeaderOf(vtp, "N"), 4000);
  this->ExpectError("raw.vtp", vtp, { "its header says 4000 bytes, but only" });

  vtp = Vtp(Quad(), Layout::Binary, true);
  Replace(vtp, "NumberOfPoints=\"4\"", "NumberOfPoints=\"1000000000\"");
  this->ExpectError("count.vtp", vtp,
    { "array 'N' of piece 1", "but its 3000000000 values of Float32 are 12000000000" });

  vtp = Vtp(Quad(), Layout::Ascii, false);
  Replace(vtp, "NumberOfPoints=\"4\"", "NumberOfPoints=\"1000000000\"");
  this->ExpectError("ascii.vtp", vtp, { "declares 3000000000 values, but its text holds at most" });
}

// VTK reads an array with an offset as appended whatever its format says, and
// divides by the block size: neither slips past.
TEST_F(MeshReaders, VtpArraysAreCheckedAsVtkReadsThem)
{
  std::string vtp = Vtp(Quad(), Layout::AppendedRaw, true);
  PutWord(vtp, HeaderOf(vtp, "N"), 1u << 28);
  const std::size_t n = vtp.find("Name=\"N\"");
  vtp.replace(vtp.find("format=\"appended\"", n), 17, "format=\"ascii\"   ");
  this->ExpectError("format.vtp", vtp, { "lists 268435456 blocks" });

  vtp = Vtp(Quad(), Layout::AppendedRaw, true);
  PutWord(vtp, HeaderOf(vtp, "N") + 4, 0);
  this->ExpectError(
    "zero.vtp", vtp, { "block sizes (0, last 48) are not a block size and a remainder" });
}

// FieldData is read while VTK reads the elements: checked before that.
TEST_F(MeshReaders, VtpFieldDataCountsAreCheckedFirst)
{
  vtkSmartPointer<vtkPolyData> quad = Quad();
  vtkNew<vtkIntArray> version;
  version->SetName("version");
  version->InsertNextValue(3);
  quad->GetFieldData()->AddArray(version);
  std::string vtp = Vtp(quad, Layout::Ascii, false);
  Replace(vtp, "NumberOfTuples=\"1\"", "NumberOfTuples=\"1000000000\"");
  this->ExpectError("field.vtp", vtp,
    { "FieldData array 'version'", "declares 1000000000 values, but its text holds at most" });
}

// VTK allocates the first piece's arrays for the points of every piece: a
// wide array on a one-point piece, then 10,000 points.
TEST_F(MeshReaders, VtpFirstPieceArraysAreCountedForAllPieces)
{
  const auto zeros = [](int n)
  {
    std::string text;
    for (int i = 0; i < n; ++i)
    {
      text += "0 ";
    }
    return text;
  };
  const std::string points =
    "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">";
  const std::string vtp = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                          "byte_order=\"LittleEndian\" header_type=\"UInt32\"><PolyData>"
                          "<Piece NumberOfPoints=\"1\"><PointData><DataArray type=\"Float64\" "
                          "Name=\"wide\" NumberOfComponents=\"100000\" format=\"ascii\">" +
    zeros(100000) + "</DataArray></PointData>" + points + zeros(3) +
    "</DataArray></Points></Piece><Piece NumberOfPoints=\"10000\">" + points + zeros(30000) +
    "</DataArray></Points></Piece></PolyData></VTKFile>\n";
  this->ExpectError("pieces.vtp", vtp,
    { "PointData array 'wide' of piece 1: the arrays up to here decode to 7630 MiB" });
}

// The connectivity's length is the offsets' last value, read before VTK
// allocates it: in text, raw, base64 and compressed.
TEST_F(MeshReaders, VtpConnectivityLongerThanItsData)
{
  std::string vtp = Vtp(Quad(), Layout::Ascii, false);
  const std::size_t offsets = vtp.find("Name=\"offsets\"", vtp.find("<Polys>"));
  const std::size_t six = vtp.find('6', vtp.find('>', offsets));
  vtp.replace(six, 1, "600000000000");
  this->ExpectError(
    "text.vtp", vtp, { "Polys connectivity of piece 1", "declares 600000000000 values" });
  // VTK reads as many offsets as there are cells, and no more.
  vtp = Vtp(Quad(), Layout::Ascii, false);
  Replace(vtp, "NumberOfPolys=\"2\"", "NumberOfPolys=\"1\"");
  const std::size_t polys = vtp.find("Name=\"offsets\"", vtp.find("<Polys>"));
  vtp.replace(vtp.find('3', vtp.find('>', polys)), 1, "600000000000");
  this->ExpectError("first.vtp", vtp, { "declares 600000000000 values" });

  for (const Layout layout : { Layout::Binary, Layout::AppendedRaw, Layout::AppendedBase64 })
  {
    for (const bool compressed : { false, true })
    {
      SCOPED_TRACE(std::to_string(static_cast<int>(layout)) + (compressed ? " zlib" : " plain"));
      // The quad's cells written with a longer last offset than its
      // connectivity holds: VTK would allocate that many ids.
      vtkSmartPointer<vtkPolyData> quad = Quad();
      vtkNew<vtkCellArray> polys;
      vtkNew<vtkTypeInt64Array> offsetValues, connectivity;
      for (const vtkTypeInt64 value : { 0, 3, 1000000 })
      {
        offsetValues->InsertNextValue(value);
      }
      for (const vtkTypeInt64 id : { 0, 1, 2, 0, 2, 3 })
      {
        connectivity->InsertNextValue(id);
      }
      polys->SetData(offsetValues, connectivity);
      quad->SetPolys(polys);
      this->ExpectError("cells.vtp", Vtp(quad, layout, compressed),
        { "Polys connectivity of piece 1", "but its 1000000 values of Int64 are 8000000" });
    }
  }
}

// A 2.9 MB file of one zlib block decoded to 2.9 GB of zeros and was read:
// counts and sizes agree, only the expansion gives it away. Here 288 MiB of
// zero coordinates in 32 KiB blocks of about 40 bytes each.
TEST_F(MeshReaders, VtpDecompressionBomb)
{
  const std::uint32_t points = 24u << 20;
  const std::uint32_t block = 1u << 15;
  const std::uint64_t bytes = std::uint64_t(points) * 12;
  const std::uint32_t blocks = static_cast<std::uint32_t>(bytes / block);
  const std::vector<unsigned char> zeros(block, 0);
  vtkNew<vtkZLibDataCompressor> zlib;
  std::vector<unsigned char> compressed(zlib->GetMaximumCompressionSpace(block));
  compressed.resize(zlib->Compress(zeros.data(), block, compressed.data(), compressed.size()));
  ASSERT_GT(compressed.size(), 0u);

  std::string data;
  for (const std::uint32_t word : { blocks, block, 0u })
  {
    Put(data, word);
  }
  for (std::uint32_t i = 0; i < blocks; ++i)
  {
    Put(data, static_cast<std::uint32_t>(compressed.size()));
  }
  for (std::uint32_t i = 0; i < blocks; ++i)
  {
    data.append(reinterpret_cast<const char*>(compressed.data()), compressed.size());
  }
  const std::string vtp = "<?xml version=\"1.0\"?>\n"
                          "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                          "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\">\n"
                          "<PolyData><Piece NumberOfPoints=\"" +
    std::to_string(points) +
    "\" NumberOfPolys=\"0\"><Points>"
    "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/>"
    "</Points></Piece></PolyData>\n<AppendedData encoding=\"raw\">_" +
    data + "\n</AppendedData></VTKFile>\n";
  ASSERT_LT(vtp.size() * shadelab::MaxExpansion, bytes);
  this->ExpectError("bomb.vtp", vtp,
    { "decode to 288 MiB, more than 64 times the file's", "a decompression bomb, not a mesh" });
}
}
