// Pictures out through OpenImageIO: the format from the file's extension,
// written to a temporary name in the same folder and renamed, so a reader of
// OUT never sees a partial file. Runs in the shadelab-image-writer process
// (image_writer_process.h), away from the renderer.
#ifndef shadelab_image_output_h
#define shadelab_image_output_h

#include "options.h"

#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
/** A rendered picture: RGBA floats, unclamped, bottom row first. */
struct FloatImage
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Rgba;
};

/** The pixel type that Auto means for path: float for EXR, HDR and PFM, else 8-bit. */
PixelType ResolvePixelType(const std::string& path, PixelType requested);

/**
 * Writes image to path as RGB: 8 and 16-bit types store
 * round(max*clamp(I, 0, 1)), float types store I as rendered. metadata
 * becomes string attributes of the file (ImageDescription, Software, ...).
 * Returns an error text (an unknown format, an unwritable path, a pixel type
 * the format cannot store), or an empty string; on error no file is left.
 */
std::string WriteImage(const std::string& path, const FloatImage& image, PixelType type,
  const std::vector<std::pair<std::string, std::string>>& metadata);
}

#endif
