#include "errors.h"

#include <iostream>

namespace shadelab
{
int ReportError(const std::string& input, const std::string& problem)
{
  std::cerr << "shadelab: error: " << input << ": " << problem << std::endl;
  return ExitFailure;
}
}
