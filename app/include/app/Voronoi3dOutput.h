#pragma once
// What `floodlight voronoi3d` writes: chosen z slices as PNGs, one montage of them, and the
// volume's distances as one EXR with the slices stacked vertically.

#include <jfa/Jfa3d.h>

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace fl::app {

/// Most slices --slices may name (each is a PNG and a tile of the montage).
inline constexpr int kMaxPictureSlices3d = 64;

/// `count` z slices evenly spaced through `depth` (the middles of count equal bands), distinct.
std::vector<int> evenlySpacedSlices(int depth, int count);

/// A flooded volume and what it is judged against.
struct Voronoi3dResult {
    const jfa::SiteGrid3& grid;             // the flood's site indices
    const std::vector<jfa::Site3>& sites;   // the site list they index
    const std::vector<std::int64_t>& exact; // exactSquaredDistances3d of the sites
};

/// Writes DIR/NAME.z<Z>.png for every slice z of `slices` (regions coloured by site, sites in
/// the slice black, error voxels red; y up; enlarged to about 128 pixels), DIR/NAME.montage.png
/// (the same pictures in rows, in the order given, 2 white pixels apart) and DIR/NAME.exr
/// (W x H*D floats: slice z in rows z*H .. z*H+H-1 from the top, each slice y up as in the PNGs;
/// channels site.id, distance, exact_distance, error; -1 where a voxel holds no site). Each file
/// goes through a temporary and a rename (the caller's OutputSet); "wrote" lines go to `log`.
void writeVoronoi3d(const std::filesystem::path& dir, const std::string& name,
                    const Voronoi3dResult& result, const std::vector<int>& slices,
                    std::ostream& log);

} // namespace fl::app
