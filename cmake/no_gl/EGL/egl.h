// In front of the system header with -DFLOODLIGHT_GL=OFF (top-level CMakeLists.txt): the CPU
// libraries and their tests build without GL, so none may include it.
#error "a -DFLOODLIGHT_GL=OFF build included <EGL/egl.h>: CPU code must not use GL"
