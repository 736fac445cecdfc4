#include "shadelabEightBitStep.h"

#include <vtkShaderProgram.h>

namespace shadelab
{
namespace
{
// The 8-bit step, after everything else in main (VTK's last tag in its
// polydata fragment shader is the coincident-topology offset's).
// shadelabQuantised(v) is Quantised(v, 255) / 255: an estimate in float is
// one too high at most, next to a half step, where comparing with the half
// step's least float settles it exactly. NaN lands on 0, as on the CPU:
// llvmpipe's clamp takes the larger of NaN and 0 first, which is 0 (the
// test's NaN square holds it to that).
const char* const QuantiseDeclaration =
  R"glsl(// The 8-bit capture: k = round(255*clamp(I)), decided exactly, stored as k/255.
uniform float shadelabHalfSteps[255]; // the least float at or above (k - 0.5)/255, k = 1..255
float shadelabQuantised(float v)
{
  float c = clamp(v, 0.0, 1.0);
  int k = int(c * 255.0 + 0.5); // k or k + 1 (IEEE rounding is monotonic, half steps are floats)
  if (k > 0 && c < shadelabHalfSteps[k - 1])
  {
    k -= 1;
  }
  return float(k) / 255.0;
}
vec4 shadelabQuantised(vec4 v)
{
  return vec4(shadelabQuantised(v.r), shadelabQuantised(v.g), shadelabQuantised(v.b),
    shadelabQuantised(v.a));
}
)glsl";
const char* const QuantiseCall = "\n  fragOutput0 = shadelabQuantised(fragOutput0);\n";
const char* const DeclarationTag = "//VTK::Output::Dec";
const char* const LastTag = "//VTK::Coincident::Impl";
// Where a complete stage declares its output: the cache replaced the
// declarations tag with it.
const char* const Output = "out vec4 fragOutput0;";

void Remove(std::string& text, const std::string& part)
{
  if (const auto at = text.find(part); at != std::string::npos)
  {
    text.erase(at, part.size());
  }
}
}

bool AddEightBitStep(std::string& fragment)
{
  const char* anchor = fragment.find(DeclarationTag) != std::string::npos ? DeclarationTag : Output;
  return fragment.find(anchor) != std::string::npos &&
    fragment.find(LastTag) != std::string::npos &&
    vtkShaderProgram::Substitute(fragment, anchor, std::string(QuantiseDeclaration) + anchor) &&
    vtkShaderProgram::Substitute(fragment, LastTag, std::string(LastTag) + QuantiseCall);
}

std::string WithoutEightBitStep(std::string fragment)
{
  Remove(fragment, QuantiseDeclaration);
  Remove(fragment, QuantiseCall);
  return fragment;
}
}
