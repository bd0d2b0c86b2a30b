#pragma once
// Shared by Trapezoid.cpp and TrapezoidStable.cpp: the steps a stable fit's parameters move in.

#include <geometry/Trapezoid.h>

#include <vector>

namespace fl::geom::detail {

/// The step of each kind of parameter (0: continuous); see the header's "Stability".
struct Steps {
    double angle = 0.0;  ///< centre line direction, radians
    double pos = 0.0;    ///< lines and offsets, light NDC
    double slope = 0.0;  ///< side-line slopes
    double weight = 0.0; ///< the uniform blend's weight
};

/// The steps `params` asks for.
Steps stepsOf(const TrapezoidParams& params);
/// x rounded to the nearest multiple of step (x itself for step 0).
double roundTo(double x, double step);
/// x rounded down / up to a multiple of step (x itself for step 0): extents round outwards.
double floorTo(double x, double step);
double ceilTo(double x, double step);
/// The polygon scaled by `factor` about its vertex mean (the hysteresis margin).
std::vector<glm::dvec2> scaledAbout(const std::vector<glm::dvec2>& polygon, double factor);
/// `fresh`, or the previous fit kept by hysteresis (its map, with fresh's hull and centre line).
TrapezoidFit settle(TrapezoidFit fresh, const TrapezoidFit* previous,
                    const TrapezoidParams& params);

} // namespace fl::geom::detail
