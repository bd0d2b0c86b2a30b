#include <app/Voronoi3dOutput.h>

#include <app/Common.h>

#include <io/ImageIO.h>

#include <algorithm>
#include <cmath>

namespace fl::app {

namespace {

// Slices are enlarged to about this many pixels on their longer side: a 32^3 grid's slices are
// 32 pixels wide, too small to see the regions.
constexpr int kSlicePicturePixels = 128;
constexpr int kMontageGap = 2;

std::int64_t squaredTo(const jfa::Site3& s, int x, int y, int z) {
    const std::int64_t dx = s.x - x, dy = s.y - y, dz = s.z - z;
    return dx * dx + dy * dy + dz * dz;
}

// The recorded squared distance of voxel i at (x, y, z), kNoDistance without a site.
std::int64_t recorded(const Voronoi3dResult& r, std::size_t i, int x, int y, int z) {
    const std::int32_t c = r.grid.cells[i];
    return c == jfa::kNoSite ? jfa::kNoDistance : squaredTo(r.sites[std::size_t(c)], x, y, z);
}

// Slice z, one pixel a voxel, row 0 = y = H-1, then enlarged `scale` times.
ByteImage slicePicture(const Voronoi3dResult& r, int z, int scale) {
    const jfa::Extent3 e = r.grid.extent;
    ByteImage pic{e.width * scale, e.height * scale, 4, {}};
    pic.data.assign(std::size_t(pic.width) * std::size_t(pic.height) * 4, 255);
    std::vector<std::uint8_t> isSite(std::size_t(e.width) * std::size_t(e.height), 0);
    for (const jfa::Site3& s : r.sites)
        if (s.z == z) isSite[std::size_t(s.y) * std::size_t(e.width) + std::size_t(s.x)] = 1;
    for (int y = 0; y < e.height; ++y) {
        for (int x = 0; x < e.width; ++x) {
            const std::size_t i = r.grid.index(x, y, z);
            const std::int32_t c = r.grid.cells[i];
            auto rgb = regionColour(c == jfa::kNoSite ? 0 : r.sites[std::size_t(c)].id);
            if (recorded(r, i, x, y, z) > r.exact[i]) rgb = {255, 0, 0};
            if (isSite[std::size_t(y) * std::size_t(e.width) + std::size_t(x)]) rgb = {0, 0, 0};
            for (int sy = 0; sy < scale; ++sy) {
                const std::size_t row = std::size_t((e.height - 1 - y) * scale + sy);
                for (int sx = 0; sx < scale; ++sx) {
                    std::uint8_t* px =
                        &pic.data[(row * std::size_t(pic.width) + std::size_t(x * scale + sx)) * 4];
                    std::copy(rgb.begin(), rgb.end(), px);
                }
            }
        }
    }
    return pic;
}

// The pictures in rows of ceil(sqrt(n)), kMontageGap white pixels apart.
ByteImage montage(const std::vector<ByteImage>& pictures) {
    const int n = int(pictures.size());
    const int columns = int(std::ceil(std::sqrt(double(n))));
    const int rows = (n + columns - 1) / columns;
    const int w = pictures.front().width, h = pictures.front().height;
    ByteImage out{
        columns * w + (columns - 1) * kMontageGap, rows * h + (rows - 1) * kMontageGap, 4, {}};
    out.data.assign(std::size_t(out.width) * std::size_t(out.height) * 4, 255);
    for (int k = 0; k < n; ++k) {
        const int x0 = (k % columns) * (w + kMontageGap), y0 = (k / columns) * (h + kMontageGap);
        for (int y = 0; y < h; ++y) {
            const auto* src = &pictures[std::size_t(k)].data[std::size_t(y) * std::size_t(w) * 4];
            std::copy(
                src, src + std::size_t(w) * 4,
                &out.data[(std::size_t(y0 + y) * std::size_t(out.width) + std::size_t(x0)) * 4]);
        }
    }
    return out;
}

// The stacked EXR's channels (see writeVoronoi3d).
std::vector<ExrChannel> volumeChannels(const Voronoi3dResult& r) {
    const jfa::Extent3 e = r.grid.extent;
    std::vector<ExrChannel> ch{
        {"site.id", {}}, {"distance", {}}, {"exact_distance", {}}, {"error", {}}};
    for (ExrChannel& c : ch) c.values.resize(e.voxels());
    for (int z = 0; z < e.depth; ++z) {
        for (int y = 0; y < e.height; ++y) {
            const std::size_t row =
                std::size_t(z) * std::size_t(e.height) + std::size_t(e.height - 1 - y);
            for (int x = 0; x < e.width; ++x) {
                const std::size_t i = r.grid.index(x, y, z);
                const std::size_t o = row * std::size_t(e.width) + std::size_t(x);
                const std::int32_t c = r.grid.cells[i];
                const std::int64_t d = recorded(r, i, x, y, z);
                ch[0].values[o] = c == jfa::kNoSite ? -1.0f : float(r.sites[std::size_t(c)].id);
                ch[1].values[o] = c == jfa::kNoSite ? -1.0f : float(std::sqrt(double(d)));
                ch[2].values[o] = float(std::sqrt(double(r.exact[i])));
                ch[3].values[o] = d > r.exact[i] ? 1.0f : 0.0f;
            }
        }
    }
    return ch;
}

} // namespace

std::vector<int> evenlySpacedSlices(int depth, int count) {
    std::vector<int> slices;
    for (int k = 0; k < count; ++k) {
        const int z = int((2 * std::int64_t(k) + 1) * depth / (2 * std::int64_t(count)));
        if (slices.empty() || slices.back() != z) slices.push_back(z);
    }
    return slices;
}

void writeVoronoi3d(const std::filesystem::path& dir, const std::string& name,
                    const Voronoi3dResult& result, const std::vector<int>& slices,
                    std::ostream& log) {
    const jfa::Extent3 e = result.grid.extent;
    const int scale = std::max(1, kSlicePicturePixels / std::max(e.width, e.height));
    std::vector<ByteImage> pictures;
    for (int z : slices) {
        pictures.push_back(slicePicture(result, z, scale));
        const auto path = dir / (name + ".z" + std::to_string(z) + ".png");
        writePng(path, pictures.back());
        log << "wrote " << path.string() << " (slice z = " << z
            << ": regions by site, sites black, errors red, y up)\n";
    }
    const auto montagePath = dir / (name + ".montage.png");
    writePng(montagePath, montage(pictures));
    log << "wrote " << montagePath.string() << " (the " << slices.size()
        << " slices in the order given, row by row)\n";
    const auto exrPath = dir / (name + ".exr");
    writeExr(exrPath, e.width, e.height * e.depth, volumeChannels(result));
    log << "wrote " << exrPath.string() << " (" << e.width << "x" << e.height * e.depth << ": the "
        << e.depth << " slices stacked, z = 0 on top; site.id, distance, "
        << "exact_distance, error)\n";
}

} // namespace fl::app
