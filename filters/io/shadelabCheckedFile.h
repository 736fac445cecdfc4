/**
 * @file    shadelabCheckedFile.h
 * @brief   every file a reader opens, checked before a byte of it is read
 *
 * A mesh file, and each file it names (an MTL library, a glTF buffer, a
 * texture's image), is opened through OpenChecked: without blocking (a FIFO's
 * open would wait for a writer forever), then refused unless it is a regular
 * file (not a folder, FIFO, socket or device such as /dev/zero, whose size
 * says nothing of what a read would bring) of at most the bytes allowed.
 *
 * A file that a mesh file names resolves, after every symbolic link, inside
 * the mesh file's folder or below it (ResolveReference); anything else is
 * refused unless the caller trusts the file (allowOutside), so that a mesh
 * from elsewhere cannot make the program read, or quote, /etc/passwd. The
 * messages name the reference, never what the file holds.
 */
#ifndef shadelabCheckedFile_h
#define shadelabCheckedFile_h

#include <cstdint>
#include <string>

namespace shadelab
{
/** An open file descriptor, closed when it goes. */
class CheckedFile
{
public:
  CheckedFile(CheckedFile&& other) noexcept;
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;
  ~CheckedFile();

  std::uint64_t GetSize() const { return this->Size; }

  /** The whole file (its size when opened); throws MeshReadError "cannot read: ...". */
  std::string ReadAll();

private:
  friend CheckedFile OpenChecked(const std::string& path, std::uint64_t maxBytes);
  CheckedFile(int descriptor, std::uint64_t size)
    : Descriptor(descriptor)
    , Size(size)
  {
  }

  int Descriptor;
  std::uint64_t Size;
};

/**
 * Opens path for reading if it is a regular file of at most maxBytes; throws
 * MeshReadError otherwise ("cannot open: No such file or directory", "is not
 * a regular file but a FIFO", "is 3072 MiB, more than the 1024 MiB allowed").
 * maxBytes 0: no limit of its own beyond what the memory allows.
 */
CheckedFile OpenChecked(const std::string& path, std::uint64_t maxBytes = 0);

/**
 * The path of the file that `reference` (as the mesh file `meshFile` names
 * it, already decoded from any URI escapes) means, relative to `base` (the
 * folder it is named from: the mesh file's, or an MTL library's). Unless
 * allowOutside, throws MeshReadError "lies outside the mesh's folder ..."
 * when the reference, its symbolic links followed, leaves the mesh file's
 * folder: an absolute path, "../", or a link to elsewhere.
 */
std::string ResolveReference(const std::string& meshFile, const std::string& base,
  const std::string& reference, bool allowOutside);
}

#endif
