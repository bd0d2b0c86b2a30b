#pragma once
// Summaries of the shadow diagnostics image (renderer/passes/ShadowDiagnosticsPass.h) and the
// pictures made from it: texel-footprint statistics over visible receivers, the share of
// receivers whose visibility changed since the previous frame, the aliasing-map EXR and a
// footprint heat map.

#include <io/ImageIO.h>

#include <filesystem>

namespace fl {

/// Median and 95th percentile of a set of values (0 and 0 for an empty set).
struct Percentiles {
    double median = 0.0;
    double p95 = 0.0;
};

/// Nearest-rank percentile (q in [0, 1]) of `values` (reordered); 0 if empty.
double percentile(std::vector<float>& values, double q);

struct ShadowMapStats {
    std::size_t receivers = 0; // visible pixels with a receiver inside the shadow map
    Percentiles footprint;     // screen pixels per shadow texel (side length), all receivers
    Percentiles footprintNear; // the same over the nearest quarter of receivers by view depth
    double nearDepth = 0.0;    // view depth below which a receiver counts as near
    double flickerShare = 0.0; // share of receivers whose hard visibility differs from last frame
    double litShare = 0.0;     // share of receivers lit (hard visibility >= 0.5)
};

/// Summarises a diagnostics image (4 channels: footprint, view depth, visibility, previous
/// visibility; footprint 0 = no receiver). "Near" is the nearest 25% of receivers by view
/// depth: the part of the picture where shadow-map resolution matters most.
ShadowMapStats summarizeShadowDiagnostics(const FloatImage& diagnostics);

/// Writes the diagnostics as an EXR with channels footprint, viewDepth, visibility,
/// previousVisibility; throws if a value is not finite.
void writeAliasingMap(const std::filesystem::path& path, const FloatImage& diagnostics);

/// A colour picture of the footprint: log2 scale from 1/4 (blue) through 1 (green) to 16 or
/// more (red) screen pixels per texel; background black.
ByteImage footprintHeatMap(const FloatImage& diagnostics);

/// Images of equal height placed left to right with a `gap`-pixel white gutter.
ByteImage sideBySide(const std::vector<ByteImage>& images, int gap = 4);

/// Tiles of one size (RGBA) in rows of `columns`, left to right then top to bottom, with a
/// `gap`-pixel white gutter; throws std::invalid_argument for none or unequal tiles.
ByteImage tileGrid(const std::vector<ByteImage>& tiles, int columns, int gap = 4);

} // namespace fl
