// shadelab-bench-vtk-pipeline: VTK's own pipeline for one picture, the
// peer of `shadelab render` in the scaling curves (scripts/bench-scaling):
// vtkPLYReader, vtkPolyDataNormals (VTK's defaults), vtkPolyDataMapper with
// VTK's own Phong lighting, an OSMesa window of the size asked,
// vtkWindowToImageFilter and vtkPNGWriter.
//
//   shadelab-bench-vtk-pipeline MESH.ply -o OUT.png [--size WxH]
//
// Its phases go to stderr as `shadelab -v` prints them, "NAME: PHASE MS ms,
// peak MIB MiB" (the peak resident memory so far), in order:
//   read     vtkPLYReader
//   normals  vtkPolyDataNormals
//   context  the OSMesa context
//   upload   a first Render into a 1x1-pixel viewport: shader compilation,
//            the vertex buffers' upload and one vertex pass (llvmpipe shades
//            every vertex however small the viewport)
//   frame    the Render at the full size and reading its pixels back
//   write    PNG encoding and the file
// VTK uploads in its first Render, so the 1x1 Render is the only way to
// tell upload from drawing from outside the mapper; it costs this process
// one vertex pass more than a single Render would.
#include "core/errors.h"
#include "core/options.h"
#include "core/output_file.h"
#include "core/phase_timer.h"
#include "headless/vtkShadelabOSMesaRenderWindow.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkImageData.h>
#include <vtkLogger.h>
#include <vtkPLYReader.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <CLI/CLI.hpp>

#include <stdexcept>
#include <string>
#include <string_view>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

using namespace shadelab;

namespace
{
constexpr const char* Name = "shadelab-bench-vtk-pipeline";
}

int main(int argc, char** argv)
{
  vtkShadelabOutputWindow::Install();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app("one picture through VTK's own pipeline, timed phase by phase", Name);
  std::string meshPath, output, sizeText = "1920x1080";
  app.add_option("MESH", meshPath, "A PLY mesh")->required();
  app.add_option("-o,--output", output, "The PNG picture")->required();
  app.add_option("--size", sizeText, "WIDTHxHEIGHT");
  CLI11_PARSE(app, argc, argv);
  ImageSize size;
  try
  {
    size = ParseSize(sizeText);
  }
  catch (const std::invalid_argument& e)
  {
    ReportError("--size", e.what());
    return ExitUsage;
  }

  PhaseTimer timer(true, Name);
  const MessageScope messages;
  auto reader = vtkSmartPointer<vtkPLYReader>::New();
  reader->SetFileName(meshPath.c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfPolys() == 0)
  {
    return ReportError(meshPath, messages.ErrorOr("no faces read"));
  }
  timer.Lap("read");
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputConnection(reader->GetOutputPort());
  normals->Update();
  timer.Lap("normals");

  vtkShadelabOSMesaRenderWindow::ChooseRasterizerThreads();
  auto window = vtkSmartPointer<vtkShadelabOSMesaRenderWindow>::New();
  window->SetMultiSamples(0);
  window->SetSize(size.Width, size.Height);
  window->Initialize();
  if (!window->GetContextReady())
  {
    return ReportError("render", "headless OpenGL: " + messages.ErrorOr("no OSMesa context"));
  }
  timer.Lap("context");

  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToPhong();
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(30);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->SetViewport(0, 0, 1.0 / size.Width, 1.0 / size.Height);
  window->Render();
  timer.Lap("upload");
  renderer->SetViewport(0, 0, 1, 1);
  window->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  if (const std::string error = messages.FirstError(); !error.empty())
  {
    return ReportError("render", error);
  }
  timer.Lap("frame");

  auto png = vtkSmartPointer<vtkPNGWriter>::New();
  png->SetInputConnection(grab->GetOutputPort());
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (!bytes || bytes->GetNumberOfValues() == 0)
  {
    return ReportError(output, messages.ErrorOr("PNG encoding failed"));
  }
  if (const std::string error = WriteFile(output,
        std::string_view(reinterpret_cast<const char*>(bytes->GetPointer(0)),
          static_cast<std::size_t>(bytes->GetNumberOfValues())));
      !error.empty())
  {
    return ReportError(output, error);
  }
  timer.Lap("write");
  window->Finalize();
  return 0;
}
