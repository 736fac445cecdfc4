// The inspector's Qt window, and RunView, which opens it (desktop/inspector_window.h).
#include "desktop/inspector_window.h"

#include "core/errors.h"
#include "core/sibling_executable.h"
#include "desktop/control_panel.h"
#include "desktop/probe_panel.h"
#include "desktop/shader_panel.h"
#include "desktop/x_display.h"
#include "image/metadata.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QAbstractSpinBox>
#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProcess>
#include <QScreen>
#include <QScrollArea>
#include <QSurfaceFormat>

#include <algorithm>
#include <cstdlib>
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
  this->ProfileDock = new QDockWidget("Profile", this);
  this->ProfileDock->setObjectName("profile dock");
  this->ProfileChart = new QLabel("Press k and drag a line across the view: its intensity per rule "
                                  "(flat, gouraud, phong), as shadelab profile draws it.",
    this->ProfileDock);
  this->ProfileChart->setObjectName("profile chart");
  this->ProfileChart->setWordWrap(true);
  this->ProfileChart->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  // The chart never widens the dock, and with it the window and the view.
  this->ProfileChart->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
  this->ProfileDock->setWidget(this->ProfileChart);
  this->addDockWidget(Qt::RightDockWidgetArea, this->ProfileDock);
  this->tabifyDockWidget(probe, this->ProfileDock);
  inspector.ProfileLine = [this](Pixel from, Pixel to) { this->RunProfile(from, to); };
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

// `shadelab profile` of the view's scene along the line, in the background
// (the window keeps answering); its chart shown in the Profile dock, its
// command line in the chart's tooltip and on stdout.
void InspectorWindow::RunProfile(Pixel from, Pixel to)
{
  const std::vector<std::string> words = this->Engine.ProfileArguments(from, to);
  if (words.empty())
  {
    return;
  }
  if (this->Profiler)
  {
    this->Profiler->kill(); // a line drawn since: only the last one's chart
    this->Profiler->deleteLater();
  }
  const QString chart = this->ProfileFolder.filePath("profile.png");
  QStringList arguments;
  for (const std::string& word : words)
  {
    arguments << QString::fromStdString(word);
  }
  arguments << "-o" << chart << "--quiet";
  // `shadelab view` names itself (ExecViewer); a test, or shadelab-view
  // run alone, finds shadelab beside it.
  const char* given = std::getenv("SHADELAB_EXECUTABLE");
  const QString program = given ? given : QString::fromStdString(SiblingExecutable("shadelab"));
  // What a user runs again headless: quoted for a shell, as Copy command's.
  std::vector<const char*> shown{ "shadelab" };
  for (const std::string& word : words)
  {
    shown.push_back(word.c_str());
  }
  const QString command =
    QString::fromStdString(QuoteCommandLine(static_cast<int>(shown.size()), shown.data()));
  std::cout << "shadelab: profile command: " << command.toStdString() << std::endl;
  this->ProfileChart->setText("Profiling...\n" + command);
  this->ProfileDock->raise();
  auto* process = new QProcess(this);
  this->Profiler = process;
  QObject::connect(process, QOverload<int, QProcess::ExitStatus>::of(&QProcess::finished), this,
    [this, process, chart, command](int code, QProcess::ExitStatus status)
    {
      if (process != this->Profiler)
      {
        return; // killed for a newer line
      }
      const QPixmap picture(chart);
      if (status != QProcess::NormalExit || code != 0 || picture.isNull())
      {
        this->ProfilePicture = QPixmap();
        this->ProfileChart->setText(
          "shadelab profile failed:\n" + QString::fromLocal8Bit(process->readAllStandardError()));
      }
      else
      {
        this->ProfilePicture = picture;
        this->FitProfileChart();
      }
      this->ProfileChart->setToolTip(command);
      this->Profiler = nullptr;
      process->deleteLater();
    });
  process->start(program, arguments);
}

// The chart as large as the dock shows it whole.
void InspectorWindow::FitProfileChart()
{
  if (!this->ProfilePicture.isNull())
  {
    this->ProfileChart->setPixmap(this->ProfilePicture.scaled(
      this->ProfileChart->size(), Qt::KeepAspectRatio, Qt::SmoothTransformation));
  }
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
  if (watched == this->ProfileChart && event->type() == QEvent::Resize)
  {
    this->FitProfileChart();
    return false;
  }
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
