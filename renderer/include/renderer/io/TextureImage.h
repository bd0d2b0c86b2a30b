#pragma once
// GL read-backs as images (io/ImageIO.h's FloatImage and ByteImage, row 0 at the top): the GL
// side of image output, kept out of the CPU io library.

#include <io/ImageIO.h>

#include <gpu/Gl.h>

namespace fl {

/// Reads level 0 of a colour texture as `channels` floats per pixel (1 = red, 4 = RGBA),
/// flipped so that row 0 is the top of the picture.
FloatImage readTexture(const gl::Texture& texture, int channels);

/// Reads the default framebuffer's back buffer (what a window shows) as 8-bit RGBA, row 0 at the
/// top.
ByteImage readDefaultFramebuffer(int width, int height);

} // namespace fl
