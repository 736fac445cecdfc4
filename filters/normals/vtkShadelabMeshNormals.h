/**
 * @class   vtkShadelabMeshNormals
 * @brief   face and vertex normals of a triangle mesh, computed with OpenMesh
 *
 * Input: a polydata of triangles (what vtkShadelabMeshReader gives: it
 * triangulates polygons, so a face here is a triangle and its Newell normal
 * is its cross product); other cells are dropped, a polygon of more than 3
 * vertices or an id out of range is an error. Output: the mesh with unit
 * point normals ("Normals", float, the active normals) and, unless
 * ComputeCellNormals is off, unit cell normals ("Normals" in the cell
 * data), computed in double. A vertex normal is the
 * normalised sum of the unit normals of the faces around the vertex, each
 * weighted by:
 *
 * - Uniform: 1 (vtkPolyDataNormals's average);
 * - Area: the face's area;
 * - Angle: the face's angle at the vertex (Thuermer & Wuethrich 1998);
 * - Max: sin(angle) / (|a| |b|), a and b the face's edges at the vertex, i.e.
 *   (a x b) / (|a|^2 |b|^2) (Max 1999; exact for points on a sphere);
 * - Loop: not a weighting but OpenMesh's Loop-subdivision limit normal
 *   (calc_vertex_normal_loop), defined at interior vertices of a closed fan;
 *   at boundary vertices, split vertices and vertices of duplicated faces,
 *   where the limit normal of a smooth surface does not apply, the angle
 *   weighting is used.
 *
 * Without splitting, the output has the input's points in the input's order
 * and the input's triangles. With Splitting on, the faces around a vertex
 * are grouped into runs between separating edges: edges where adjacent
 * faces meet at more than FeatureAngle degrees, boundary edges, and
 * non-manifold edges (as in vtkPolyDataNormals). Each run beyond the first
 * becomes a new point (appended after the input's points, in the order of
 * the points they split) with its own normal, and the triangles refer to it:
 * a cube's corner becomes three points.
 *
 * Points that a reader split from one vertex of its file (an OBJ vertex at
 * a texture's seam: the point data "FileVertex", shadelabTriangleMesh.h)
 * are one vertex here: the normals are computed on the file's vertices,
 * each welded onto the lowest-numbered of its points, exactly as for the
 * file without the seams, and every point gets its vertex's normal; the
 * points and their data stay as they are (shadelabFileVertices.h). With
 * splitting, a point whose corners lie in different runs gets a copy for
 * each further run. A FileVertex that is not one point number per point is
 * an error.
 *
 * OpenMesh's connectivity is built only where splitting or Loop normals
 * need it: the other normals are sums over each vertex's faces, which need
 * none (the same bits without it, at a fraction of the time and memory).
 * Once built for an input (by its modification time) it is kept, with the
 * face normals and corner weights computed beside it, so that changing the
 * weighting or the feature angle recomputes normals without rebuilding it.
 * Faces that OpenMesh refuses (they would make a non-manifold edge or
 * vertex, or they repeat a vertex) still get normals, through copies of
 * their vertices (with splitting, they keep those as points of their own);
 * GetNumberOfDuplicatedFaces() reports how many where the connectivity was
 * used. Zero-area faces add no weight and no NaN; a vertex with no face of positive area, or whose
 * faces' weighted normals cancel (a face and its reverse: the sum shorter
 * than 1e-12 of the weights' sum, rounding in no direction), gets
 * (0,0,0), which shadelab's shaders treat as "no normal". Consistency on
 * makes the faces' orientation consistent within each edge-connected part,
 * as vtkPolyDataNormals does: the part's lowest-numbered face keeps its
 * orientation and faces that disagree with their neighbours are reversed in
 * the output (across manifold edges; a non-manifold edge does not propagate
 * orientation).
 *
 * Both cores are used: the face geometry is computed while OpenMesh builds
 * the connectivity, and the sums, the splitting and Loop normals run
 * through vtkSMPTools; each point still receives its faces' terms in the
 * faces' order, so the bits do not depend on the number of threads (see
 * SumChunks). Without the connectivity the sum computes each face's
 * normal, area and weights as it adds it (and writes its cell normal), in
 * the same order and with the same arithmetic: one pass over the faces and
 * nothing stored per face (7 doubles a face) at the same bits.
 */
