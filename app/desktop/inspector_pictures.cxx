// The inspector's window read back: screenshots, and the difference cell
// computed from two panels as rendered.
#include "desktop/inspector.h"

#include "core/errors.h"
#include "image/metadata.h"

#include <vtkImageData.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace shadelab
{
namespace
{
// The width x height pixels of `window` from the panel's lower left.
FloatImage Crop(const FloatImage& window, vtkRenderer* panel, int width, int height)
{
  FloatImage cut{ width, height, {} };
  for (int y = 0; y < height; ++y)
  {
    // GetOrigin: the panel's lower left in the window's pixels.
    const auto row = window.Rgba.begin() +
      4 * (static_cast<size_t>(panel->GetOrigin()[1] + y) * window.Width + panel->GetOrigin()[0]);
    cut.Rgba.insert(cut.Rgba.end(), row, row + 4 * width);
  }
  return cut;
}
}

vtkSmartPointer<vtkImageData> ToVtkImage(const FloatImage& picture)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(picture.Width, picture.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  const std::vector<std::uint8_t> topDown = Quantise<std::uint8_t>(picture, 255);
  for (int y = 0; y < picture.Height; ++y)
  {
    std::copy_n(topDown.data() + static_cast<size_t>(picture.Height - 1 - y) * picture.Width * 3,
      picture.Width * 3, out + static_cast<size_t>(y) * picture.Width * 3);
  }
  return image;
}

// The window's pixels as rendered now: 8-bit values as floats, which an
// 8-bit file gets back exactly.
FloatImage Inspector::GrabWindow()
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(this->Window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* window = grab->GetOutput();
  const auto* rgb = static_cast<const unsigned char*>(window->GetScalarPointer());
  FloatImage image{ window->GetDimensions()[0], window->GetDimensions()[1], {} };
  image.Rgba.resize(static_cast<size_t>(image.Width) * image.Height * 4, 1);
  for (size_t i = 0; i < static_cast<size_t>(image.Width) * image.Height; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image.Rgba[4 * i + c] = rgb[3 * i + c] / 255.0f;
    }
  }
  return image;
}

void Inspector::RefreshDifference()
{
  if (!this->DifferenceCell || this->Dragging)
  {
    return;
  }
  for (int panel : { this->Plan.DifferenceA, this->Plan.DifferenceB })
  {
    const Slot& slot = this->Slots[panel];
    if (slot.Traced && !slot.Traced->Renderer->GetDraw())
    {
      this->DifferenceImage->VisibilityOff(); // until its picture is whole
      return;
    }
  }
  // The two panels as rendered, without the texts drawn over them.
  std::vector<vtkProp*> texts{ this->Hud, this->Help };
  for (Slot& slot : this->Slots)
  {
    texts.push_back(slot.Label);
  }
  std::vector<int> visible;
  for (vtkProp* text : texts)
  {
    visible.push_back(text->GetVisibility());
    text->VisibilityOff();
  }
  vtkRenderer* a = this->Slots[this->Plan.DifferenceA].Renderer;
  vtkRenderer* b = this->Slots[this->Plan.DifferenceB].Renderer;
  const int width = std::min(a->GetSize()[0], b->GetSize()[0]);
  const int height = std::min(a->GetSize()[1], b->GetSize()[1]);
  const FloatImage window = this->GrabWindow();
  const FloatImage pictureA = Crop(window, a, width, height);
  const FloatImage pictureB = Crop(window, b, width, height);
  for (std::size_t i = 0; i < texts.size(); ++i)
  {
    texts[i]->SetVisibility(visible[i]);
  }
  const Difference difference = CompareImages(pictureA, pictureB);
  // The comparison picture's own difference cell: label, heat map, colour bar.
  const FloatImage cell =
    ComposeComparison({ { &difference.Heat, this->Plan.DifferenceLabel } }, 1, &difference, 0);
  this->DifferenceImage->SetInputData(ToVtkImage(cell));
  this->DifferenceImage->VisibilityOn();
  // Fit the picture into the cell.
  this->DifferenceRenderer->ResetCamera();
  const int* cellSize = this->DifferenceRenderer->GetSize();
  this->DifferenceRenderer->GetActiveCamera()->SetParallelScale(0.5 *
    std::max(static_cast<double>(cell.Height),
      static_cast<double>(cell.Width) * cellSize[1] / std::max(cellSize[0], 1)));
  this->Window->Render();
}

std::string NumberedName(const std::string& mesh, const std::string& extension)
{
  const std::string stem = std::filesystem::path(mesh).stem().string();
  std::string path;
  for (int n = 1; path.empty() || std::filesystem::exists(path); ++n)
  {
    char number[16];
    std::snprintf(number, sizeof number, "%03d", n);
    path = "shadelab-" + stem + "-" + number + extension;
  }
  return path;
}

void Inspector::Screenshot()
{
  const std::string path = NumberedName(this->Options.Scene.Mesh, ".png");
  const FloatImage image = this->GrabWindow();
  if (!this->Writer)
  {
    this->Writer = std::make_unique<ImageWriterProcess>();
  }
  const std::string error = this->Writer->Write(path, image, PixelType::UInt8,
    DescribePicture(this->CommandLine, this->State.Scene, this->Camera,
      this->Meshes.Get(this->State.Scene).Mesh));
  if (!error.empty())
  {
    ReportError(path, error);
    return;
  }
  std::cout << "shadelab: screenshot " << std::filesystem::absolute(path).string() << std::endl;
}
}
