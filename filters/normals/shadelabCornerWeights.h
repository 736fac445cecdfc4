/**
 * @brief   the weight of each face corner in a vertex normal, per weighting
 *
 * A vertex normal sums the unit normals of the faces around it, each
 * weighted at the vertex's corner by vtkShadelabMeshNormals's Weighting:
 * Uniform 1, Area the face's area (here twice it: the scale cancels), Angle
 * the corner's angle, Max sin(angle) / (|a| |b|). Angle and Max depend on
 * the corner and are computed per face; Loop sums as Angle wherever
 * OpenMesh's limit normal does not apply.
 */
#ifndef shadelabCornerWeights_h
#define shadelabCornerWeights_h

#include "shadelabNormalsMesh.h"
#include "vtkShadelabMeshNormals.h"

namespace shadelab::normals
{
/** The weighting whose weights are summed: Loop's where no limit normal. */
inline int SummedWeighting(int weighting)
{
  return weighting == vtkShadelabMeshNormals::Loop ? vtkShadelabMeshNormals::Angle : weighting;
}

/** Angle and Max weigh each corner differently: ComputeCornerWeights. */
inline bool HasCornerWeights(int weighting)
{
  return weighting == vtkShadelabMeshNormals::Angle || weighting == vtkShadelabMeshNormals::Max;
}

/**
 * Angle's or Max's weights of the corners of faces begin to end - 1 (3 a
 * face, into `weights`, face begin's first), from the points `xyz`, the
 * faces' 3 point ids each and the doubled areas of faces begin to end - 1
 * (`doubleArea`, face begin's first; zero for faces of no area, which
 * weigh 0).
 */
void ComputeCornerWeights(int weighting, const double* xyz, const Id* triangles,
  const double* doubleArea, vtkIdType begin, vtkIdType end, double* weights);

/**
 * The weight of corner `corner` of a face of doubled area `doubleArea`;
 * `cornerWeights` are ComputeCornerWeights's where HasCornerWeights.
 */
inline double CornerWeight(
  int weighting, double doubleArea, const double* cornerWeights, vtkIdType corner)
{
  return weighting == vtkShadelabMeshNormals::Uniform ? 1
    : weighting == vtkShadelabMeshNormals::Area       ? doubleArea
                                                      : cornerWeights[corner];
}
}

#endif
