// Materials, base colour textures and image decoding.
//
// Policy for images (shadows never depend on a texture, colour does):
// - an image file that is missing or unreadable rejects the file (the asset is incomplete, and
//   usually its buffers are missing too), as does an image bufferView outside its buffer;
// - image data that cannot be decoded (unknown format such as KTX2 or WebP, corrupt data,
//   absurd dimensions) only drops the texture with a warning: the material keeps its base
//   colour factor and the geometry stays usable;
// - a material's texture index that does not exist drops the texture with a warning, while a
//   texture whose source image does not exist rejects the file (an invalid index into images).
// Decoding happens here rather than inside tinygltf so that only used images are decoded and
// bufferView images are read only after their byte range has been checked.

#include "GltfInternal.h"

#include <io/PngLimits.h>

#include <base/InputFile.h>

#include <stb_image.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>

namespace fl::gltf {
namespace {

bool isDataUri(const std::string& uri) {
    return uri.rfind("data:", 0) == 0;
}

/// RGBA8 pixels of an encoded PNG/JPEG/... image; nullopt and `why` when stb_image cannot.
std::optional<Image> decode(const ByteSpan& bytes, std::string& why) {
    if (bytes.size == 0 || bytes.size > static_cast<std::size_t>(INT_MAX)) {
        why = cat("encoded size ", bytes.size, " bytes");
        return std::nullopt;
    }
    const int size = static_cast<int>(bytes.size);
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data, size, &w, &h, &channels)) {
        why = cat("unsupported or corrupt image data (", stbi_failure_reason(), ")");
        return std::nullopt;
    }
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide ||
        static_cast<long long>(w) * h > kMaxImagePixels) {
        why = cat("absurd image size ", w, "x", h, " (limit ", kMaxImageSide, " per side, ",
                  kMaxImagePixels, " pixels)");
        return std::nullopt;
    }
    // stb_image would allocate what the PNG's chunks claim before finding them missing.
    if (std::string problem = pngSizeProblem(bytes.data, bytes.size); !problem.empty()) {
        why = std::move(problem);
        return std::nullopt;
    }
    stbi_uc* pixels = stbi_load_from_memory(bytes.data, size, &w, &h, &channels, 4);
    if (!pixels) {
        why = cat("decoding failed (", stbi_failure_reason(), ")");
        return std::nullopt;
    }
    Image image;
    image.width = w;
    image.height = h;
    image.rgba.assign(pixels,
                      pixels + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    stbi_image_free(pixels);
    return image;
}

/// The encoded bytes of images[index]; fails when they are missing.
ByteSpan encodedBytes(const Context& ctx, std::size_t index) {
    const tinygltf::Image& image = ctx.model().images[index];
    const std::string element = elem("images", index);
    if (image.bufferView >= 0) return bufferViewBytes(ctx, image.bufferView, element);
    if (!image.image.empty()) return {image.image.data(), image.image.size()};
    if (image.uri.empty() || isDataUri(image.uri)) ctx.fail(element, "no image data");
    // The same checks tinygltf's read went through (GltfLoader.cpp): say which one failed.
    const std::string problem = inputFileProblem(ctx.baseDir() / image.uri, kSceneInputLimitMiB);
    ctx.fail(element, cat("image file '", image.uri,
                          "': ", problem.empty() ? "empty or unreadable" : problem));
}

/// Decodes used images once and maps glTF image indices to Scene::images indices.
class ImageTable {
  public:
    ImageTable(const Context& ctx, std::vector<Image>& images) : ctx_(ctx), images_(images) {}

    /// Scene image index of images[index], or -1 (warned) when it cannot be decoded.
    int get(std::size_t index) {
        if (auto it = done_.find(index); it != done_.end()) return it->second;
        int& slot = done_[index];
        slot = -1;
        std::string why;
        std::optional<Image> image = decode(encodedBytes(ctx_, index), why);
        if (!image) {
            ctx_.warn(elem("images", index), why + "; texture dropped");
            return slot;
        }
        const tinygltf::Image& src = ctx_.model().images[index];
        image->name = !src.name.empty()                         ? src.name
                      : !src.uri.empty() && !isDataUri(src.uri) ? src.uri
                                                                : elem("images", index);
        images_.push_back(std::move(*image));
        slot = static_cast<int>(images_.size()) - 1;
        return slot;
    }

