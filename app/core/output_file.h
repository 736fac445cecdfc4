// The one way shadelab writes a file: pictures, meshes, benchmark results,
// shaders, screenshots. Nothing is lost and nothing partial is left:
//   - bytes go to a temporary beside the output (same folder, so the rename
//     stays on one file system), created exclusively and locked (flock) while
//     it is written;
//   - every write and the close are checked (ENOSPC, EDQUOT, EIO, EFBIG with
//     SIGXFSZ ignored, ...), the file is fsynced, renamed over the output,
//     and the folder is fsynced, so the rename itself survives a power loss;
//   - on any failure the temporary is removed and the error names the cause.
// A temporary whose lock nobody holds was left by a killed run: writing an
// output removes its stale temporaries first.
#ifndef shadelab_output_file_h
#define shadelab_output_file_h

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace shadelab
{
class OutputFile
{
public:
  /** Opens a temporary beside path; Error() says why when it cannot. */
  explicit OutputFile(std::string path);
  /** Removes the temporary unless Commit() succeeded. */
  ~OutputFile();

  /** Appends bytes; false (and Error() set) when the write fails. */
  bool Write(const void* data, std::size_t size);
  bool Write(std::string_view bytes) { return this->Write(bytes.data(), bytes.size()); }

  /** fsync, close, rename into place, fsync the folder: "" or the first error. */
  std::string Commit();

  /** "" while all is well, else "cannot write: REASON". */
  const std::string& Error() const { return this->Failure; }

private:
  OutputFile(const OutputFile&) = delete;
  void operator=(const OutputFile&) = delete;

  bool Fail(const char* what, int error);

  std::string Path;
  std::string Temporary;
  int Slot = -1; // in the table that RemoveTemporariesNow reads
  int Descriptor = -1;
  std::string Failure;
};

/**
 * Removes every temporary that an OutputFile of this process is writing:
 * for a process about to end at once (a signal's hard stop), so that no
 * partial file stays behind. Async-signal-safe; the OutputFiles are not
 * used again.
 */
void RemoveTemporariesNow();

/** Writes bytes to path through an OutputFile: "" or "cannot write: REASON". */
std::string WriteFile(const std::string& path, std::string_view bytes);

/**
 * An anonymous file in memory (memfd), for libraries and programs that write
 * only to a file they name and open themselves (and do not all check their
 * writes): Name() opens it, in this process or in a child; WriteTo then
 * writes what it holds to path through an OutputFile.
 */
class MemoryFile
{
public:
  /** Makes the file; Error() says why when it cannot. */
  MemoryFile();
  ~MemoryFile();

  /** "/proc/PID/fd/N": the same file, whichever process of ours opens it. */
  std::string Name() const;
  /** For a child's standard output or error (dup2 it there). */
  int Descriptor() const { return this->Memory; }
  /** "" while all is well, else "cannot write: REASON". */
  const std::string& Error() const { return this->Failure; }

  /**
   * Whether it holds as much as the file-size limit (ulimit -f) allows: a
   * writer stopped there (with EFBIG, which one that checks none of its
   * writes, vtkOBJWriter, never sees) and what came after is lost.
   */
  bool AtSizeLimit() const;

  /** What the file holds (a log, say). */
  std::string Read() const;
  /** Writes what it holds to path through an OutputFile: "" or "cannot write: REASON" (File too
   * large AtSizeLimit). */
  std::string WriteTo(const std::string& path) const;

private:
  MemoryFile(const MemoryFile&) = delete;
  void operator=(const MemoryFile&) = delete;

  int Memory = -1;
  std::string Failure;
};

/**
 * write(name) writes into a MemoryFile named `name`; its bytes then go to
 * path through an OutputFile. write returns "" or its own error, which is
 * passed on.
 */
std::string WriteFileThroughMemory(
  const std::string& path, const std::function<std::string(const std::string& name)>& write);
}

#endif
