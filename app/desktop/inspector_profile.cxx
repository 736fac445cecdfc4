// The profile in the window (Mach bands as a measurement): the k key arms
// it, the next drag draws the line over the single view (in yellow, as the
// profile's inset shows it), and its release hands the line to the window,
// which runs `shadelab profile` on the scene that Copy command writes and
// shows the chart in its Profile dock.
#include "desktop/inspector.h"

#include "settings/command_line.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>

#include <iostream>

namespace shadelab
{
void Inspector::ArmProfileLine()
{
  if (this->State.Compare)
  {
    this->Problem = "profile: the line is drawn on the single view (c leaves the comparison)";
    this->UpdateHud();
    this->Window->Render();
    return;
  }
  std::cout << "shadelab: profile: drag a line across the view" << std::endl;
  this->Style->LineDrag = [this](const int from[2], const int to[2], bool released)
  { this->DrawProfileLine(from, to, released); };
}

void Inspector::DrawProfileLine(const int from[2], const int to[2], bool released)
{
  if (!this->Line->GetMapper())
  {
    vtkNew<vtkPolyData> line;
    vtkNew<vtkPoints> ends;
    ends->SetNumberOfPoints(2);
    line->SetPoints(ends);
    vtkNew<vtkCellArray> segment;
    const vtkIdType ids[2] = { 0, 1 };
    segment->InsertNextCell(2, ids);
    line->SetLines(segment);
    vtkNew<vtkPolyDataMapper2D> mapper;
    mapper->SetInputData(line);
    this->Line->SetMapper(mapper);
    this->Line->GetProperty()->SetColor(1, 220 / 255.0, 0);
    this->Line->GetProperty()->SetLineWidth(2);
    this->Overlay->AddActor2D(this->Line);
  }
  auto* line = vtkPolyData::SafeDownCast(this->Line->GetMapper()->GetInputDataObject(0, 0));
  line->GetPoints()->SetPoint(0, from[0], from[1], 0);
  line->GetPoints()->SetPoint(1, to[0], to[1], 0);
  line->GetPoints()->Modified();
  this->Line->VisibilityOn();
  this->Window->Render();
  if (released && this->ProfileLine)
  {
    // VTK counts rows from the bottom, the profile from the top.
    const int height = this->Window->GetSize()[1];
    this->ProfileLine({ from[0], height - 1 - from[1] }, { to[0], height - 1 - to[1] });
  }
}

std::vector<std::string> Inspector::ProfileArguments(Pixel from, Pixel to)
{
  if (!this->SaveStages())
  {
    return {};
  }
  const SceneOptions s = this->ShownScene();
  std::vector<std::string> words{ "profile", s.Mesh, "--line",
    std::to_string(from.X) + "," + std::to_string(from.Y) + "," + std::to_string(to.X) + "," +
      std::to_string(to.Y),
    "--modes", this->Options.Panels.Modes };
  const std::vector<std::string> options = SceneArguments(s);
  words.insert(words.end(), options.begin(), options.end());
  return words;
}
}
