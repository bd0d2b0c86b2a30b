#include <geometry/MeshSvg.h>

#include "PointIODetail.h"

#include <base/Text.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace fl::geom {

namespace {

void requireFinite(glm::dvec2 p, const char* what) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw std::invalid_argument(std::string(what) + ": non-finite coordinate");
}

void requireFinite(const std::vector<glm::dvec2>& points, const char* what) {
    for (const glm::dvec2& p : points) requireFinite(p, what);
}

struct Bounds {
    glm::dvec2 min{std::numeric_limits<double>::infinity()};
    glm::dvec2 max{-std::numeric_limits<double>::infinity()};
    void add(glm::dvec2 p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    [[nodiscard]] bool valid() const { return min.x <= max.x && min.y <= max.y; }
};

// Writes world coordinates into SVG user units: x as is, y negated (negation is exact, so the
// text still reads back as the original value, sign flipped).
class Writer {
  public:
    std::string out;

    void number(double v) { detail::appendDouble(out, v); }
    void size(double v) { detail::appendRounded(out, v, 6); }
    void attr(const char* name, double v) {
        out += ' ';
        out += name;
        out += "=\"";
        number(v);
        out += '"';
    }
    void colourAttr(const char* name, const std::string& colour) {
        if (colour.empty()) return;
        out += ' ';
        out += name;
        out += "=\"";
        out += fl::xmlEscape(colour); // callers' values: keep the document well-formed
        out += '"';
    }
    void point(glm::dvec2 p) {
        number(p.x);
        out += ',';
        number(-p.y);
    }
};

} // namespace

// --- Style and palette --------------------------------------------------------------------------

SvgStyle SvgStyle::markers(std::string colour, double radius) {
    SvgStyle s;
    s.fill = std::move(colour);
    s.markerRadius = radius;
    return s;
}

SvgStyle SvgStyle::lines(std::string colour, double width) {
    SvgStyle s;
    s.stroke = std::move(colour);
    s.strokeWidth = width;
    return s;
}

SvgStyle SvgStyle::areas(std::string colour, double opacity) {
    SvgStyle s;
    s.fill = std::move(colour);
    s.opacity = opacity;
    s.crispEdges = true;
    return s;
}

std::string svgPaletteColour(std::int32_t label) {
    // Golden-ratio hue steps keep neighbouring labels (often neighbouring cells) far apart.
    const double h =
        std::fmod(static_cast<double>(static_cast<std::uint32_t>(label)) * 0.6180339887498949,
                  1.0) *
        6.0;
    const double s = 0.45, v = 0.95;
    const double f = h - std::floor(h);
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    glm::dvec3 rgb;
    switch (static_cast<int>(h) % 6) {
    case 0:
        rgb = {v, t, p};
        break;
    case 1:
        rgb = {q, v, p};
        break;
    case 2:
        rgb = {p, v, t};
        break;
    case 3:
        rgb = {p, q, v};
        break;
    case 4:
        rgb = {t, p, v};
        break;
    default:
        rgb = {v, p, q};
        break;
    }
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out = "#";
    for (int i = 0; i < 3; ++i) {
        const int byte = static_cast<int>(std::lround(rgb[i] * 255.0));
        out += kHex[byte >> 4];
        out += kHex[byte & 15];
    }
    return out;
}

// --- SvgLayer -----------------------------------------------------------------------------------

SvgLayer::SvgLayer(std::string id, SvgStyle style) : id_(std::move(id)), style_(std::move(style)) {}

void SvgLayer::addPoint(glm::dvec2 p, std::string fill) {
    requireFinite(p, "SvgLayer::addPoint");
    shapes_.emplace_back(Marker{p, std::move(fill)});
    ++markers_;
}

void SvgLayer::addPoints(const std::vector<glm::dvec2>& points) {
    requireFinite(points, "SvgLayer::addPoints");
    shapes_.reserve(shapes_.size() + points.size());
    for (const glm::dvec2& p : points) shapes_.emplace_back(Marker{p, {}});
    markers_ += points.size();
}

void SvgLayer::addCircle(glm::dvec2 centre, double radius, std::string fill) {
    requireFinite(centre, "SvgLayer::addCircle");
    if (!(radius >= 0.0) || !std::isfinite(radius))
        throw std::invalid_argument("SvgLayer::addCircle: radius must be finite and >= 0");
    shapes_.emplace_back(Circle{centre, radius, std::move(fill)});
}