#ifndef vtkShadelabMeshNormals_h
#define vtkShadelabMeshNormals_h

#include "shadelab_filtersModule.h" // the export macro

#include "shadelabNames.h"

#include <vtkPolyDataAlgorithm.h>

#include <array>
#include <memory>
#include <utility>

class SHADELAB_FILTERS_EXPORT vtkShadelabMeshNormals : public vtkPolyDataAlgorithm
{
public:
  static vtkShadelabMeshNormals* New();
  vtkTypeMacro(vtkShadelabMeshNormals, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Weightings
  {
    Uniform = 0,
    Area,
    Angle,
    Max,
    Loop
  };
  vtkSetClampMacro(Weighting, int, Uniform, Loop);
  vtkGetMacro(Weighting, int);
  /** Sets the weighting by its name (NameTable below); false if unknown. */
  bool SetWeightingByName(const char* name);

  vtkSetMacro(Splitting, bool);
  vtkGetMacro(Splitting, bool);
  vtkBooleanMacro(Splitting, bool);
  vtkSetClampMacro(FeatureAngle, double, 0, 180);
  vtkGetMacro(FeatureAngle, double);

  vtkSetMacro(Consistency, bool);
  vtkGetMacro(Consistency, bool);
  vtkBooleanMacro(Consistency, bool);

  /**
   * Whether the output has the unit face normals in its cell data (On, as
   * vtkPolyDataNormals's default); Off saves a float triple a face where
   * nothing reads them.
   */
  vtkSetMacro(ComputeCellNormals, bool);
  vtkGetMacro(ComputeCellNormals, bool);
  vtkBooleanMacro(ComputeCellNormals, bool);

  /**
   * How many contiguous chunks of faces the vertex normals are summed in,
   * on the cores at once: 0 (the default) one per SMP thread. Every value
   * gives the same bits (each point still sums its faces in their order);
   * tests set several to exercise that on any machine.
   */
  vtkSetClampMacro(SumChunks, int, 0, 254);
  vtkGetMacro(SumChunks, int);

  /**
   * Faces that needed duplicated vertices in the last update; 0 unless it
   * used OpenMesh's connectivity (Splitting or Loop).
   */
  vtkGetMacro(NumberOfDuplicatedFaces, vtkIdType);

  /**
   * How often the face geometry (and the OpenMesh connectivity, where
   * needed) has been built: once per new input (or Consistency change), not
   * when only the weighting or the feature angle changed.
   */
  vtkGetMacro(NumberOfConnectivityBuilds, int);

protected:
  vtkShadelabMeshNormals();
  ~vtkShadelabMeshNormals() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkShadelabMeshNormals(const vtkShadelabMeshNormals&) = delete;
  void operator=(const vtkShadelabMeshNormals&) = delete;

  int Weighting = Angle;
  bool Splitting = false;
  double FeatureAngle = 30;
  bool Consistency = false;
  bool ComputeCellNormals = true;
  int SumChunks = 0;
  vtkIdType NumberOfDuplicatedFaces = 0;
  int NumberOfConnectivityBuilds = 0;

  struct Cache; // the OpenMesh mesh of the last input, and that input's MTime
  std::unique_ptr<Cache> Cached;
};

namespace shadelab
{
template <>
struct NameTable<vtkShadelabMeshNormals::Weightings>
{
  static constexpr std::array<std::pair<vtkShadelabMeshNormals::Weightings, const char*>, 5>
    Entries{ { { vtkShadelabMeshNormals::Uniform, "uniform" },
      { vtkShadelabMeshNormals::Area, "area" }, { vtkShadelabMeshNormals::Angle, "angle" },
      { vtkShadelabMeshNormals::Max, "max" }, { vtkShadelabMeshNormals::Loop, "loop" } } };
};
}

#endif
