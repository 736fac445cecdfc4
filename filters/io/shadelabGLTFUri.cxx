#include "shadelabGLTFUri.h"

#include "shadelabCheckedFile.h"
#include "shadelabGLTFJson.h"

#include <vtkBase64Utilities.h>

#include <filesystem>

namespace shadelab::gltf
{
std::string DecodeDataUri(std::string_view uri, const std::string& where)
{
  const auto comma = uri.find(',');
  if (comma == std::string_view::npos || uri.substr(0, comma).size() < 7 ||
    uri.substr(comma - 7, 7) != ";base64")
  {
    Fail(where + ": a data URI that is not base64");
  }
  const std::string_view text = uri.substr(comma + 1);
  std::size_t padding = 0;
  while (padding < 2 && padding < text.size() && text[text.size() - 1 - padding] == '=')
  {
    ++padding;
  }
  const std::size_t expected = text.size() / 4 * 3 - padding;
  std::string bytes(text.size() / 4 * 3, '\0');
  // DecodeSafely stops at the first byte outside the alphabet.
  const std::size_t decoded = text.size() % 4 != 0
    ? 0
    : vtkBase64Utilities::DecodeSafely(reinterpret_cast<const unsigned char*>(text.data()),
        text.size(), reinterpret_cast<unsigned char*>(bytes.data()), bytes.size());
  if ((text.size() % 4 != 0 || decoded != expected) && !text.empty())
  {
    Fail(where + ": malformed base64 in its data URI");
  }
  bytes.resize(expected);
  return bytes;
}

namespace
{
int HexDigit(char c)
{
  return c >= '0' && c <= '9' ? c - '0'
    : c >= 'a' && c <= 'f'    ? c - 'a' + 10
    : c >= 'A' && c <= 'F'    ? c - 'A' + 10
                              : -1;
}

}

std::string FilePath(const std::string& documentName, bool allowOutside, std::string_view uri,
  const std::string& where)
{
  const std::string folder = std::filesystem::path(documentName).parent_path().string();
  const auto colon = uri.find(':');
  if (uri.empty() || (colon != std::string_view::npos && uri.find('/') > colon) || uri[0] == '/')
  {
    Fail(where + ": uri " + Quote(uri) + " is neither a data URI nor a relative file name");
  }
  std::string decoded;
  for (std::size_t i = 0; i < uri.size(); ++i)
  {
    if (uri[i] != '%')
    {
      decoded += uri[i];
      continue;
    }
    const int high = i + 2 < uri.size() ? HexDigit(uri[i + 1]) : -1;
    const int low = i + 2 < uri.size() ? HexDigit(uri[i + 2]) : -1;
    if (high < 0 || low < 0 || (high == 0 && low == 0))
    {
      Fail(where + ": malformed percent-escape in uri " + Quote(uri));
    }
    decoded += static_cast<char>(16 * high + low);
    i += 2;
  }
  // Inside the document's folder unless trusted; a plain file, checked
  // where it is read (a relative uri can name a device or a pipe).
  return Referred(
    where, uri, [&] { return ResolveReference(documentName, folder, decoded, allowOutside); });
}
}
