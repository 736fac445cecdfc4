/**
 * @class   vtkShadelabOutputWindow
 * @brief   collects VTK's error and warning texts instead of printing them
 *
 * VTK reports pipeline failures through vtkOutputWindow as multi-line texts
 * ("ERROR: In file, line N\nclass (0x...): message"). shadelab's contract is a
 * single line naming the input and the problem, so this window keeps only the
 * message part of each text and lets the program decide what to print.
 * Install() makes it VTK's global output window.
 */
#ifndef vtkShadelabOutputWindow_h
#define vtkShadelabOutputWindow_h

#include <vtkOutputWindow.h>

#include <string>
#include <vector>

class vtkShadelabOutputWindow : public vtkOutputWindow
{
public:
  static vtkShadelabOutputWindow* New();
  vtkTypeMacro(vtkShadelabOutputWindow, vtkOutputWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Makes a new instance VTK's global output window and returns it. */
  static vtkShadelabOutputWindow* Install();

  void DisplayText(const char* text) override;
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override;
  void DisplayDebugText(const char* text) override;

  /** The first error since the last Clear(), as one line; empty if none. */
  const std::string& GetFirstError() const { return this->FirstError; }
  const std::vector<std::string>& GetWarnings() const { return this->Warnings; }
  void Clear();

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

  std::string FirstError;
  std::vector<std::string> Warnings;
  bool Echo = false;
};

#endif