  private:
    const Context& ctx_;
    std::vector<Image>& images_;
    std::map<std::size_t, int> done_;
};

int baseColorTexture(const Context& ctx, const tinygltf::TextureInfo& info,
                     const std::string& element, ImageTable& table) {
    const auto& model = ctx.model();
    if (info.index == -1) return -1;
    if (!Context::inRange(model.textures, info.index)) {
        ctx.warn(element, cat("texture ", info.index, " does not exist (", model.textures.size(),
                              " in textures); texture dropped"));
        return -1;
    }
    const auto& texture = model.textures[static_cast<std::size_t>(info.index)];
    const std::string texElement = elem("textures", static_cast<std::size_t>(info.index));
    if (texture.source == -1) {
        // e.g. KHR_texture_basisu / EXT_texture_webp put the image in an extension.
        ctx.warn(texElement, "no source image we can decode; texture dropped");
        return -1;
    }
    ctx.lookup(model.images, texture.source, texElement, "image", "images");
    return table.get(static_cast<std::size_t>(texture.source));
}

glm::vec4 baseColorFactor(const Context& ctx, const std::vector<double>& f,
                          const std::string& element) {
    const bool ok =
        f.size() == 4 && std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); });
    if (!ok) {
        ctx.warn(element, "baseColorFactor is not 4 finite numbers; white used");
        return glm::vec4(1.0f);
    }
    return glm::clamp(glm::vec4(f[0], f[1], f[2], f[3]), 0.0f, 1.0f);
}

/// alphaMode and alphaCutoff (spec 3.9.4); an unknown mode is drawn opaque and a cutoff that is
/// not a finite number >= 0 replaced by the default 0.5, each with a warning.
void readAlpha(const Context& ctx, const tinygltf::Material& src, const std::string& element,
               Material& m) {
    if (src.alphaMode == "MASK")
        m.alphaMode = AlphaMode::Mask;
    else if (src.alphaMode == "BLEND")
        m.alphaMode = AlphaMode::Blend;
    else if (src.alphaMode != "OPAQUE")
        ctx.warn(element, cat("alphaMode \"", src.alphaMode,
                              "\" is not OPAQUE, MASK or BLEND; drawn opaque"));
    if (!std::isfinite(src.alphaCutoff) || src.alphaCutoff < 0.0 || src.alphaCutoff > 1e6) {
        ctx.warn(element, "alphaCutoff is not a finite number >= 0; 0.5 used");
        return;
    }
    m.alphaCutoff = static_cast<float>(src.alphaCutoff);
}

} // namespace

std::vector<Material> convertMaterials(const Context& ctx, const std::vector<bool>& used,
                                       std::vector<Image>& images) {
    ImageTable table(ctx, images);
    std::vector<Material> materials;
    const auto& src = ctx.model().materials;
    materials.reserve(src.size());
    for (std::size_t i = 0; i < src.size(); ++i) {
        const std::string element = elem("materials", i);
        const auto& pbr = src[i].pbrMetallicRoughness;
        Material m;
        m.name = src[i].name.empty() ? element : src[i].name;
        m.baseColorFactor = baseColorFactor(ctx, pbr.baseColorFactor, element);
        if (i < used.size() && used[i]) // unused materials' images are neither decoded nor checked
            m.baseColorTexture =
                baseColorTexture(ctx, pbr.baseColorTexture,
                                 element + ".pbrMetallicRoughness.baseColorTexture", table);
        m.doubleSided = src[i].doubleSided;
        readAlpha(ctx, src[i], element, m);
        materials.push_back(std::move(m));
    }
    return materials;
}

bool keepEncodedImage(tinygltf::Image* image, int /*imageIndex*/, std::string* /*err*/,
                      std::string* /*warn*/, int /*reqWidth*/, int /*reqHeight*/,
                      const unsigned char* bytes, int size, void* /*user*/) {
    // For bufferView images tinygltf passes an unchecked pointer into the buffer: ignore it,
    // encodedBytes() reads the view after checking its range.
    if (image->bufferView < 0 && bytes != nullptr && size > 0)
        image->image.assign(bytes, bytes + size);
    return true;
}

} // namespace fl::gltf
