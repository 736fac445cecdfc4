#include "core/errors.h"

#include <iostream>
#include <set>
#include <utility>

namespace shadelab
{
namespace
{
bool Silenced = false;
}

int ReportError(const std::string& input, const std::string& problem)
{
  std::cerr << "shadelab: error: " << input << ": " << problem << std::endl;
  return ExitFailure;
}

int ReportErrors(const std::vector<InputProblem>& problems)
{
  for (const auto& [input, problem] : problems)
  {
    ReportError(input, problem);
  }
  return ExitFailure;
}

void ReportWarnings(const std::string& input, const std::vector<std::string>& warnings)
{
  static std::set<std::pair<std::string, std::string>> reported;
  for (const std::string& warning : warnings)
  {
    if (!Silenced && reported.emplace(input, warning).second)
    {
      std::cerr << "shadelab: warning: " << input << ": " << warning << std::endl;
    }
  }
}

void SilenceWarnings()
{
  Silenced = true;
}
}
