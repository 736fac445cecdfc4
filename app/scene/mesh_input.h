// A mesh file in, ready to render: read by the filters library's reader,
// with the vertex normals that --normals and --weighting ask for.
#ifndef shadelab_mesh_input_h
#define shadelab_mesh_input_h

#include "core/options.h"
#include "core/phase_timer.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <string>
#include <vector>

class vtkPolyData;

namespace shadelab
{
struct LoadedMesh
{
  vtkSmartPointer<vtkPolyData> Mesh; // null on error
  std::string Error;                 // one line, without the file name
  bool NormalsFromFile = false;
  vtkIdType DuplicatedFaces = 0; // ComputedNormals's, when they were computed
};

/** Whether a part of mesh has a normal map of the file's own (PartNormalTexture). */
bool FileMapsNormals(vtkPolyData* mesh);

/**
 * Reads options.Mesh and computes its normals as asked; warnings are
 * reported. `timer` (if given) times the phases "read" and "normals" (and
 * "tangents", for a normal map).
 * Computed normals come with face normals only if `cellNormals`: no
 * picture draws them (flat shading computes its own), a mesh file does.
 */
LoadedMesh LoadMesh(
  const SceneOptions& options, PhaseTimer* timer = nullptr, bool cellNormals = false);

struct ComputedNormals
{
  vtkSmartPointer<vtkPolyData> Mesh; // null on failure
  std::string Error;                 // why it failed: one line
  std::vector<std::string> Warnings; // what the filter warned of
  vtkIdType DuplicatedFaces = 0;     // faces OpenMesh refused, given vertices of their own
};

/**
 * mesh with vertex normals computed by vtkShadelabMeshNormals as settings
 * say, and with face normals if `cellNormals`.
 */
ComputedNormals ComputeNormals(
  vtkPolyData* mesh, const NormalsSettings& settings, bool cellNormals = false);

/**
 * mesh welded (vtkCleanPolyData) and Loop-subdivided `levels` times, with
 * double points as shadelab's readers give: the large meshes of the
 * benchmarks (the bunny: 2 levels 1.1M triangles, 3 levels 4.4M).
 */
vtkSmartPointer<vtkPolyData> LoopSubdivided(vtkPolyData* mesh, int levels);
}

#endif
