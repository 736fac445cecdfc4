#include "errors.h"

#include "vtkShadelabOutputWindow.h"

#include <vtkOutputWindow.h>

#include <iostream>

namespace shadelab
{
int ReportError(const std::string& input, const std::string& problem)
{
  std::cerr << "shadelab: error: " << input << ": " << problem << std::endl;
  return ExitFailure;
}

std::string FirstVtkError(const char* fallback)
{
  auto* window = vtkShadelabOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  return window && !window->GetFirstError().empty() ? window->GetFirstError() : fallback;
}
}
