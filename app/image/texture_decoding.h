// Images in for textures, through OpenImageIO, in the shadelab-image-writer
// process (image_writer_process.h: the one that links OpenImageIO): a file,
// or an image's bytes embedded in a mesh file, decoded on the CPU to linear
// RGB floats, bottom row first (TextureImage).
//
// Colour: the file's colour space as OpenImageIO reports it
// ("oiio:ColorSpace") decides: sRGB is decoded to linear, linear stays,
// "GammaCorrectedG" is raised to the power G. A file that says nothing is
// sRGB when its samples are 8-bit and linear otherwise (16-bit, half, float).
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
