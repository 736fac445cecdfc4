// The profile in the window, in process: the k key and a drag draw the
// line over the view and the Profile dock shows `shadelab profile`'s chart
// of the picture the view shows, along that line.
#include "desktop/inspector_window.h"
#include "in_process.h"
#include "viewer.h"

#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkWindowToImageFilter.h>

#include <QLabel>
#include <QTest>

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <sstream>
#include <vector>

using namespace shadelab;
using namespace shadelab_test;

namespace
{
// The CSV's column `name`, by its header.
std::vector<double> Column(const std::string& csv, const std::string& name)
{
  std::istringstream in(csv);
  std::string line, field;
  std::getline(in, line);
  std::istringstream header(line);
  int index = 0;
  for (; std::getline(header, field, ',') && field != name; ++index)
  {
  }
  std::vector<double> values;
  while (std::getline(in, line))
  {
    std::istringstream row(line);
    for (int i = 0; i <= index; ++i)
    {
      std::getline(row, field, ',');
    }
    values.push_back(std::stod(field));
  }
  return values;
}

// The window's row y (from the bottom) as RGB triples, drawn again.
std::vector<std::array<int, 3>> WindowRow(Inspector& inspector, int y)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(inspector.GetWindow());
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  const int width = grab->GetOutput()->GetDimensions()[0];
  const auto* p = static_cast<const unsigned char*>(grab->GetOutput()->GetScalarPointer(0, y, 0));
  std::vector<std::array<int, 3>> row;
  for (int x = 0; x < width; ++x, p += 3)
  {
    row.push_back({ p[0], p[1], p[2] });
  }
  return row;
}
}

TEST(ProfileDock, ADragDrawsTheLineAndTheDockShowsTheViewsProfile)
{
  setenv("SHADELAB_EXECUTABLE", SHADELAB_BINARY, 1);
  Inspector inspector(SpotView(Shading::Gouraud), "shadelab view");
  ASSERT_EQ(inspector.Load(), 0);
  const auto application = MakeApplication();
  InspectorWindow window(inspector);
  ASSERT_TRUE(window.Open({ 240, 180 }));
  auto* chart = window.findChild<QLabel*>("profile chart");
  ASSERT_NE(chart, nullptr);
  const int* size = inspector.GetWindow()->GetSize();
  const int width = size[0], height = size[1];
  const int row = height / 2; // from the bottom, as VTK counts

  // Before the key a drag turns the camera; after it, it draws the line.
  ASSERT_TRUE(inspector.OnKey("k"));
  vtkRenderWindowInteractor* mouse = inspector.GetWindow()->GetInteractor();
  mouse->SetEventInformation(4, row);
  mouse->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  mouse->SetEventInformation(width - 5, row);
  mouse->InvokeEvent(vtkCommand::MouseMoveEvent);
  const std::array<int, 3> yellow{ 255, 220, 0 };
  // Over the view, on the pixels' boundary at the row: the row or the one below.
  const auto drawn = [&]
  {
    return WindowRow(inspector, row)[width / 2] == yellow ||
      WindowRow(inspector, row - 1)[width / 2] == yellow;
  };
  EXPECT_TRUE(drawn()) << "the line drawn over the view";
  mouse->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  ASSERT_TRUE(QTest::qWaitFor([chart] { return !chart->toolTip().isEmpty(); }, 60000));
  ASSERT_FALSE(chart->pixmap(Qt::ReturnByValue).isNull()) << chart->text().toStdString();

  // The tooltip's command: the line from the top, and the view's scene.
  const std::string command = chart->toolTip().toStdString();
  const int top = height - 1 - row;
  const std::string lineOption =
    "--line 4," + std::to_string(top) + "," + std::to_string(width - 5) + "," + std::to_string(top);
  EXPECT_NE(command.find(lineOption), std::string::npos) << command;
  // Run again for its CSV: gouraud's samples are the view's own pixels,
  // 8-bit in the window (a step of rounding at most).
  const TempDir dir;
  std::vector<std::string> words;
  std::istringstream split(command);
  for (std::string word; split >> word;)
  {
    words.push_back(word);
  }
  words.erase(words.begin()); // "shadelab"
  words.insert(words.end(), { "-o", (dir / "p.csv").string() });
  const RunResult run = RunShadelab(words);
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  const std::string csv = Slurp(dir / "p.csv");
  const std::vector<double> x = Column(csv, "x");
  const std::vector<double> green = Column(csv, "gouraud g");
  const std::vector<double> triangle = Column(csv, "triangle");
  ASSERT_EQ(x.size(), static_cast<std::size_t>(width - 8));
  // The line is gone from the view once the camera moves: the pixels beside
  // it show the picture the profile read.
  mouse->SetEventInformation(10, 10);
  mouse->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  mouse->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  EXPECT_FALSE(drawn()) << "hidden";
  const std::vector<std::array<int, 3>> shown = WindowRow(inspector, row);
  int compared = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    if (triangle[i] >= 0)
    {
      ++compared;
      EXPECT_NEAR(shown[static_cast<std::size_t>(x[i])][1], green[i] * 255, 1.01) << "sample " << i;
    }
  }
  EXPECT_GT(compared, 50);
}
