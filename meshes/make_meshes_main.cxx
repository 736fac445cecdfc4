// shadelab-meshes DIR: writes the meshes that shadelab makes itself (the
// Utah teapot from Newell's patches, a torus) into DIR, in every format the
// tests read, with a texture and its material library. The build runs it;
// the demo, the guide's pictures and the tests read what it writes.
#include "mesh_file_writers.h"
#include "teapot.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace
{
using namespace shadelab::meshes;

// A 256x256 8-bit RGB texture of 8x8 squares in two colours that change
// smoothly across the picture: the squares show how texture coordinates run,
// and the colours where on the texture a point is.
void WriteTexture(const std::string& path)
{
  constexpr int Size = 256, Square = 32;
  std::vector<unsigned char> pixels(Size * Size * 3);
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const bool light = ((x / Square) + (y / Square)) % 2 == 0;
      const double s = x / (Size - 1.0), t = y / (Size - 1.0);
      const double rgb[3] = { 0.35 + 0.6 * s, 0.35 + 0.6 * t, light ? 0.9 : 0.25 };
      for (int c = 0; c < 3; ++c)
      {
        pixels[(y * Size + x) * 3 + c] =
          static_cast<unsigned char>(std::lround((light ? rgb[c] : 0.5 * rgb[c]) * 255));
      }
    }
  }
  auto out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, OIIO::ImageSpec(Size, Size, 3, OIIO::TypeDesc::UINT8)) ||
    !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
  {
    throw std::runtime_error(path + ": cannot be written");
  }
}

void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();
  if (!out)
  {
    throw std::runtime_error(path + ": cannot be written");
  }
}
}

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: shadelab-meshes DIR\n";
    return 2;
  }
  try
  {
    const std::string dir = argv[1];
    std::filesystem::create_directories(dir);
    const auto at = [&](const char* name) { return dir + "/" + name; };

    // The classic tessellation: 6,320 triangles, texture coordinates split
    // where patches meet.
    const SurfaceMesh teapot = MeshFromGrids(TeapotGrids(10), false);
    WriteObj(at("teapot.obj"), teapot, {});
    WriteStl(at("teapot.stl"), teapot);
    WriteOff(at("teapot.off"), teapot);
    WriteObj(at("teapot-textured.obj"), teapot, { true, false, "teapot-textured.mtl", "teapot" });
    WriteText(at("teapot-textured.mtl"),
      "# Made by shadelab-meshes\nnewmtl teapot\nKa 0.2 0.2 0.2\nKd 0.8 0.8 0.8\n"
      "Ks 0.1 0.1 0.1\nNs 20\nmap_Ka teapot-texture.png\nmap_Kd teapot-texture.png\n");
    WriteTexture(at("teapot-texture.png"));

    // A finer teapot (65,280 triangles) for the tests that need many.
    const SurfaceMesh fine = MeshFromGrids(TeapotGrids(32), false);
    WriteObj(at("teapot-fine.obj"), fine, { false, false, "", "" });
    WritePly(at("teapot-fine.ply"), fine);

    // Quads (triangles where a patch closes to a point) with the surface's
    // exact normals, as a modeller exports a smooth quad mesh.
    WriteObj(at("teapot-quads.obj"), MeshFromGrids(TeapotGrids(6), true), { true, true, "", "" });

    // A coarse torus: 576 triangles, where Gouraud and Phong differ most.
    WriteObj(at("torus.obj"), MeshFromGrids({ TorusGrid(1.0, 0.4, 12, 24) }, false), {});
  }
  catch (const std::exception& e)
  {
    std::cerr << "shadelab-meshes: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
