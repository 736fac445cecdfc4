// The X display of the desktop window, opened by shadelab before VTK sees
// it: VTK's X window aborts the process when there is none.
// (Xlib's header defines None, Bool, ...: it stays inside x_display.cxx.)
#ifndef shadelab_x_display_h
#define shadelab_x_display_h

#include <string>

namespace shadelab
{
/** The display DISPLAY names (an X Display*), or null with `error` set. */
void* OpenXDisplay(std::string& error);

void CloseXDisplay(void* display);
}

#endif
