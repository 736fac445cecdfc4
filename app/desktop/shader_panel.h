// The running shader beside the picture: the complete vertex and fragment
// GLSL that draws the view now (Inspector::GetShownShaders, the program the
// mapper bound), in two read-only tabs with line numbers, with the lines that compute each
// term of the equation, and each effect a scene adds (attenuation, fog), on a
// background of its colour. The generator
// marks those lines (TermMarker, shadelabShaderSource.h); nothing here
// guesses from variable names. The term buttons are the colours' legend
// and pick the term to highlight.
#ifndef shadelab_shader_panel_h
#define shadelab_shader_panel_h

#include "scene/comparison_panels.h"
#include "scene/shader_sources.h"

#include <QWidget>

#include <array>

class QAbstractButton;
class QPlainTextEdit;
class QTabWidget;

namespace shadelab
{
class ShaderPanel : public QWidget
{
public:
  explicit ShaderPanel(QWidget* parent = nullptr);

  /** Shows sources (kept as they are, and where they were scrolled, when unchanged). */
  void Show(const ShaderSources& sources);

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
  static constexpr std::size_t MarkCount = 7;

private:
  void HighlightMark(std::size_t mark);
  void Highlight();

  QTabWidget* Tabs;
  std::array<QPlainTextEdit*, 2> Stages;               // vertex, fragment
  std::array<QAbstractButton*, MarkCount + 1> Buttons; // all, then Marks()
  ShaderSources Sources;
  std::size_t Shown = AllMarks;
};
}

#endif
