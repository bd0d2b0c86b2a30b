#pragma once
// The shadow methods' options as structs, for the methods that share them or whose options other
// code reads (a method with options of its own declares its struct in its own file, as vsm
// does): the method reads these fields (in.options<PcfOptions>().kernel), its row in the method
// table binds each field to its option's metadata (MethodTable.cpp: flag, capture key, range,
// default, help), and the renderer parses the settings' values into it once per settings. Members
// take their option's default when parsed, so they carry no initializer of their own (a second copy
// of the default).

#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/FilteredShadow.h>
#include <renderer/soft/OccluderEdge.h>

#include <geometry/DiskSampling.h>
#include <jfa/Band.h>

namespace fl {

/// What every flooding method takes (jfa-l, flood-l, jfa-e, flood-e).
struct FloodOptions {
    int passes;              // --jfa-passes; kAutoPasses for auto
    bool fullJfa;            // --full-jfa
    jfa::FloodRegion region; // --flood-region
    int bandTile;            // --band-tile
};

/// jfa-l, flood-l.
struct LightFloodOptions {
    FloodOptions flood;
    bool bothSides; // --penumbra both (else outer)
};

/// jfa-e, flood-e.
struct EyeFloodOptions {
    FloodOptions flood;
    bool noObjectIdFix;
    bool noMidpointFix;
    float boundaryThreshold;
    OccluderPoints occluderPoints;
    EyeAutoPasses autoPasses;
};

struct PcfOptions {
    int kernel;
};

struct PcssOptions {
    PcssPreset preset;
};

/// reference: N point-light shadow maps.
struct GroundTruthOptions {
    int samples;
    int mapSize;
    geom::DiskPattern pattern;
};

/// raytrace.
struct RayTraceOptions {
    int samples;
    bool grid;
    bool terminatorOffset; // --terminator-offset on
};

} // namespace fl
