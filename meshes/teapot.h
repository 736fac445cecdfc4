/**
 * The Utah teapot, made here from Martin Newell's 32 bicubic Bezier patches
 * (1975; their control points are published figures): the mesh of shadelab's
 * demo, pictures and tests.
 */
#ifndef shadelab_meshes_teapot_h
#define shadelab_meshes_teapot_h

#include "surface_grid.h"

#include <vector>

namespace shadelab::meshes
{
/**
 * Each patch sampled at (n+1) x (n+1) parameter values, with its exact
 * outward normal and its own parameters as texture coordinates; y up, the
 * spout towards +x. n = 10 gives the classic 6,320 triangles once the
 * patches that close to a point (the lid's knob, the bottom's centre) lose
 * their empty triangles.
 */
std::vector<SurfaceGrid> TeapotGrids(int n);
}

#endif
