#include <renderer/io/TextureImage.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace fl {

FloatImage readTexture(const gl::Texture& texture, int channels) {
    if (channels != 1 && channels != 4) throw std::invalid_argument("readTexture: 1 or 4 channels");
    const int w = texture.width(), h = texture.height();
    std::vector<float> raw(static_cast<size_t>(w) * static_cast<size_t>(h) *
                           static_cast<size_t>(channels));
    glGetTextureImage(texture.id(), 0, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(raw.size() * sizeof(float)), raw.data());
    gl::throwIfErrors("texture read-back");
    return fromGlRows(raw.data(), w, h, channels);
}

ByteImage readDefaultFramebuffer(int width, int height) {
    ByteImage img{width, height, 4,
                  std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
    std::vector<std::uint8_t> raw(img.data.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadnPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(raw.size()),
                  raw.data());
    gl::throwIfErrors("window read-back");
    const size_t row = static_cast<size_t>(width) * 4; // GL rows are bottom-up
    for (int y = 0; y < height; ++y)
        std::memcpy(&img.data[static_cast<size_t>(y) * row],
                    &raw[static_cast<size_t>(height - 1 - y) * row], row);
    return img;
}

} // namespace fl
