#include "shadelabAssimpMeshBytes.h"

#include "shadelabMeshReadError.h"

#include <cstring>
#include <type_traits>

namespace shadelab
{
namespace
{
template <typename T>
constexpr bool Plain = std::is_trivially_copyable<T>::value;

// Each struct's fields, in one list for both directions: a field added to
// a struct is added here once. (The writer takes them as non-const only
// to share this list; it changes nothing.)
template <typename Archive>
void Fields(Archive& a, Material& m)
{
  a(m.Name), a(m.Ka), a(m.Kd), a(m.Ks), a(m.Ns), a(m.Translucency);
}

template <typename Archive>
void Fields(Archive& a, PartMaterial& p)
{
  a(p.Name), a(p.Index), a(p.Coefficients), a(p.KdTexture), a(p.KaTexture), a(p.KsTexture),
    a(p.KsTextureScale), a(p.NormalTexture), a(p.NormalScale), a(p.NormalFromBump);
}

template <typename Archive>
void Fields(Archive& a, Texture& t)
{
  a(t.Source), a(t.Bytes), a(t.WrapS), a(t.WrapT), a(t.MagFilter), a(t.MinFilter);
}

template <typename Archive>
void Fields(Archive& a, PolygonMesh& m)
{
  a(m.Points), a(m.FloatPoints), a(m.Normals), a(m.Colors), a(m.TextureCoordinates),
    a(m.FileVertices), a(m.FaceOffsets), a(m.FaceIds), a(m.StripOffsets), a(m.StripIds), a(m.Parts);
}

template <typename Archive>
void Fields(Archive& a, AssimpMesh& m)
{
  a(m.Mesh), a(m.Parts), a(m.Textures), a(m.Warnings);
}

class Writer
{
public:
  template <typename T>
  void operator()(T& value)
  {
    if constexpr (Plain<T>)
    {
      this->Bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    else
    {
      Fields(*this, value);
    }
  }
  template <typename T>
  void operator()(std::vector<T>& values)
  {
    this->Count(values.size());
    if constexpr (Plain<T>)
    {
      this->Bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    else
    {
      for (T& value : values)
      {
        (*this)(value);
      }
    }
  }
  void operator()(std::string& text)
  {
    this->Count(text.size());
    this->Bytes.append(text);
  }
  std::string Bytes;

private:
  void Count(size_t count)
  {
    this->Bytes.append(reinterpret_cast<const char*>(&count), sizeof count);
  }
};

class Reader
{
public:
  explicit Reader(const std::string& bytes)
    : Bytes(bytes)
  {
  }
  template <typename T>
  void operator()(T& value)
  {
    if constexpr (Plain<T>)
    {
      std::memcpy(&value, this->Take(sizeof value), sizeof value);
    }
    else
    {
      Fields(*this, value);
    }
  }
  template <typename T>
  void operator()(std::vector<T>& values)
  {
    // Each element takes one byte at least: a count beyond what is left is cut short.
    const size_t count = this->Count(Plain<T> ? sizeof(T) : 1);
    values.resize(count);
    if constexpr (Plain<T>)
    {
      const char* bytes = this->Take(count * sizeof(T));
      if (count > 0) // an empty vector's data() may be null, which memcpy may not take
      {
        std::memcpy(values.data(), bytes, count * sizeof(T));
      }
    }
    else
    {
      for (T& value : values)
      {
        (*this)(value);
      }
    }
  }
  void operator()(std::string& text)
  {
    const size_t count = this->Count(1);
    text.assign(this->Take(count), count);
  }
  bool AtEnd() const { return this->Position == this->Bytes.size(); }

private:
  [[noreturn]] static void CutShort()
  {
    throw MeshReadError("the reading process's answer is cut short", vtkErrorCode::UnknownError);
  }
  size_t Count(size_t elementSize)
  {
    size_t count = 0;
    (*this)(count);
    if (count > (this->Bytes.size() - this->Position) / elementSize)
    {
      CutShort();
    }
    return count;
  }
  const char* Take(size_t count)
  {
    if (count > this->Bytes.size() - this->Position)
    {
      CutShort();
    }
    const char* at = this->Bytes.data() + this->Position;
    this->Position += count;
    return at;
  }
  const std::string& Bytes;
  size_t Position = 0;
};
}

std::string EncodeAssimpMesh(const AssimpMesh& mesh)
{
  Writer out;
  out(const_cast<AssimpMesh&>(mesh));
  return std::move(out.Bytes);
}

AssimpMesh DecodeAssimpMesh(const std::string& bytes)
{
  AssimpMesh mesh;
  Reader in(bytes);
  in(mesh);
  if (!in.AtEnd())
  {
    throw MeshReadError(
      "the reading process's answer has bytes past its end", vtkErrorCode::UnknownError);
  }
  return mesh;
}
}
