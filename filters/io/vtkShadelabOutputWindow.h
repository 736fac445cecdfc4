/**
 * @class   vtkShadelabOutputWindow
 * @brief   collects VTK's error and warning texts instead of printing them
 *
 * VTK reports pipeline failures through vtkOutputWindow as multi-line texts
 * ("ERROR: In file, line N\nclass (0x...): message"). shadelab's contract is a
 * single line naming the input and the problem, so this window keeps only the
 * message part of each text and hands it to the innermost
 * shadelab::MessageScope, so that each operation (a read, the normals, a
 * render, a write) gets its own first error and warnings, not one left over
 * from an earlier operation. Texts outside any scope are only echoed.
 * Install() makes it VTK's global output window.
 */
#ifndef vtkShadelabOutputWindow_h
#define vtkShadelabOutputWindow_h

#include "shadelab_filtersModule.h" // the export macro

#include <vtkOutputWindow.h>

#include <string>
#include <vector>

namespace shadelab
{
class MessageScope;
}

class SHADELAB_FILTERS_EXPORT vtkShadelabOutputWindow : public vtkOutputWindow
{
public:
  static vtkShadelabOutputWindow* New();
  vtkTypeMacro(vtkShadelabOutputWindow, vtkOutputWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Makes an instance VTK's global output window, unless one is already; returns it. */
  static vtkShadelabOutputWindow* Install();

  void DisplayText(const char* text) override;
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override;
  void DisplayDebugText(const char* text) override;

  /** The scope that receives the messages (the innermost open one), or null. */
  shadelab::MessageScope* GetScope() const { return this->Scope; }
  void SetScope(shadelab::MessageScope* scope) { this->Scope = scope; }

  /** Also print every text to stderr as it arrives (for --verbose). */
  vtkSetMacro(Echo, bool);
  vtkGetMacro(Echo, bool);

  /** The message part of one of VTK's texts, on one line. */
  static std::string OneLine(const char* text);

protected:
  vtkShadelabOutputWindow() = default;
  ~vtkShadelabOutputWindow() override = default;

private:
  vtkShadelabOutputWindow(const vtkShadelabOutputWindow&) = delete;
  void operator=(const vtkShadelabOutputWindow&) = delete;

  shadelab::MessageScope* Scope = nullptr;
  bool Echo = false;
};

namespace shadelab
{
/**
 * The messages VTK reports during one operation. A scope starts empty and,
 * while it is the innermost one, collects every error and warning; closing
 * it (the destructor) gives the messages back to the scope around it no
 * more. Makes vtkShadelabOutputWindow VTK's output window if it is not yet.
 * Scopes nest on one thread: the one that runs VTK's pipelines.
 */
class SHADELAB_FILTERS_EXPORT MessageScope
{
public:
  MessageScope();
  ~MessageScope();

  /** The first error, as one line; empty if none. */
  const std::string& FirstError() const { return this->First; }
  /** The first error, or fallback when VTK reported none. */
  std::string ErrorOr(const char* fallback) const
  {
    return this->First.empty() ? fallback : this->First;
  }
  /** Each warning as one line, in order. */
  const std::vector<std::string>& Warnings() const { return this->WarningLines; }

  void AddError(const std::string& line);
  void AddWarning(const std::string& line);

private:
  MessageScope(const MessageScope&) = delete;
  void operator=(const MessageScope&) = delete;

  vtkShadelabOutputWindow* Window;
  MessageScope* Outer;
  std::string First;
  std::vector<std::string> WarningLines;
};
}

#endif
