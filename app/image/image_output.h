// Pictures out through OpenImageIO: the format from the file's extension,
// encoded in memory and written by OutputFile (output_file.h), so a reader
// of OUT never sees a partial file; an animated GIF takes an --orbit's
// frames as its subimages. Runs in the shadelab-image-writer process
// (image_writer_process.h), away from the renderer.
#ifndef shadelab_image_output_h
#define shadelab_image_output_h

#include "image/picture_files.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

namespace shadelab
{
/** OpenImageIO's message s (often several lines) as one line. */
std::string OneLine(std::string s);

/**
 * Writes RGB (RGBA with alpha): 8 and 16-bit types store
 * round(max*clamp(I, 0, 1)), float types store I as rendered. The request's
 * metadata becomes string attributes of the file (ImageDescription,
 * Software, ...); an 8-bit request's pixels come quantised (Pixels8).
 */
class ImageEncoder : public Encoder
{
public:
  /**
   * Opens first's file for its frames: "" or the problem (an unknown format,
   * one that cannot hold the frames, the alpha or the pixel type).
   */
  std::string Open(const ImageRequest& first);
  std::string Add(const ImageRequest& frame) override;
  std::string Finish() override;

private:
  std::string Path;
  PixelType Type = PixelType::UInt8; // as resolved for the format
  OIIO::ImageSpec Spec;
  std::vector<unsigned char> Encoded;
  std::unique_ptr<OIIO::Filesystem::IOVecOutput> Memory;
  std::unique_ptr<OIIO::ImageOutput> Output;
};
}

#endif
