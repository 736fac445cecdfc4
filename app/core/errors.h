// The one-line messages of the contract: "shadelab: error: INPUT: PROBLEM"
// and "shadelab: warning: INPUT: PROBLEM".
#ifndef shadelab_errors_h
#define shadelab_errors_h

#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
/** Exit status for bad input or a failed render; usage errors exit 2. */
constexpr int ExitFailure = 1;
constexpr int ExitUsage = 2;

/** An input (a file, `FILE:LINE`, "render") and its problem. */
using InputProblem = std::pair<std::string, std::string>;

/** Prints the error line on stderr and returns ExitFailure. */
int ReportError(const std::string& input, const std::string& problem);

/** Prints an error line for each problem (a stage's compile errors) and returns ExitFailure. */
int ReportErrors(const std::vector<InputProblem>& problems);

/**
 * Prints each warning about input on stderr, one line each, once per run
 * (a mesh read again for other normals warns once), unless silenced.
 */
void ReportWarnings(const std::string& input, const std::vector<std::string>& warnings);

/** --quiet: no warnings from here on. */
void SilenceWarnings();
}

#endif
