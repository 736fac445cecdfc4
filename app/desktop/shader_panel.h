// The running shader beside the picture: the complete vertex and fragment
// GLSL that draws the view now (Inspector::GetShownShaders, the program the
// mapper bound), in two tabs with line numbers, with the lines that compute each
// term of the equation, and each effect a scene adds (attenuation, fog), on a
// background of its colour. The generator
// marks those lines (TermMarker, shadelabShaderSource.h); nothing here
// guesses from variable names. The term buttons are the colours' legend
// and pick the term to highlight. The stages can be edited and applied
// (the hands-on): the driver's errors are marked at their lines and listed
// under the tabs, while the program that drew before keeps drawing.
#ifndef shadelab_shader_panel_h
#define shadelab_shader_panel_h

#include "scene/comparison_panels.h"
#include "scene/own_stage_files.h"
#include "scene/shader_sources.h"

#include <QWidget>

#include <array>
#include <functional>
#include <vector>

class QAbstractButton;
class QListWidget;
class QPlainTextEdit;
class QTabWidget;

namespace shadelab
{
class ShaderPanel : public QWidget
{
public:
  explicit ShaderPanel(QWidget* parent = nullptr);

  /**
   * Shows sources (kept as they are, and where they were scrolled, when
   * unchanged); a stage edited and not applied keeps its edit.
   */
  void Show(const ShaderSources& sources);

  /**
   * Apply (the button, Ctrl+Return): draws the edited stages (a stage not
   * edited since it was shown: empty) and gives the driver's errors, none
   * when they draw. Revert: the generated stages again. Save: writes the
   * stages of one's own.
   */
  std::function<std::vector<StageErrorLine>(const OwnStages&)> ApplyEdits;
  std::function<void()> Revert;
  std::function<void()> Save;

  /**
   * Highlights the lines of `term` only (Terms::All: every term's, each in
   * its colour), and shows the first of them: in the stage that lights,
   * scrolled to it. What a term button does; the probe's readout can call
   * it for the term the user picks there.
   */
  void HighlightTerm(Terms term);

  /** 0: every mark's lines; then the marks in the legend's order (the terms', then the effects').
   */
  static constexpr std::size_t AllMarks = 0;
  /** The terms and effects the generator marks (Marks(), shader_panel.cxx). */
  static constexpr std::size_t MarkCount = 10;

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void HighlightMark(std::size_t mark);
  void Highlight();
  void Apply();
  void ShowErrors(const std::vector<StageErrorLine>& errors);
  void GoToError(int row);

  QTabWidget* Tabs;
  std::array<QPlainTextEdit*, 2> Stages;               // vertex, fragment
  std::array<QAbstractButton*, MarkCount + 1> Buttons; // all, then Marks()
  QListWidget* ErrorList;
  ShaderSources Sources;
  std::size_t Shown = AllMarks;
  std::vector<StageErrorLine> Errors; // the last apply's, marked at their lines
};
}

#endif
