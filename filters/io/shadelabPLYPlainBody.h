/**
 * @brief   the usual binary PLY body, read straight into VTK's arrays
 *
 * Most large PLY files hold one vertex element whose x y z are 32-bit
 * floats (any other scalar properties are skipped) and one face element
 * of a single index list. ReadPlainBody reads such a body in one pass into
 * float points and 32-bit cells, where the general parser goes through a
 * double per value and 64-bit ids and then copies them into VTK's arrays
 * (at 17.8M triangles, a second and about 900 MB more).
 *
 * It returns null for any other file, and for anything unusual in one (a
 * truncated body, a negative list length, an index or a corner count
 * beyond 32 bits): the general parser then reads the file and names the
 * problem in its own words. Values that fit are taken as they are, in range
 * or not, and checked by MakeTriangleMesh like every reader's.
 */
#ifndef shadelabPLYPlainBody_h
#define shadelabPLYPlainBody_h

#include "shadelabPLYHeader.h"

#include <vtkSmartPointer.h>

#include <string_view>

class vtkPolyData;

namespace shadelab::ply
{
/** The points and faces of `body` (binary, in `header`'s byte order), or null. */
vtkSmartPointer<vtkPolyData> ReadPlainBody(std::string_view body, const Header& header);
}

#endif
