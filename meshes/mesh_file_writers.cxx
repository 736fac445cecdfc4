#include "mesh_file_writers.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace shadelab::meshes
{
namespace
{
// Shortest text that reads back to the same double.
constexpr int Digits = 17;

class File
{
public:
  File(const std::string& path, std::ios::openmode mode)
    : Path(path)
    , Stream(path, mode | std::ios::trunc)
  {
    this->Stream.precision(Digits);
    this->Check();
  }

  /** Ends the file; throws if any of it could not be written. */
  void Close()
  {
    this->Stream.close();
    this->Check();
  }

  std::ofstream& operator*() { return this->Stream; }

  template <class T>
  void Binary(T value)
  {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T)); // little-endian machines only, as Debian's amd64/arm64
    this->Stream.write(bytes, sizeof(T));
  }

private:
  void Check()
  {
    if (!this->Stream)
    {
      throw std::runtime_error(this->Path + ": cannot be written");
    }
  }

  std::string Path;
  std::ofstream Stream;
};

std::size_t TriangleCount(const SurfaceMesh& mesh)
{
  std::size_t n = 0;
  for (const auto& face : mesh.Faces)
  {
    n += face.size() - 2;
  }
  return n;
}
}

void WriteObj(const std::string& path, const SurfaceMesh& mesh, const ObjContents& contents)
{
  File file(path, std::ios::out);
  auto& out = *file;
  out << "# Made by shadelab-meshes (shadelab's own generator)\n";
  if (!contents.MaterialLibrary.empty())
  {
    out << "mtllib " << contents.MaterialLibrary << "\nusemtl " << contents.Material << '\n';
  }
  for (const Vec3& p : mesh.Points)
  {
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  for (const Vec2& t : contents.Uv ? mesh.Uv : std::vector<Vec2>{})
  {
    out << "vt " << t[0] << ' ' << t[1] << '\n';
  }
  for (const Vec3& n : contents.Normals ? mesh.Normals : std::vector<Vec3>{})
  {
    out << "vn " << n[0] << ' ' << n[1] << ' ' << n[2] << '\n';
  }
  for (const auto& face : mesh.Faces)
  {
    out << 'f';
    for (const Corner& c : face)
    {
      out << ' ' << c.Point + 1;
      if (contents.Uv || contents.Normals)
      {
        out << '/';
      }
      if (contents.Uv)
      {
        out << c.Uv + 1;
      }
      if (contents.Normals)
      {
        out << '/' << c.Normal + 1;
      }
    }
    out << '\n';
  }
  file.Close();
}

void WriteStl(const std::string& path, const SurfaceMesh& mesh)
{
  File file(path, std::ios::out | std::ios::binary);
  char header[80] = "binary STL made by shadelab-meshes";
  (*file).write(header, sizeof(header));
  file.Binary(static_cast<std::uint32_t>(TriangleCount(mesh)));
  for (const auto& face : mesh.Faces)
  {
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
    {
      // The facet normal stays zero: readers compute it, as STL allows.
      for (int a = 0; a < 3; ++a)
      {
        file.Binary(0.0f);
      }
      for (const Corner& c : { face[0], face[k], face[k + 1] })
      {
        for (double x : mesh.Points[c.Point])
        {
          file.Binary(static_cast<float>(x));
        }
      }
      file.Binary(std::uint16_t{ 0 });
    }
  }
  file.Close();
}

void WriteOff(const std::string& path, const SurfaceMesh& mesh)
{
  File file(path, std::ios::out);
  auto& out = *file;
  out << "OFF\n" << mesh.Points.size() << ' ' << mesh.Faces.size() << " 0\n";
  for (const Vec3& p : mesh.Points)
  {
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  for (const auto& face : mesh.Faces)
  {
    out << face.size();
    for (const Corner& c : face)
    {
      out << ' ' << c.Point;
    }
    out << '\n';
  }
  file.Close();
}

void WritePly(const std::string& path, const SurfaceMesh& mesh)
{
  File file(path, std::ios::out | std::ios::binary);
  *file << "ply\nformat binary_little_endian 1.0\ncomment made by shadelab-meshes\n"
        << "element vertex " << mesh.Points.size()
        << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face " << mesh.Faces.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : mesh.Points)
  {
    for (double x : p)
    {
      file.Binary(static_cast<float>(x));
    }
  }
  for (const auto& face : mesh.Faces)
  {
    file.Binary(static_cast<std::uint8_t>(face.size()));
    for (const Corner& c : face)
    {
      file.Binary(static_cast<std::int32_t>(c.Point));
    }
  }
  file.Close();
}
}
