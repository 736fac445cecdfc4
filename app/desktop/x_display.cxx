#include "desktop/x_display.h"

#include <X11/Xlib.h>

#include <cstdlib>

namespace shadelab
{
void* OpenXDisplay(std::string& error)
{
  Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    const char* name = std::getenv("DISPLAY");
    error = std::string("cannot open the display '") + (name ? name : "") +
      "' (no X server?); `shadelab render` and `compare` need none";
  }
  return display;
}

void CloseXDisplay(void* display)
{
  XCloseDisplay(static_cast<Display*>(display));
}
}
