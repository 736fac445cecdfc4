// The inspector's Qt window, and RunView, which opens it (desktop/inspector_window.h).
#include "desktop/inspector_window.h"

#include "core/errors.h"
#include "desktop/control_panel.h"
#include "desktop/probe_panel.h"
#include "desktop/shader_panel.h"
#include "desktop/x_display.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QAbstractSpinBox>
#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QScreen>
#include <QScrollArea>
#include <QSurfaceFormat>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace shadelab
{
namespace
{
// Whether options ask the window to draw raytrace live (the rule, the
// drag's): it draws the raster rules live, and raytrace's pictures take
// seconds, not a frame. The comparison layout takes it as a mode: traced
// when the camera rests (inspector_tracing.cxx).
bool AsksForRaytrace(const ViewOptions& options)
{
  return options.Scene.ShadingRule == Shading::Raytrace ||
    options.InteractiveShading == Shading::Raytrace;
}
}

InspectorWindow::InspectorWindow(Inspector& inspector)
  : Engine(inspector)
  , View(new QVTKOpenGLNativeWidget(this))
  , Panel(new ControlPanel(inspector, this))
  , Shaders(new ShaderPanel(this))
  , Readout(new ProbePanel(inspector, this))
{
  this->View->setRenderWindow(inspector.GetWindow());
  this->setCentralWidget(this->View);
  auto* dock = new QDockWidget("Controls", this);
  auto* scroll = new QScrollArea(dock);
  // Scrolled: a window lower than the panel keeps its 3D view's size.
  scroll->setWidget(this->Panel);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(this->Panel->sizeHint().width() + 24);
  dock->setWidget(scroll);
  this->addDockWidget(Qt::RightDockWidgetArea, dock);
  // The shader and the probe tabbed with the controls, right of the view
  // (which stays at the window's top left, where the window tests' mouse
  // finds it): one dock's width beside the view, so that the window fits a
  // laptop's screen, and the controls in front at start.
  auto* shaderDock = new QDockWidget("Shader", this);
  shaderDock->setObjectName("shader dock");
  shaderDock->setWidget(this->Shaders);
  this->addDockWidget(Qt::RightDockWidgetArea, shaderDock);
  this->tabifyDockWidget(dock, shaderDock);
  auto* probe = new QDockWidget("Probe", this);
  probe->setWidget(this->Readout);
  this->addDockWidget(Qt::RightDockWidgetArea, probe);
  this->tabifyDockWidget(shaderDock, probe);
  this->Controls = dock;
  // A probed pixel brings its readout to the front.
  inspector.ProbeChanged = [this, probe]
  {
    this->Readout->Show();
    probe->raise();
  };
  this->Readout->TermPicked = [this](Terms term) { this->Shaders->HighlightTerm(term); };
  this->Shaders->ApplyEdits = [&inspector](const OwnStages& edits)
  { return inspector.ApplyStages(edits); };
  this->Shaders->Revert = [&inspector] { inspector.RevertStages(); };
  this->Shaders->Save = [&inspector] { inspector.SaveStages(); };
  inspector.Changed = [this]
  {
    this->Panel->Show();
    this->Shaders->Show(this->Engine.GetShownShaders());
  };
  inspector.Quit = [this] { this->close(); };
  inspector.Copy = [](const std::string& text)
  { QApplication::clipboard()->setText(QString::fromStdString(text)); };
  qApp->installEventFilter(this);
}

bool InspectorWindow::Open(const ImageSize& size, bool sizeGiven)
{
  const QSize view(size.Width, size.Height);
  this->View->resize(view);
  this->resize(this->sizeHint() + view - this->View->sizeHint());
  this->show();
  QApplication::processEvents(); // the layout, and the widget's OpenGL context
  // The 3D view exactly --size, as the headless picture: the dock takes the rest.
  this->resize(this->size() + view - this->View->size());
  QApplication::processEvents();
  // In front once shown: before, Qt keeps the last tab added in front.
  this->Controls->raise();
  this->FitScreen(view, sizeGiven);
  this->View->setFocus();
  this->Engine.Start();
  this->Shaders->Show(this->Engine.GetShownShaders());
  this->Started = true;
  for (const std::string& key : this->EarlyKeys)
  {
    this->Engine.OnKey(key);
  }
  return this->isVisible();
}

void InspectorWindow::FitScreen(const QSize& view, bool sizeGiven)
{
  const QRect screen = this->screen()->availableGeometry();
  // What the window needs beside its view: the docks, and the frame a
  // window manager adds (none without one).
  const QSize around = this->frameGeometry().size() - this->View->size();
  const QSize room = screen.size() - around;
  if (view.width() > room.width() || view.height() > room.height())
  {
    if (sizeGiven)
    {
      // The picture asked for is kept: what the window shows is what
      // Copy command and the screenshot key give.
      ReportWarnings("view",
        { "--size " + std::to_string(view.width()) + "x" + std::to_string(view.height()) +
          " with the controls needs " + std::to_string(view.width() + around.width()) + "x" +
          std::to_string(view.height() + around.height()) + " pixels, more than the screen's " +
          std::to_string(screen.width()) + "x" + std::to_string(screen.height()) });
    }
    else
    {
      // Smaller in the same shape, so that the fitted camera frames the
      // mesh as the headless picture of that size does.
      const double scale = std::min(static_cast<double>(room.width()) / view.width(),
        static_cast<double>(room.height()) / view.height());
      const QSize fitted(std::max(1, static_cast<int>(view.width() * scale)),
        std::max(1, static_cast<int>(view.height() * scale)));
      this->resize(this->size() + fitted - this->View->size());
      QApplication::processEvents();
    }
  }
  if (!screen.contains(this->frameGeometry()))
  {
    this->move(screen.topLeft());
    QApplication::processEvents();
  }
}

bool InspectorWindow::eventFilter(QObject* watched, QEvent* event)
{
  auto* widget = qobject_cast<QWidget*>(watched);
  if (event->type() != QEvent::KeyPress || !widget || widget->window() != this)
  {
    return false;
  }
  const auto* key = static_cast<QKeyEvent*>(event);
  const std::string name = key->key() == Qt::Key_Escape ? "Escape" : key->text().toStdString();
  // A number being typed keeps its keys.
  if (name.empty() ||
    (name != "Escape" &&
      (qobject_cast<QLineEdit*>(widget) || qobject_cast<QAbstractSpinBox*>(widget) ||
        qobject_cast<QPlainTextEdit*>(widget))))
  {
    return false;
  }
  // Keys that come while the window opens (xdotool's, or a quick hand)
  // are kept for when the inspector has started.
  if (!this->Started)
  {
    this->EarlyKeys.push_back(name);
    return true;
  }
  return this->Engine.OnKey(name);
}

int RunView(const ViewOptions& options, const std::string& commandLine)
{
  if (AsksForRaytrace(options))
  {
    std::cerr << "shadelab: error: view: raytrace is drawn in the window only as a mode of "
                 "the comparison layout (--modes); shadelab render draws it (see shadelab view "
                 "--help)"
              << std::endl;
    return ExitUsage;
  }
  // Checked first: Qt aborts the process when it finds no display.
  std::string error;
  void* display = OpenXDisplay(error);
  if (!display)
  {
    return ReportError("view", error);
  }
  CloseXDisplay(display);
  Inspector inspector(options, commandLine);
  if (const int code = inspector.Load())
  {
    return code;
  }
  // Before the application exists (QVTKOpenGLNativeWidget's documentation).
  // Not forward-compatible: such a core context refuses lines wider than a
  // pixel, and the wireframe's widths are OpenGL's own wide lines
  // (Inspector::SetUpWindow says why not VTK's).
  QSurfaceFormat format = QVTKOpenGLNativeWidget::defaultFormat();
  format.setOption(QSurfaceFormat::DeprecatedFunctions);
  QSurfaceFormat::setDefaultFormat(format);
  int argc = 1;
  char name[] = "shadelab-view";
  char* argv[] = { name, nullptr };
  QApplication application(argc, argv);
  InspectorWindow window(inspector);
  if (!window.Open(options.Scene.Size, options.SizeGiven))
  {
    return 0;
  }
  // Titled once started: what finds the window by its title (the window
  // tests' xdotool) finds it ready for the mouse.
  const std::string title =
    "shadelab - " + std::filesystem::path(options.Scene.Mesh).filename().string();
  window.setWindowTitle(QString::fromStdString(title));
  if (options.MeasureDrag > 0)
  {
    return inspector.MeasureDrag();
  }
  std::cout << "shadelab: " << title << ": press h for the keys" << std::endl;
  return application.exec();
}
}
