// Mach bands as a measurement (`shadelab profile`): the rendered intensity
// along a line of the picture, for each rule, with its first and second
// differences, beside the oracle's smooth (phong) curve. Gouraud's kinks at
// the triangles' edges, where the eye sees Mach bands, are steps of the
// first difference and spikes of the second; flat's steps are spikes of the
// first.
#ifndef shadelab_line_profile_h
#define shadelab_line_profile_h

#include "core/options.h"
#include "image/image_pixels.h"
#include "shadelabIllumination.h"

#include <vtkType.h>

#include <string>
#include <vector>

namespace shadelab
{
/**
 * The pixels a line from `from` to `to` (pixel X from the left, Y from the
 * top) passes, one per column or row along its longer axis, the nearest
 * pixel of the other: both ends included, none twice.
 */
std::vector<Pixel> LinePixels(Pixel from, Pixel to);

/** Rec. 709's luminance of a linear RGB value, as the eye weighs the channels. */
double Luminance(const Rgb& c);

/** One rule's values along the line. */
struct ProfileCurve
{
  std::string Label;
  std::vector<Rgb> Values;
  std::vector<double> Luminance;
  // Of the luminance, per sample; NaN where a sample it takes is off the
  // mesh (a silhouette's jump is not the shading's): First[i] = L[i+1] -
  // L[i] (none at the last sample), Second[i] = L[i+1] - 2 L[i] + L[i-1]
  // (none at either end).
  std::vector<double> First, Second;
};

struct LineProfile
{
  std::vector<Pixel> Samples;
  std::vector<vtkIdType> Triangles;  // the triangle each sample's centre meets, -1 off the mesh
  std::vector<double> EdgeDistances; // from that point to its triangle's nearest edge, in pixels
  std::vector<ProfileCurve> Curves;  // the modes', in their order
  ProfileCurve Oracle;               // the double-precision oracle's phong
};

/** The samples i whose triangle differs from sample i + 1's, both on the mesh: an edge between. */
std::vector<std::size_t> EdgeCrossings(const LineProfile& profile);

/** label's curve read from picture at the profile's samples, with its differences. */
ProfileCurve ReadCurve(
  const std::string& label, const FloatImage& picture, const LineProfile& profile);

/** curve made of values (one per sample), with its differences. */
ProfileCurve MakeCurve(
  const std::string& label, std::vector<Rgb> values, const std::vector<vtkIdType>& triangles);

/**
 * The profile as CSV, a row per sample: sample, x, y, triangle, edge (the
 * distance to the triangle's nearest edge in pixels), then per
 * curve (the modes', then "oracle") its luminance, r, g, b, first and
 * second difference; a difference that is not defined is left empty.
 */
std::string ProfileCsv(const LineProfile& profile);
}

#endif
