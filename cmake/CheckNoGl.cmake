# ctest no_gl_configure (-DFLOODLIGHT_GL=OFF builds; cmake -DCACHE=.../CMakeCache.txt -P this):
# the configure asked for no GL, EGL, GLFW or epoxy package. find_package and pkg_check_modules
# leave entries in the cache for every package they looked for, found or not (glfw3_DIR,
# OPENGL_*, epoxy_* and __pkg_config_checked_epoxy), so an entry names a lookup that a machine
# without those development files would fail. The cpu preset also sets
# CMAKE_DISABLE_FIND_PACKAGE_glfw3 and _OpenGL, which makes a REQUIRED lookup of either an error.
file(STRINGS "${CACHE}" entries REGEX "^[^#/]")
set(found "")
foreach(entry IN LISTS entries)
  string(REGEX REPLACE "[:=].*" "" key "${entry}")
  string(TOLOWER "${key}" key_lower)
  if(key_lower MATCHES "^(__pkg_config_checked_)?(pkgcfg_lib_)?(epoxy|glfw|opengl|egl)")
    list(APPEND found "${key}")
  endif()
endforeach()
if(found)
  message(FATAL_ERROR "the FLOODLIGHT_GL=OFF configure looked for GL packages: ${found}")
endif()
list(LENGTH entries n)
message(STATUS "${n} cache entries, none of a GL, EGL, GLFW or epoxy lookup")
