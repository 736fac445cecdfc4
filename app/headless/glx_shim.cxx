// The GLX answers that let Debian's GLEW 2.2 initialise over an OSMesa
// context (ARCHITECTURE.md, "The headless backend").
//
// Debian's VTK 9.1 calls glewInit, and GLEW 2.2 built for GLX also
// initialises GLX: it fetches glXGetCurrentDisplay through
// glXGetProcAddressARB and fails unless that returns a non-null display, then
// calls glXQueryVersion and glXGetClientString. There is no X server here, so
// this file answers those few calls itself and hands every other name to
// OSMesaGetProcAddress. The executable exports these symbols (shadelab.dynlist)
// so that they win the lookup over libGLX; only headless executables link it.
#include <GL/osmesa.h>

#include <cstring>

namespace
{
// Never dereferenced: GLEW only checks it against null and passes it back.
char DummyDisplay;

void* CurrentDisplay()
{
  return &DummyDisplay;
}

OSMESAproc Lookup(const unsigned char* name)
{
  const char* n = reinterpret_cast<const char*>(name);
  if (std::strcmp(n, "glXGetCurrentDisplay") == 0)
  {
    return reinterpret_cast<OSMESAproc>(&CurrentDisplay);
  }
  return OSMesaGetProcAddress(n);
}
}

extern "C"
{
  OSMESAproc glXGetProcAddressARB(const unsigned char* name)
  {
    return Lookup(name);
  }

  OSMESAproc glXGetProcAddress(const unsigned char* name)
  {
    return Lookup(name);
  }

  void* glXGetCurrentDisplay()
  {
    return CurrentDisplay();
  }

  int glXQueryVersion(void*, int* major, int* minor)
  {
    *major = 1;
    *minor = 4;
    return 1;
  }

  const char* glXGetClientString(void*, int)
  {
    return "";
  }
}
