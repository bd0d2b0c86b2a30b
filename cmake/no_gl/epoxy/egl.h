// In front of the system header with -DFLOODLIGHT_GL=OFF (top-level CMakeLists.txt): the CPU
// libraries and their tests build without GL, so none may include it.
#error "<epoxy/egl.h> included in a -DFLOODLIGHT_GL=OFF build: the CPU libraries and their tests must not use GL"
