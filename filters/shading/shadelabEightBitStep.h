// The 8-bit capture's step in a fragment stage (vtkShadelabCapturePass): a
// picture bound for an 8-bit file stores k = round(255*clamp(I)), decided
// exactly in the shader. It is the output's step, not the lecture's, so a
// stage of one's own is given without it and takes it where the picture
// is 8-bit, as the generated stage does, and in the same place.
#ifndef shadelabEightBitStep_h
#define shadelabEightBitStep_h

#include <string>

namespace shadelab
{
/**
 * Adds the step to a fragment stage: a template's (before VTK's output
 * declarations tag) or a complete one's (before its output's declaration,
 * where VTK put it); false when it has neither, or no end of main to call
 * it from (VTK's coincident-topology tag, the last in main).
 */
bool AddEightBitStep(std::string& fragment);

/** The fragment stage without the step, as a float picture's is. */
std::string WithoutEightBitStep(std::string fragment);
}

#endif
