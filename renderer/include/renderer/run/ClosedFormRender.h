#pragma once
// A closed-form case (scene/ClosedForm.h) rendered by a method and scored against its exact
// visibility.

#include <renderer/Renderer.h>

#include <scene/ClosedForm.h>

namespace fl {

/// One frame of a case, read back and scored.
struct ClosedFormFrame {
    FloatImage visibility;
    ClosedFormError error;
};
/// Renders `c` from its camera with `settings` (a method and its options) at size x size, reads
/// the visibility back and scores it (needs a current context).
ClosedFormFrame renderClosedForm(const gl::ShaderLibrary& shaders, const ClosedFormCase& c,
                                 const RenderSettings& settings, int size);

} // namespace fl