void SvgLayer::addSegment(glm::dvec2 a, glm::dvec2 b, std::string stroke) {
    addSegments({a, b}, std::move(stroke));
}

void SvgLayer::addSegments(const std::vector<glm::dvec2>& ends, std::string stroke) {
    if (ends.size() % 2 != 0)
        throw std::invalid_argument("SvgLayer::addSegments: end points must come in pairs");
    requireFinite(ends, "SvgLayer::addSegments");
    if (ends.empty()) return;
    segments_ += ends.size() / 2;
    shapes_.emplace_back(Segments{ends, std::move(stroke)});
}

void SvgLayer::addTriangleEdges(const std::vector<glm::dvec2>& points,
                                const std::vector<std::uint32_t>& triangles, std::string stroke) {
    detail::requireTriangles(points, triangles, "SvgLayer::addTriangleEdges");
    // Shared edges once: half the path length, and translucent strokes stay even.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = triangles[t + k], b = triangles[t + (k + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::vector<glm::dvec2> ends;
    ends.reserve(2 * edges.size());
    for (const auto& [a, b] : edges) {
        ends.push_back(points[a]);
        ends.push_back(points[b]);
    }
    addSegments(ends, std::move(stroke));
}

void SvgLayer::addPolygon(std::vector<glm::dvec2> vertices, std::string fill) {
    requireFinite(vertices, "SvgLayer::addPolygon");
    if (vertices.empty()) return;
    shapes_.emplace_back(Poly{std::move(vertices), true, std::move(fill)});
}

void SvgLayer::addPolyline(std::vector<glm::dvec2> vertices, std::string stroke) {
    requireFinite(vertices, "SvgLayer::addPolyline");
    if (vertices.empty()) return;
    shapes_.emplace_back(Poly{std::move(vertices), false, std::move(stroke)});
}

void SvgLayer::addRect(glm::dvec2 min, glm::dvec2 max, std::string fill) {
    requireFinite(min, "SvgLayer::addRect");
    requireFinite(max, "SvgLayer::addRect");
    shapes_.emplace_back(Rect{glm::min(min, max), glm::max(min, max), std::move(fill)});
}

void SvgLayer::addLabelGrid(const SvgLabelGrid& grid,
                            const std::function<std::string(std::int32_t)>& colour) {
    if (grid.width < 0 || grid.height < 0 ||
        grid.labels.size() !=
            static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height)) {
        throw std::invalid_argument("SvgLayer::addLabelGrid: labels must hold width * height");
    }
    requireFinite(grid.origin, "SvgLayer::addLabelGrid");
    if (!(grid.pixelSize.x > 0.0 && grid.pixelSize.y > 0.0) || !std::isfinite(grid.pixelSize.x) ||
        !std::isfinite(grid.pixelSize.y)) {
        throw std::invalid_argument("SvgLayer::addLabelGrid: pixel size must be finite and > 0");
    }
    const auto corner = [&](int x, int y) {
        return grid.origin + glm::dvec2(x, y) * grid.pixelSize;
    };
    for (int y = 0; y < grid.height; ++y) {
        const std::int32_t* row = grid.labels.data() + static_cast<std::size_t>(y) * grid.width;
        for (int x = 0; x < grid.width;) {
            const std::int32_t label = row[x];
            int end = x + 1;
            while (end < grid.width && row[end] == label) ++end;
            if (label >= 0)
                shapes_.emplace_back(Rect{corner(x, y), corner(end, y + 1), colour(label)});
            x = end;
        }
    }
}

// --- SvgPicture ---------------------------------------------------------------------------------

SvgLayer& SvgPicture::addLayer(std::string id, SvgStyle style) {
    return layers_.emplace_back(std::move(id), std::move(style));
}

void SvgPicture::setBounds(glm::dvec2 min, glm::dvec2 max) {
    requireFinite(min, "SvgPicture::setBounds");
    requireFinite(max, "SvgPicture::setBounds");
    fixedBounds_ = true;
    min_ = glm::min(min, max);
    max_ = glm::max(min, max);
}

