// Images in for textures, through OpenImageIO, in the shadelab-image-writer
// process (image_writer_process.h: the one that links OpenImageIO): a file,
// or an image's bytes embedded in a mesh file, decoded on the CPU to RGB
// floats, bottom row first (TextureImage).
//
// Colour: the stored values as they are, in 0..1 for integer samples (an
// 8-bit 128 is 128/255), whatever colour space the file names: shadelab's
// colours are display values throughout, as the lecture's material numbers
// are, and pictures are written as computed (doc/design.md, "Colour").
// Grey images give R = G = B; alpha is dropped.
#ifndef shadelab_texture_decoding_h
#define shadelab_texture_decoding_h

#include "image/image_writer_protocol.h"

#include <string>

namespace shadelab
{
/** Decodes request's image into image: "" or the problem, one line. */
std::string DecodeTexture(const DecodeRequest& request, TextureImage& image);
}

#endif
