// LeakSanitizer suppressions for ASan builds (-DFSI_SANITIZE=ON): Mesa's OSMesa keeps
// per-context allocations (OSMesaMakeCurrent, the gallium screen) until process exit.
// Those leaks are Mesa's, not ours; everything in our own code is still checked.
// The sanitizer runtime looks this weak hook up in the loaded objects at start.
#ifdef FSI_SANITIZE_BUILD
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n"
         "leak:libgallium\n"
         "leak:libLLVM\n"
         "leak:libglapi.so\n"
         "leak:libEGL_mesa.so\n";
}
#endif