void SvgPicture::setMargin(double fraction) {
    if (!(fraction >= 0.0) || !std::isfinite(fraction))
        throw std::invalid_argument("SvgPicture::setMargin: fraction must be finite and >= 0");
    margin_ = fraction;
}

void SvgPicture::setSize(int longSidePixels) {
    if (longSidePixels < 1) throw std::invalid_argument("SvgPicture::setSize: size must be >= 1");
    size_ = longSidePixels;
}

void SvgPicture::setBackground(std::string colour) {
    background_ = std::move(colour);
}

namespace {

// Grows `bounds` by what `shape` covers.
void addShapeBounds(const SvgLayer::Shape& shape, Bounds& bounds) {
    if (const auto* m = std::get_if<SvgLayer::Marker>(&shape)) bounds.add(m->p);
    if (const auto* c = std::get_if<SvgLayer::Circle>(&shape)) {
        bounds.add(c->centre - c->radius);
        bounds.add(c->centre + c->radius);
    }
    if (const auto* s = std::get_if<SvgLayer::Segments>(&shape))
        for (const glm::dvec2& p : s->ends) bounds.add(p);
    if (const auto* p = std::get_if<SvgLayer::Poly>(&shape))
        for (const glm::dvec2& v : p->vertices) bounds.add(v);
    if (const auto* r = std::get_if<SvgLayer::Rect>(&shape)) {
        bounds.add(r->min);
        bounds.add(r->max);
    }
}

// The picture's view box (y up in the scene, down in SVG) and its pixel scale and sizes.
struct SvgFrame {
    glm::dvec2 viewMin, view;
    double pxPerUnit, markerPx, linePx;
};

SvgFrame svgFrame(const Bounds& bounds, double marginFraction, int size, std::size_t markers,
                  std::size_t segments) {
    const glm::dvec2 extent = bounds.max - bounds.min;
    double span = std::max(extent.x, extent.y);
    if (span == 0.0) {
        // One point (or all equal): any extent shows it; stay above the rounding of the position.
        const glm::dvec2 a = glm::abs(bounds.min);
        span = std::max(1.0, 1e-6 * std::max(a.x, a.y));
    }
    const double margin = marginFraction * span;
    const glm::dvec2 viewMin(bounds.min.x - margin, -(bounds.max.y + margin));
    const glm::dvec2 view = extent + 2.0 * margin;
    if (!std::isfinite(view.x) || !std::isfinite(view.y) || !std::isfinite(viewMin.x) ||
        !std::isfinite(viewMin.y) || !(view.x > 0 && view.y > 0))
        throw std::invalid_argument("the picture's extent overflows a double");
    // Pixel sizes from the mean spacing of the points on the nominal picture: markers 15% of
    // it, lines a sixteenth, clamped so that few points do not get blobs and many do not vanish.
    const double count = static_cast<double>(std::max<std::size_t>({1, markers, segments / 3}));
    const double spacingPx = size / std::sqrt(count);
    return {viewMin, view, size / std::max(view.x, view.y), std::clamp(0.15 * spacingPx, 0.8, 4.0),
            std::clamp(0.06 * spacingPx, 0.35, 1.5)};
}

// The <svg> element's opening and the background.
void writeSvgOpening(Writer& w, const SvgFrame& f, const std::string& background) {
    w.out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
    w.size(std::max(1.0, std::round(f.view.x * f.pxPerUnit)));
    w.out += "\" height=\"";
    w.size(std::max(1.0, std::round(f.view.y * f.pxPerUnit)));
    w.out += "\" viewBox=\"";
    w.number(f.viewMin.x);
    w.out += ' ';
    w.number(f.viewMin.y);
    w.out += ' ';
    w.number(f.view.x);
    w.out += ' ';
    w.number(f.view.y);
    w.out += "\">\n";
    if (background.empty()) return;
    w.out += "<rect";
    w.attr("x", f.viewMin.x);
    w.attr("y", f.viewMin.y);
    w.attr("width", f.view.x);
    w.attr("height", f.view.y);
    w.colourAttr("fill", background);
    w.out += "/>\n";
}

// A layer's <g> with its style.
void writeGroupOpening(Writer& w, const SvgLayer& layer, const SvgFrame& f) {
    const SvgStyle& st = layer.style();
    w.out += "<g id=\"" + fl::xmlEscape(layer.id()) + "\"";
    w.colourAttr("fill", st.fill);
    w.colourAttr("stroke", st.stroke);
    w.out += " stroke-width=\"";
    w.size(f.linePx * st.strokeWidth / f.pxPerUnit);
    w.out += "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
    if (st.opacity != 1.0) {
        w.out += " opacity=\"";
        w.size(st.opacity);
        w.out += '"';
    }
    if (st.crispEdges) w.out += " shape-rendering=\"crispEdges\"";
    w.out += ">\n";
}

// One shape as an SVG element; markers get radius `markerR` (scene units).
void writeShape(Writer& w, const SvgLayer::Shape& shape, double markerR) {
    if (const auto* m = std::get_if<SvgLayer::Marker>(&shape)) {
        w.out += "<circle";
        w.attr("cx", m->p.x);
        w.attr("cy", -m->p.y);
        w.out += " r=\"";
        w.size(markerR);
        w.out += '"';
        w.colourAttr("fill", m->colour);
    } else if (const auto* c = std::get_if<SvgLayer::Circle>(&shape)) {
        w.out += "<circle";
        w.attr("cx", c->centre.x);
        w.attr("cy", -c->centre.y);
        w.attr("r", c->radius);
        w.colourAttr("fill", c->colour);
    } else if (const auto* s = std::get_if<SvgLayer::Segments>(&shape)) {
        w.out += "<path fill=\"none\" d=\"";
        for (std::size_t i = 0; i < s->ends.size(); i += 2) {
            w.out += i == 0 ? "M" : " M";
            w.point(s->ends[i]);
            w.out += 'L';
            w.point(s->ends[i + 1]);
        }
        w.out += '"';
        w.colourAttr("stroke", s->colour);
    } else if (const auto* p = std::get_if<SvgLayer::Poly>(&shape)) {
        w.out += p->closed ? "<polygon points=\"" : "<polyline fill=\"none\" points=\"";
        for (std::size_t i = 0; i < p->vertices.size(); ++i) {
            if (i > 0) w.out += ' ';
            w.point(p->vertices[i]);
        }
        w.out += '"';
        w.colourAttr(p->closed ? "fill" : "stroke", p->colour);
    } else if (const auto* r = std::get_if<SvgLayer::Rect>(&shape)) {
        w.out += "<rect";
        w.attr("x", r->min.x);
        w.attr("y", -r->max.y);
        w.attr("width", r->max.x - r->min.x);
        w.attr("height", r->max.y - r->min.y);
        w.colourAttr("fill", r->colour);
    }
    w.out += "/>\n";
}

} // namespace

