/**
 * @brief   the arrays of a VTK XML PolyData file, checked against its bytes
 *          before VTK's reader allocates them
 *
 * vtkXMLPolyDataReader believes every number a file gives: it allocates each
 * array for the piece's counts, each zlib block for its header's size, the
 * block table for its header's count, and it seeks to an appended array's
 * offset, negative or not. So a 581-byte file can ask for gigabytes, and a
 * negative offset makes the XML's own text into coordinates.
 *
 * CheckXMLPolyDataArrays parses the XML's elements itself, since VTK's
 * reader reads FieldData while it reads them, and reads, for each array VTK
 * will read (the points,
 * point and cell data, the cells' offsets and connectivity, field data),
 * only its header (and, for the connectivity's length, the offsets' last
 * value) and requires:
 * - an appended array's offset to lie inside the appended data, and its
 *   header and compressed blocks to fit in what follows;
 * - the bytes the header says the array decodes to to be exactly what the
 *   piece's counts need (so no block or array is bigger than the file says),
 *   and the block sizes to be a size and a remainder;
 * - an array to be read as VTK reads it: appended wherever it has an
 *   offset, and only one offsets or connectivity array per cell kind;
 * - an ASCII array to have room for its values (two characters each);
 * - what VTK allocates (the first piece's arrays for all pieces' points and
 *   cells, a String 32 bytes a value) to fit in half the memory available, and, beyond
 *   256 MiB, to be at most 64 times the file's size: zlib reaches 1032
 *   times on zeros, meshes' coordinates about 1.1 to 3 times, so a file
 *   past that is a decompression bomb rather than a mesh.
 * It throws MeshReadError naming the array and its problem.
 */
#ifndef shadelabXMLArraySizes_h
#define shadelabXMLArraySizes_h

#include <cstdint>
#include <string_view>

namespace shadelab
{
/** file: the bytes VTK's reader will read. Malformed XML fails with the parser's message. */
void CheckXMLPolyDataArrays(std::string_view file);

/** Beyond MinimumBomb bytes, arrays decoding to more than MaxExpansion times the file's size. */
constexpr std::uint64_t MaxExpansion = 64;
constexpr std::uint64_t MinimumBomb = std::uint64_t(256) << 20;
}

#endif
