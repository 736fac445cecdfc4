// shadelab-bench-normals' pieces: the filters it compares, and its two
// tables (bench_normals_main.cxx says what it measures).
#ifndef shadelab_bench_normals_h
#define shadelab_bench_normals_h

#include "vtkShadelabMeshNormals.h"

#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>

#include <string>

class vtkAlgorithm;
class vtkPolyData;

namespace shadelab
{
namespace bench_normals
{
const char* WeightingName(int weighting);

/** vtkPolyDataNormals on mesh: its defaults, or without splitting, consistency and cell normals. */
vtkSmartPointer<vtkPolyDataNormals> VtkNormals(vtkPolyData* mesh, bool defaults);

/** vtkShadelabMeshNormals on mesh (splitting at 30 degrees when asked). */
vtkSmartPointer<vtkShadelabMeshNormals> OurNormals(
  vtkPolyData* mesh, int weighting, bool splitting, bool consistency);

/** A timed configuration whose output has no point normals measured nothing. */
bool HasPointNormals(vtkAlgorithm* filter);

/**
 * Time and peak memory of each configuration on mesh, runs times each, and
 * whether the goals are met: a markdown section on stdout.
 */
void SpeedTable(vtkPolyData* mesh, const std::string& name, int runs);

/** Each weighting's angle to the exact normals of a sphere and a torus: a markdown section. */
void AccuracyTable();
}
}

#endif
