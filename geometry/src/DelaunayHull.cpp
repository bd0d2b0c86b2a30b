// Step C1 of the thesis (§6.3.3, "Fix Convex Hull"): triangles whose Voronoi vertex lies outside
// the texture are missing from T', so its boundary may be concave and T' may even fall apart into
// pieces (Fig. 6.8). The thesis walks the texture border counterclockwise from the lowest site,
// Graham-style: consecutive border sites that turn clockwise get the missing triangle.
//
// Ambiguities resolved here:
//   - "consecutive sites" = the colours met along the border with repeats collapsed (a slim
//     region reaching the border twice appears twice, as it must for pieces to be linked);
//   - after a triangle is added the middle site is popped and the turn re-tested against the
//     new top (as Graham's scan does), so a deep pocket is filled completely;
//   - the walk closes by re-visiting the lowest site, which is on the hull and never popped;
//   - collinear turns (orientation 0) add nothing: collinear hull points stay on the hull.
// All tests are on pixel positions in 64-bit integers. Whether the result really is a
// triangulation of S' is not assumed: the driver certifies it (WorkMesh::isTriangulation).
#include <geometry/detail/DelaunaySteps.h>

#include <algorithm>

namespace fl::geom::detail {

std::optional<std::size_t> completeHull(const DiscreteDelaunay& discrete,
                                        std::vector<std::uint32_t>& tris) {
    const IdTexture& ids = discrete.cleaned;
    const std::vector<glm::ivec2>& pixels = discrete.snapped.pixels;
    const int n = ids.width;
    if (n < 2 || ids.height != n || ids.ids.size() != std::size_t(n) * std::size_t(n))
        return std::nullopt;

    // The border counterclockwise: bottom row, right column, top row, left column.
    std::vector<std::uint32_t> border;
    const auto visit = [&](int x, int y) {
        const std::uint32_t id = ids.at(x, y);
        if (id >= pixels.size()) return;
        if (border.empty() || border.back() != id) border.push_back(id);
    };
    for (int x = 0; x < n; ++x) visit(x, 0);
    for (int y = 1; y < n; ++y) visit(n - 1, y);
    for (int x = n - 2; x >= 0; --x) visit(x, n - 1);
    for (int y = n - 2; y >= 1; --y) visit(0, y);
    while (border.size() > 1 && border.back() == border.front()) border.pop_back();
    if (border.size() < 3) return std::size_t{0};

    // Start at the lowest (then leftmost) site on the border: an extreme point, so it is on the
    // hull and the scan never pops it.
    const auto lower = [&](std::uint32_t a, std::uint32_t b) {
        const glm::ivec2 pa = pixels[a], pb = pixels[b];
        return pa.y != pb.y ? pa.y < pb.y : pa.x < pb.x;
    };
    std::rotate(border.begin(), std::min_element(border.begin(), border.end(), lower),
                border.end());
    border.push_back(border.front());

    std::size_t added = 0;
    std::vector<std::uint32_t> stack;
    for (const std::uint32_t c : border) {
        while (stack.size() >= 2) {
            const std::uint32_t a = stack[stack.size() - 2], b = stack.back();
            if (pixelOrient(pixels[a], pixels[b], pixels[c]) >= 0) break;
            tris.insert(tris.end(), {a, c, b}); // counterclockwise: b lies right of a -> c
            ++added;
            stack.pop_back();
        }
        stack.push_back(c);
    }
    return added;
}

} // namespace fl::geom::detail
