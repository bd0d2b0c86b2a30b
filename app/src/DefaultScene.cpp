// The built-in scene, assets/default.glb, inside the binary: it was read from the
// source tree at run time (FLOODLIGHT_SOURCE_DIR), so a binary moved or installed away from its
// sources silently rendered the scene generator's version instead. The assembler's .incbin puts
// the file's bytes in the read-only data; CMake rebuilds this file when the asset changes
// (OBJECT_DEPENDS).
#include <app/Common.h>

#include <span>

extern "C" {
extern const unsigned char floodlight_default_glb[];
extern const unsigned char floodlight_default_glb_end[];
}

__asm__(".pushsection .rodata\n"
        ".global floodlight_default_glb\n"
        ".balign 16\n"
        "floodlight_default_glb:\n"
        ".incbin \"" FLOODLIGHT_DEFAULT_GLB "\"\n"
        ".global floodlight_default_glb_end\n"
        "floodlight_default_glb_end:\n"
        ".popsection\n");

namespace fl::app {

Scene loadDefaultScene(const LoadOptions& options) {
    const std::span<const unsigned char> glb(
        floodlight_default_glb,
        static_cast<std::size_t>(floodlight_default_glb_end - floodlight_default_glb));
    return loadGlbBytes(glb, "default.glb (built in)", options);
}

} // namespace fl::app
