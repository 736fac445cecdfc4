// The speed-accuracy measurements: how far a rendered picture is
// from the exact one, the rows `shadelab bench` writes (CSV, JSON) and
// `shadelab advise` reads back.
#ifndef shadelab_speed_accuracy_h
#define shadelab_speed_accuracy_h

#include "image/image_pixels.h"
#include "shadelabExactImage.h"

#include <iosfwd>
#include <string>
#include <vector>

class vtkPolyData;

namespace shadelab
{
/**
 * Pixels within this many pixels (Chebyshev distance) of the silhouette, of
 * either picture, are not compared: there geometry, not shading, differs.
 */
constexpr int SilhouetteBand = 2;

struct AccuracyMetrics
{
  double Rmse = 0;     // over the compared pixels' R, G and B values
  double MaxError = 0; // the largest |rendered - exact| of any channel
  double Psnr = 0;     // 10 log10(1 / MSE): peak 1, an 8-bit display's full scale
  long long Pixels = 0;
};

/**
 * rendered (alpha > 0.5 where the mesh covers a pixel) against exact, over
 * the pixels both cover, less the silhouette band. Unclamped intensities:
 * the equation's error, before the display clamps it.
 */
AccuracyMetrics CompareWithExact(const FloatImage& rendered, const ExactImage& exact);

/**
 * How coarse a mesh is for shading: the mean angle, in degrees, between the
 * vertex normals at the two ends of an edge (each edge once). Flat's error
 * grows with it about linearly and Gouraud's and Phong's about
 * quadratically, whatever the mesh's size on screen; `advise` compares
 * meshes by it.
 */
double MeanEdgeNormalAngle(vtkPolyData* meshWithNormals);

/** A triangle count as the chart and `advise` print it: 640, 20k, 1.3M. */
std::string TriangleCountText(double triangles);

/** One row of speed_accuracy.csv. */
struct SpeedAccuracyRow
{
  std::string Surface; // sphere, torus
  std::string Shading; // flat, gouraud, phong
  std::string Weighting;
  long long Triangles = 0;
  int Width = 0;
  int Height = 0;
  double MsPerFrame = 0; // median after the first frame, read-back included
  double Rmse = 0;
  double MaxError = 0;
  double Psnr = 0;
  double NormalsMs = 0; // computing the vertex normals
  double CompileMs = 0; // the first frame less a steady one: shaders compiled, buffers uploaded
  double EdgeAngle = 0; // MeanEdgeNormalAngle, degrees
  long long Pixels = 0; // compared
};

/**
 * What the measurements should show, checked (each surface, size and
 * weighting on its own): the error falls as the triangles grow for every
 * rule, and phong < gouraud < flat at every level. One line per exception;
 * none when all holds.
 */
std::vector<std::string> CheckSpeedAccuracyOrder(const std::vector<SpeedAccuracyRow>& rows);

/** The CSV (a header row, then one line per row), written by OutputFile: "" or the error. */
std::string WriteSpeedAccuracyCsv(
  const std::string& path, const std::vector<SpeedAccuracyRow>& rows);
/** The same rows as a JSON array of objects with the CSV's column names. */
std::string WriteSpeedAccuracyJson(
  const std::string& path, const std::vector<SpeedAccuracyRow>& rows);
/** Reads what WriteSpeedAccuracyCsv wrote (columns by name, in any order); an error text or "". */
std::string ReadSpeedAccuracyCsv(const std::string& path, std::vector<SpeedAccuracyRow>& rows);
/** The same from a stream. */
std::string ParseSpeedAccuracyCsv(std::istream& in, std::vector<SpeedAccuracyRow>& rows);
}

#endif
