// Pictures out through OpenImageIO: the format from the file's extension,
// encoded in memory and written by OutputFile (output_file.h), so a reader
// of OUT never sees a partial file. Runs in the shadelab-image-writer
// process (image_writer_process.h), away from the renderer.
#ifndef shadelab_image_output_h
#define shadelab_image_output_h

#include "core/options.h"
#include "image/image_pixels.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
/**
 * Writes image to path as RGB: 8 and 16-bit types store
 * round(max*clamp(I, 0, 1)), float types store I as rendered. metadata
 * becomes string attributes of the file (ImageDescription, Software, ...).
 * Returns an error text (an unknown format, an unwritable path, a pixel type
 * the format cannot store), or an empty string; on error no file is left.
 * pixels8, when given, is the 8-bit picture already quantised (Quantise<uint8_t>),
 * used instead of image's pixels when the type resolves to 8-bit.
 */
std::string WriteImage(const std::string& path, const FloatImage& image, PixelType type,
  const std::vector<std::pair<std::string, std::string>>& metadata,
  const std::vector<std::uint8_t>* pixels8 = nullptr);
}

#endif
