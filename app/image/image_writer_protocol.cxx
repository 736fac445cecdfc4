#include "image/image_writer_protocol.h"

#include "core/options.h"

#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace shadelab
{
namespace
{
constexpr uint32_t Magic = 0x53484c31;       // "SHL1": a picture
constexpr uint32_t DecodeMagic = 0x53484431; // "SHD1": an image to decode
constexpr uint64_t MaxText = 1 << 24;
// An embedded image's bytes: as large as a glTF buffer is likely to hold.
constexpr uint64_t MaxEncoded = 1ULL << 30;

// Moves size bytes through read or write, across partial transfers and EINTR.
template <typename Call, typename Byte>
bool Transfer(Call call, int fd, Byte* p, size_t size)
{
  while (size > 0)
  {
    const ssize_t n = call(fd, p, size);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return false;
    }
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool WriteAll(int fd, const void* data, size_t size)
{
  return Transfer(::write, fd, static_cast<const char*>(data), size);
}

bool ReadAll(int fd, void* data, size_t size)
{
  return Transfer(::read, fd, static_cast<char*>(data), size);
}

template <typename T>
bool Send(int fd, T value)
{
  return WriteAll(fd, &value, sizeof value);
}

template <typename T>
bool Receive(int fd, T& value)
{
  return ReadAll(fd, &value, sizeof value);
}

bool SendText(int fd, const std::string& s)
{
  return Send<uint64_t>(fd, s.size()) && WriteAll(fd, s.data(), s.size());
}

bool ReceiveText(int fd, std::string& s)
{
  uint64_t size = 0;
  if (!Receive(fd, size) || size > MaxText)
  {
    return false;
  }
  s.resize(size);
  return ReadAll(fd, s.data(), size);
}
}

bool SendImageRequest(int fd, const ImageRequest& r)
{
  bool ok = Send(fd, Magic) && SendText(fd, r.Path) &&
    Send<uint32_t>(fd, static_cast<uint32_t>(r.Type)) &&
    Send<uint32_t>(fd, static_cast<uint32_t>(r.Metadata.size()));
  for (const auto& [key, value] : r.Metadata)
  {
    ok = ok && SendText(fd, key) && SendText(fd, value);
  }
  ok =
    ok && Send(fd, r.Frame.Index) && Send(fd, r.Frame.Count) && Send(fd, r.Frame.FramesPerSecond);
  const bool bytes = !r.Pixels8.empty();
  return ok && Send<int32_t>(fd, r.Image.Width) && Send<int32_t>(fd, r.Image.Height) &&
    Send<uint32_t>(fd, bytes ? 1 : 0) && Send<uint32_t>(fd, r.Image.Alpha ? 1 : 0) &&
    (bytes ? WriteAll(fd, r.Pixels8.data(), r.Pixels8.size())
           : WriteAll(fd, r.Image.Rgba.data(), r.Image.Rgba.size() * sizeof(float)));
}

bool SendDecodeRequest(int fd, const DecodeRequest& r)
{
  return Send(fd, DecodeMagic) && SendText(fd, r.Path) && Send<uint64_t>(fd, r.Bytes.size()) &&
    WriteAll(fd, r.Bytes.data(), r.Bytes.size());
}

bool ReceiveRequestKind(int fd, RequestKind& kind)
{
  uint32_t magic = 0;
  if (!Receive(fd, magic) || (magic != Magic && magic != DecodeMagic))
  {
    return false;
  }
  kind = magic == Magic ? RequestKind::Picture : RequestKind::Decode;
  return true;
}

bool ReceiveDecodeRequest(int fd, DecodeRequest& r)
{
  uint64_t size = 0;
  if (!ReceiveText(fd, r.Path) || !Receive(fd, size) || size > MaxEncoded)
  {
    return false;
  }
  r.Bytes.resize(size);
  return ReadAll(fd, r.Bytes.data(), size);
}

bool SendTextureImage(int fd, const TextureImage& image)
{
  return Send<int32_t>(fd, image.Width) && Send<int32_t>(fd, image.Height) &&
    WriteAll(fd, image.Pixels.data(), image.Pixels.size() * sizeof(float));
}

bool ReceiveTextureImage(int fd, TextureImage& image)
{
  int32_t width = 0, height = 0;
  if (!Receive(fd, width) || !Receive(fd, height) || width < 1 || height < 1 ||
    width > MaxImageSide || height > MaxImageSide ||
    static_cast<long long>(width) * height > MaxImagePixels)
  {
    return false;
  }
  image.Width = width;
  image.Height = height;
  image.Pixels.resize(static_cast<size_t>(width) * height * 3);
  return ReadAll(fd, image.Pixels.data(), image.Pixels.size() * sizeof(float));
}

bool ReceiveImageRequest(int fd, ImageRequest& r)
{
  uint32_t type = 0, count = 0;
  if (!ReceiveText(fd, r.Path) || !Receive(fd, type) ||
    type > static_cast<uint32_t>(PixelType::Float) || !Receive(fd, count) || count > 64)
  {
    return false;
  }
  r.Type = static_cast<PixelType>(type);
  r.Metadata.resize(count);
  for (auto& [key, value] : r.Metadata)
  {
    if (!ReceiveText(fd, key) || !ReceiveText(fd, value))
    {
      return false;
    }
  }
  FramePlace& f = r.Frame;
  if (!Receive(fd, f.Index) || !Receive(fd, f.Count) || !Receive(fd, f.FramesPerSecond) ||
    f.Count < 1 || f.Count > static_cast<uint32_t>(MaxOrbitFrames) || f.Index >= f.Count ||
    !(f.FramesPerSecond > 0 && f.FramesPerSecond <= MaxFramesPerSecond))
  {
    return false;
  }
  int32_t width = 0, height = 0;
  if (!Receive(fd, width) || !Receive(fd, height) || width < 1 || height < 1 ||
    width > MaxImageSide || height > MaxImageSide ||
    static_cast<long long>(width) * height > MaxImagePixels)
  {
    return false;
  }
  uint32_t bytes = 0, alpha = 0;
  if (!Receive(fd, bytes) || bytes > 1 || !Receive(fd, alpha) || alpha > 1)
  {
    return false;
  }
  r.Image.Width = width;
  r.Image.Height = height;
  r.Image.Alpha = alpha == 1;
  const size_t pixels = static_cast<size_t>(width) * height;
  if (bytes)
  {
    r.Image.Rgba.clear();
    r.Pixels8.resize(pixels * Channels(r.Image));
    return ReadAll(fd, r.Pixels8.data(), r.Pixels8.size());
  }
  r.Pixels8.clear();
  r.Image.Rgba.resize(pixels * 4);
  return ReadAll(fd, r.Image.Rgba.data(), r.Image.Rgba.size() * sizeof(float));
}
}
