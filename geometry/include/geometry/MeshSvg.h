#pragma once
// SVG pictures of point sets and triangulations, built from layers so the Delaunay pipeline can
// stack what it wants to show: Voronoi cells as filled pixels, triangles as outlines, highlighted
// edges, sites on top.
//
// Coordinates are world units with +y up (the picture flips y; SVG's own y points down) and are
// written with the shortest round-trip text, so a picture can be read back exactly. The viewBox
// fits the content (or setBounds) plus a margin. Line widths and point markers are sized in
// pixels of the nominal picture size from the number of points, so that 10 points get bold
// markers and 100,000 points still show as dots and hairlines instead of a black blob.

#include <glm/glm.hpp>

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace fl::geom {

/// Presentation shared by everything in one layer (attributes of its <g>).
struct SvgStyle {
    std::string fill = "none";   ///< CSS colour of markers, circles, polygons and rectangles
    std::string stroke = "none"; ///< CSS colour of outlines and segments
    double strokeWidth = 1.0;    ///< in multiples of the picture's line width
    double markerRadius = 1.0;   ///< in multiples of the picture's point marker radius
    double opacity = 1.0;
    bool crispEdges = false; ///< no anti-aliasing: pixel grids tile without seams

    /// Filled dots (sites, input points).
    static SvgStyle markers(std::string colour, double radius = 1.0);
    /// Outlines and segments (triangles, highlighted edges).
    static SvgStyle lines(std::string colour, double width = 1.0);
    /// Filled areas (cells, pixels); shapes may bring their own colours.
    static SvgStyle areas(std::string colour = "none", double opacity = 1.0);
};

/// A raster of labels drawn as filled pixels, e.g. the site ids of a discrete Voronoi diagram.
struct SvgLabelGrid {
    int width = 0;
    int height = 0;
    glm::dvec2 origin{0.0};           ///< world position of the lower-left corner of pixel (0, 0)
    glm::dvec2 pixelSize{1.0};        ///< world size of one pixel
    std::vector<std::int32_t> labels; ///< row-major, bottom row first; negative: left empty
};

/// A distinct, deterministic colour ("#rrggbb") for a label (golden-ratio hue steps).
std::string svgPaletteColour(std::int32_t label);

/// One group of shapes sharing a style; drawn in the order added. An empty colour argument means
/// the layer's colour. Every add* throws std::invalid_argument for non-finite coordinates.
class SvgLayer {
  public:
    SvgLayer(std::string id, SvgStyle style);

    /// A point marker; its radius is the picture's marker radius times style().markerRadius.
    void addPoint(glm::dvec2 p, std::string fill = {});
    /// Point markers for every point.
    void addPoints(const std::vector<glm::dvec2>& points);
    /// A circle with a radius in world units (e.g. a circumcircle).
    void addCircle(glm::dvec2 centre, double radius, std::string fill = {});
    /// A line segment.
    void addSegment(glm::dvec2 a, glm::dvec2 b, std::string stroke = {});
    /// Segments given as consecutive pairs of end points, drawn as one path.
    void addSegments(const std::vector<glm::dvec2>& ends, std::string stroke = {});
    /// Every distinct edge of the triangles once (3 indices per triangle, checked).
    void addTriangleEdges(const std::vector<glm::dvec2>& points,
                          const std::vector<std::uint32_t>& triangles, std::string stroke = {});
    /// A closed polygon (filled with the layer's or the given fill, outlined with its stroke).
    void addPolygon(std::vector<glm::dvec2> vertices, std::string fill = {});
    /// An open polyline.
    void addPolyline(std::vector<glm::dvec2> vertices, std::string stroke = {});
    /// An axis-aligned rectangle.
    void addRect(glm::dvec2 min, glm::dvec2 max, std::string fill = {});
    /// The labelled pixels of a grid, horizontal runs of one label merged into one rectangle.
    void addLabelGrid(const SvgLabelGrid& grid,
                      const std::function<std::string(std::int32_t)>& colour = svgPaletteColour);

    [[nodiscard]] const std::string& id() const { return id_; }
    [[nodiscard]] const SvgStyle& style() const { return style_; }
    /// Number of shapes (a segment path or a merged pixel run counts once).
    [[nodiscard]] std::size_t size() const { return shapes_.size(); }
    /// Number of point markers.
    [[nodiscard]] std::size_t markerCount() const { return markers_; }
    /// Number of segments in segment paths (sizes lines when a picture has no markers).
    [[nodiscard]] std::size_t segmentCount() const { return segments_; }

    struct Marker {
        glm::dvec2 p;
        std::string colour;
    };
    struct Circle {
        glm::dvec2 centre;
        double radius;
        std::string colour;
    };
    struct Segments {
        std::vector<glm::dvec2> ends;
        std::string colour;
    };
    struct Poly {
        std::vector<glm::dvec2> vertices;
        bool closed;
        std::string colour;
    };
    struct Rect {
        glm::dvec2 min, max;
        std::string colour;
    };
    using Shape = std::variant<Marker, Circle, Segments, Poly, Rect>;
    /// The shapes, for the renderer.
    [[nodiscard]] const std::vector<Shape>& shapes() const { return shapes_; }

  private:
    std::string id_;
    SvgStyle style_;
    std::vector<Shape> shapes_;
    std::size_t markers_ = 0;
    std::size_t segments_ = 0;
};

/// Layers stacked bottom to top, rendered into one SVG document.
class SvgPicture {
  public:
    /// Adds a layer above the existing ones; the reference stays valid while the picture lives.
    SvgLayer& addLayer(std::string id, SvgStyle style = {});
    [[nodiscard]] const std::deque<SvgLayer>& layers() const { return layers_; }

    /// Shows this world rectangle (plus the margin) instead of fitting the content.
    void setBounds(glm::dvec2 min, glm::dvec2 max);
    /// Margin around the shown area as a fraction of its larger side (default 0.05).
    void setMargin(double fraction);
    /// Nominal size of the larger side in pixels (default 1024); line widths refer to it.
    void setSize(int longSidePixels);
    /// Background colour; empty for transparent (default "white").
    void setBackground(std::string colour);

    /// The SVG document; throws std::invalid_argument if the extent overflows double.
    [[nodiscard]] std::string render() const;

  private:
    std::deque<SvgLayer> layers_;
    bool fixedBounds_ = false;
    glm::dvec2 min_{0.0}, max_{0.0};
    double margin_ = 0.05;
    int size_ = 1024;
    std::string background_ = "white";
};

/// Writes picture.render() to `path` (temporary file and rename; PointFileError on failure).
void writeSvg(const std::filesystem::path& path, const SvgPicture& picture);

/// The standard picture of a triangulation: layer "triangles" (grey edges) under layer
/// "points" (dark red markers); throws std::invalid_argument for bad indices.
SvgPicture triangulationPicture(const std::vector<glm::dvec2>& points,
                                const std::vector<std::uint32_t>& triangles);

} // namespace fl::geom
