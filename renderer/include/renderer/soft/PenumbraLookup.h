#pragma once
// JFA-L's lookup with --penumbra both on the CPU: the twin of shaders/light_visibility.frag.glsl
// with soft_penumbra.glsl, both of its passes (the occluder's point everywhere, then its edges
// where the first pass marked), operation for operation. The GLSL files say why each step is.

#include <io/ImageIO.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/soft/OccluderLines.h>

#include <vector>

namespace fl {

/// The frame's surfaces as the lookup reads them, each read back with row 0 at the top
/// (FloatImage's layout): positions (w = 0 on background), the lift, the shading and the
/// plane normals.
struct LookupSurfaces {
    FloatImage points, lift, shading, planes;
};
LookupSurfaces readLookupSurfaces(const SurfacesPass::Outputs& surfaces);

/// One visibility per pixel, FloatImage's layout. `tags`: the penumbra map's packed cells (the
/// flood's R32F, map.size² in GL order, 0 empty); `threshold`: the silhouette threshold
/// (occluderEdgePoint's).
FloatImage penumbraLookupVisibility(const LookupSurfaces& surfaces, const LineMap& map,
                                    const std::vector<float>& tags, float threshold);

} // namespace fl
