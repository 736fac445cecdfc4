// The one-line error of the contract: "shadelab: error: INPUT: PROBLEM".
#ifndef shadelab_errors_h
#define shadelab_errors_h

#include <string>

namespace shadelab
{
/** Exit status for bad input or a failed render; usage errors exit 2. */
constexpr int ExitFailure = 1;
constexpr int ExitUsage = 2;

/** Prints the error line on stderr and returns ExitFailure. */
int ReportError(const std::string& input, const std::string& problem);

/** The first error VTK reported (through vtkShadelabOutputWindow), or `fallback`. */
std::string FirstVtkError(const char* fallback);
}

#endif