std::string SvgPicture::render() const {
    Bounds bounds;
    std::size_t markers = 0, segments = 0;
    for (const SvgLayer& layer : layers_) {
        markers += layer.markerCount();
        segments += layer.segmentCount();
        if (fixedBounds_) continue;
        for (const SvgLayer::Shape& shape : layer.shapes()) addShapeBounds(shape, bounds);
    }
    if (fixedBounds_) bounds = {min_, max_};
    if (!bounds.valid()) bounds = {glm::dvec2(0.0), glm::dvec2(1.0)};
    const SvgFrame f = svgFrame(bounds, margin_, size_, markers, segments);
    Writer w;
    writeSvgOpening(w, f, background_);
    for (const SvgLayer& layer : layers_) {
        writeGroupOpening(w, layer, f);
        const double markerR = f.markerPx * layer.style().markerRadius / f.pxPerUnit;
        for (const SvgLayer::Shape& shape : layer.shapes()) writeShape(w, shape, markerR);
        w.out += "</g>\n";
    }
    w.out += "</svg>\n";
    return std::move(w.out);
}

void writeSvg(const std::filesystem::path& path, const SvgPicture& picture) {
    detail::writeFileAtomically(path, picture.render());
}

SvgPicture triangulationPicture(const std::vector<glm::dvec2>& points,
                                const std::vector<std::uint32_t>& triangles) {
    SvgPicture picture;
    picture.addLayer("triangles", SvgStyle::lines("#555")).addTriangleEdges(points, triangles);
    picture.addLayer("points", SvgStyle::markers("#b00")).addPoints(points);
    return picture;
}

} // namespace fl::geom
