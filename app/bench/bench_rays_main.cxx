// shadelab-bench-rays: the oracle's shadow rays, Embree's hierarchy
// (shadelabRayScene) against VTK's vtkStaticCellLocator (the bins a VTK user
// would reach for), each candidate tested in double by the same
// IntersectTriangle, so both give every triangle's answer and differ only
// in time; and every triangle tested, the reference, on the first rays.
//
//   shadelab-bench-rays MESH [--subdivide LEVELS] [--rays N] [--checked M]
//
// The rays: from N points at random on the mesh's faces (seeded), each moved
// ShadowRayOffset of the diagonal along its face's normal, towards a point
// light two diagonals from the centre; those facing away from it are not
// cast. Each structure's build (milliseconds, Embree's on its threads) and
// its rays per second on one thread; the rays whose answer differs from
// testing every triangle, over the first M, and between the two, over all.
// Exits 1 if any answer differs.
#include "core/errors.h"
#include "core/milliseconds.h"
#include "core/options.h"
#include "scene/mesh_input.h"
#include "shadelabMeshTriangles.h"
#include "shadelabRayScene.h"
#include "shadelabVec3.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkIdList.h>
#include <vtkLogger.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <random>

using namespace shadelab;
using namespace shadelab::vec3;

namespace
{
struct ShadowRay
{
  Ray Cast;
  double Distance;
};

bool Meets(const RayScene& scene, std::int64_t t, const ShadowRay& r)
{
  const TriangleHit h = scene.Intersect(r.Cast, t);
  return h.Inside && h.T <= r.Distance;
}

bool EveryTriangle(const RayScene& scene, const ShadowRay& r)
{
  for (std::size_t t = 0; t < scene.GetTriangles().size(); ++t)
  {
    if (Meets(scene, static_cast<std::int64_t>(t), r))
    {
      return true;
    }
  }
  return false;
}

// The locator's candidates along the ray's segment, widened by tolerance.
bool LocatorBlocked(
  vtkStaticCellLocator* locator, const RayScene& scene, const ShadowRay& r, vtkIdList* cells)
{
  const Vec3 end = r.Cast.Origin + r.Distance * r.Cast.Direction;
  locator->FindCellsAlongLine(r.Cast.Origin.data(), end.data(), 1e-6 * scene.Diagonal(), cells);
  for (vtkIdType i = 0; i < cells->GetNumberOfIds(); ++i)
  {
    if (Meets(scene, cells->GetId(i), r))
    {
      return true;
    }
  }
  return false;
}
}

int main(int argc, char** argv)
{
  vtkShadelabOutputWindow::Install();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app(
    "the oracle's shadow rays: Embree against vtkStaticCellLocator", "shadelab-bench-rays");
  SceneOptions o;
  int subdivide = 0, rays = 100000, checked = 300;
  app.add_option("MESH", o.Mesh)->required();
  app.add_option("--subdivide", subdivide, "Loop subdivision levels first")
    ->check(CLI::Range(0, 4));
  app.add_option("--rays", rays)->check(CLI::Range(1, 100000000));
  app.add_option("--checked", checked, "Rays checked against every triangle")
    ->check(CLI::Range(0, 100000000));
  CLI11_PARSE(app, argc, argv);
  LoadedMesh loaded = LoadMesh(o);
  if (!loaded.Mesh)
  {
    return ReportError(o.Mesh, loaded.Error);
  }
  vtkSmartPointer<vtkPolyData> mesh = loaded.Mesh;
  if (subdivide > 0)
  {
    mesh = LoopSubdivided(mesh, subdivide);
  }

  Clock::time_point start = Clock::now();
  const RayScene scene(PointsOf(mesh), TrianglesOf(mesh));
  const double embreeBuild = Milliseconds(start);
  start = Clock::now();
  auto locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator->SetDataSet(mesh);
  locator->BuildLocator();
  const double locatorBuild = Milliseconds(start);

  double bounds[6];
  mesh->GetBounds(bounds);
  const Vec3 centre{ 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const Vec3 light = centre + (2 * scene.Diagonal() / std::sqrt(3.0)) * Vec3{ 1, 1, 1 };
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<ShadowRay> cast;
  const auto& points = scene.GetPoints();
  for (int i = 0; i < rays; ++i)
  {
    const TriangleCorners& c = scene.GetTriangles()[random() % scene.GetTriangles().size()];
    double u = unit(random), v = unit(random);
    if (u + v > 1)
    {
      u = 1 - u;
      v = 1 - v;
    }
    Vec3 n;
    if (FaceNormal(points[c[0]], points[c[1]], points[c[2]], n) == 0)
    {
      continue;
    }
    const Vec3 p = (1 - u - v) * points[c[0]] + u * points[c[1]] + v * points[c[2]];
    const Vec3 origin = p + (ShadowRayOffset * scene.Diagonal()) * n;
    const Vec3 towards = light - origin;
    if (dot(towards, n) > 0)
    {
      cast.push_back({ { origin, normalize(towards) }, length(towards) });
    }
  }

  std::vector<char> embree(cast.size()), binned(cast.size());
  start = Clock::now();
  for (std::size_t i = 0; i < cast.size(); ++i)
  {
    embree[i] = scene.Blocked(cast[i].Cast, 0, cast[i].Distance);
  }
  const double embreeRays = Milliseconds(start);
  auto cells = vtkSmartPointer<vtkIdList>::New();
  start = Clock::now();
  for (std::size_t i = 0; i < cast.size(); ++i)
  {
    binned[i] = LocatorBlocked(locator, scene, cast[i], cells);
  }
  const double locatorRays = Milliseconds(start);
  int embreeOff = 0, locatorOff = 0, shadowed = 0;
  const std::size_t reference = std::min<std::size_t>(checked, cast.size());
  start = Clock::now();
  for (std::size_t i = 0; i < reference; ++i)
  {
    const bool every = EveryTriangle(scene, cast[i]);
    embreeOff += embree[i] != every;
    locatorOff += binned[i] != every;
  }
  const double everyRays = Milliseconds(start);
  int apart = 0; // over every ray: the two structures' answers
  for (std::size_t i = 0; i < cast.size(); ++i)
  {
    shadowed += embree[i];
    apart += embree[i] != binned[i];
  }

  std::printf("%zu triangles; %zu shadow rays cast, %d blocked; the two structures' answers "
              "differ on %d\n\n",
    scene.GetTriangles().size(), cast.size(), shadowed, apart);
  std::printf("| candidates from | build ms | rays per second, one thread | answers unlike every "
              "triangle's (of %zu) |\n|---|---:|---:|---:|\n",
    reference);
  const double n = static_cast<double>(cast.size());
  std::printf(
    "| Embree's hierarchy | %.0f | %.3g | %d |\n", embreeBuild, 1000 * n / embreeRays, embreeOff);
  std::printf("| vtkStaticCellLocator | %.0f | %.3g | %d |\n", locatorBuild, 1000 * n / locatorRays,
    locatorOff);
  if (reference > 0)
  {
    std::printf("| every triangle | 0 | %.3g | 0 |\n", 1000 * reference / everyRays);
  }
  return embreeOff + locatorOff + apart == 0 ? 0 : 1;
}
