// A reading step in a child process: its answer, its error, its crash and
// its prints, as the parent sees them.
#include "shadelabIsolatedRead.h"
#include "shadelabMeshReadError.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <new>
#include <string>

namespace
{
using shadelab::MeshReadError;
using shadelab::ReadIsolated;

// The error ReadIsolated throws, or "" (and a failure) when it returns.
MeshReadError ErrorOf(const std::function<std::string()>& read)
{
  try
  {
    ReadIsolated("lib", read);
  }
  catch (const MeshReadError& error)
  {
    return error;
  }
  ADD_FAILURE() << "no error";
  return MeshReadError("");
}

TEST(IsolatedRead, ReturnsTheChildsBytesWhateverTheirSize)
{
  EXPECT_EQ(ReadIsolated("lib", [] { return std::string(); }), "");
  // Far beyond a pipe's buffer, every byte value.
  std::string bytes(3 << 20, '\0');
  for (size_t i = 0; i < bytes.size(); ++i)
  {
    bytes[i] = static_cast<char>(i * 7);
  }
  EXPECT_EQ(ReadIsolated("lib", [&] { return bytes; }), bytes);
}

TEST(IsolatedRead, RunsInAnotherProcessWhoseMemoryStaysItsOwn)
{
  int touched = 0;
  const std::string pid = ReadIsolated("lib",
    [&]
    {
      touched = 1;
      return std::to_string(getpid());
    });
  EXPECT_NE(pid, std::to_string(getpid()));
  EXPECT_EQ(touched, 0);
}

TEST(IsolatedRead, TheChildsErrorKeepsItsMessageAndCode)
{
  const MeshReadError error = ErrorOf([]() -> std::string
    { throw MeshReadError("bad face 3", vtkErrorCode::PrematureEndOfFileError); });
  EXPECT_STREQ(error.what(), "bad face 3");
  EXPECT_EQ(error.GetCode(), vtkErrorCode::PrematureEndOfFileError);
  EXPECT_STREQ(ErrorOf([]() -> std::string { throw std::bad_alloc(); }).what(), "out of memory");
  EXPECT_STREQ(
    ErrorOf([]() -> std::string { throw std::runtime_error("json: bad"); }).what(), "json: bad");
}

TEST(IsolatedRead, ACrashIsAnErrorNamingTheLibraryAndTheSignal)
{
  // SIGKILL: no sanitizer's handler can turn it into an exit status.
  const MeshReadError killed = ErrorOf(
    []() -> std::string
    {
      raise(SIGKILL);
      return "";
    });
  EXPECT_STREQ(killed.what(), "lib crashed reading it (SIGKILL)");
  EXPECT_EQ(killed.GetCode(), vtkErrorCode::FileFormatError);
  EXPECT_STREQ(
    ErrorOf([]() -> std::string { _exit(3); }).what(), "lib crashed reading it (exit status 3)");
}

TEST(IsolatedRead, TheChildsPrintsGoNowhere)
{
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const std::string answer = ReadIsolated("lib",
    []
    {
      std::printf("on stdout\n");
      std::fprintf(stderr, "on stderr\n");
      std::fflush(nullptr);
      return std::string("answer");
    });
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(answer, "answer");
}
}
