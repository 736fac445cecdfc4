#include "vtkShadelabOutputWindow.h"

#include <vtkObjectFactory.h>
#include <vtkSmartPointer.h>

#include <iostream>

vtkStandardNewMacro(vtkShadelabOutputWindow);

vtkShadelabOutputWindow* vtkShadelabOutputWindow::Install()
{
  if (auto* installed = SafeDownCast(vtkOutputWindow::GetInstance()))
  {
    return installed; // open scopes keep pointing at it
  }
  auto window = vtkSmartPointer<vtkShadelabOutputWindow>::New();
  vtkOutputWindow::SetInstance(window);
  return window; // the global instance holds the reference now
}

std::string vtkShadelabOutputWindow::OneLine(const char* text)
{
  std::string s = text ? text : "";
  // "ERROR: In /path/file.cxx, line 12\nvtkClass (0x55..): message\n\n"
  if (s.rfind("ERROR: In ", 0) == 0 || s.rfind("Warning: In ", 0) == 0 ||
    s.rfind("Generic Warning: In ", 0) == 0)
  {
    const auto eol = s.find('\n');
    s = eol == std::string::npos ? std::string() : s.substr(eol + 1);
  }
  const auto eol = s.find('\n');
  const auto tag = s.find("): ");
  if (tag != std::string::npos && (eol == std::string::npos || tag < eol))
  {
    s = s.substr(tag + 3);
  }
  for (char& c : s)
  {
    if (c == '\n' || c == '\r' || c == '\t')
    {
      c = ' ';
    }
  }
  while (!s.empty() && s.back() == ' ')
  {
    s.pop_back();
  }
  return s;
}

void vtkShadelabOutputWindow::DisplayText(const char* text)
{
  if (this->Echo)
  {
    std::cerr << text;
  }
}

void vtkShadelabOutputWindow::DisplayErrorText(const char* text)
{
  if (this->Scope)
  {
    this->Scope->AddError(OneLine(text));
  }
  this->DisplayText(text);
}

void vtkShadelabOutputWindow::DisplayWarningText(const char* text)
{
  if (this->Scope)
  {
    this->Scope->AddWarning(OneLine(text));
  }
  this->DisplayText(text);
}

void vtkShadelabOutputWindow::DisplayGenericWarningText(const char* text)
{
  this->DisplayWarningText(text);
}

void vtkShadelabOutputWindow::DisplayDebugText(const char* text)
{
  this->DisplayText(text);
}

void vtkShadelabOutputWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scope: " << this->Scope << "\n";
  os << indent << "Echo: " << this->Echo << "\n";
}

namespace shadelab
{
MessageScope::MessageScope()
  : Window(vtkShadelabOutputWindow::Install())
{
  this->Outer = this->Window->GetScope();
  this->Window->SetScope(this);
}

MessageScope::~MessageScope()
{
  this->Window->SetScope(this->Outer);
}

void MessageScope::AddError(const std::string& line)
{
  if (this->First.empty())
  {
    this->First = line;
  }
}

void MessageScope::AddWarning(const std::string& line)
{
  this->WarningLines.push_back(line);
}
}
