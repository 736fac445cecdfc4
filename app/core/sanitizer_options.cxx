// LeakSanitizer's settings for the sanitizer build (SHADELAB_SANITIZE).
// LeakSanitizer calls these hooks itself, so no environment is needed.

// Only leaks that live in other projects' code, each with its reason.
extern "C" const char* __lsan_default_suppressions()
{
  return
    // Mesa 22.3's OSMesa: OSMesaMakeCurrent allocates a framebuffer wrapper
    // for each buffer it is given and keeps it in a table that
    // OSMesaDestroyContext does not empty; OSMesa has no call to free it.
    "leak:libOSMesa.so\n"
    // libdbus, which Qt's window (shadelab-view) loads for its desktop
    // integration: a message buffer it keeps in a connection that lives
    // until the process ends.
    "leak:libdbus-1.so\n"
    // VTK 9.1's XML writers: a write that fails (a full disk, a file-size
    // limit) returns before freeing what vtkXMLWriter::Start allocated for
    // each array's offsets (the report shows only the library's addresses,
    // so the library is named).
    "leak:libvtkIOXML-9.1.so\n";
}

// The list of suppressions used would break the one-line error contract.
extern "C" const char* __lsan_default_options()
{
  return "print_suppressions=0";
}

// LeakSanitizer checks at exit, after the dynamic loader has unloaded what
// was dlopen'ed and dlclose'd: memory that an unloaded library's globals
// still point to then looks leaked, with frames in an "<unknown module>".
// Mesa's GLX (the desktop window's) unloads its DRI driver that way at
// exit. So in sanitizer builds nothing is ever unloaded: this dlclose,
// exported from the executable (app/CMakeLists.txt), takes the C
// library's place for every library in the process.
extern "C" int dlclose(void*)
{
  return 0;
}
