#version 450 core
#include "bindings.glsl"
// Between two G3 passes (thesis §6.3.2, removeIslands in geometry/DiscreteVoronoi.h): the
// thesis' occlusion-query loop without a read-back. One invocation reads the pass' counter of
// recoloured pixels, keeps the IslandStats and sets the next pass' indirect dispatch to zero
// groups once a pass changed nothing (or the 2 N cap is reached), so the host can queue a fixed
// number of passes and never wait for one.
#include "delaunay_common.glsl"

layout(local_size_x = 1) in;

// Binding 2: the island pass keeps its site pixels at 0.
layout(std430, binding = FL_SSBO_DELAUNAY_CONTROL) buffer Control { uint control[]; };
uniform ivec2 uGroups; // the island pass' work groups
uniform int uCap;      // passes at most (2 N, as on the CPU)
uniform int uReset;    // 1: start a new loop

void main() {
    if (uReset != 0) {
        control[kCtlGroupsX] = uint(uGroups.x);
        control[kCtlGroupsY] = uint(uGroups.y);
        control[kCtlGroupsZ] = 1u;
        control[kCtlActive] = 1u;
        control[kCtlPasses] = 0u;
        control[kCtlChanging] = 0u;
        control[kCtlReassignedLo] = 0u;
        control[kCtlReassignedHi] = 0u;
        control[kCtlConverged] = 1u;
        control[kCtlChanged] = 0u;
        return;
    }
    if (control[kCtlActive] == 0u) return;
    uint passes = control[kCtlPasses] + 1u;
    uint changed = control[kCtlChanged];
    control[kCtlPasses] = passes;
    control[kCtlChanged] = 0u;
    if (changed == 0u) {
        control[kCtlActive] = 0u;
    } else {
        uint carry;
        control[kCtlReassignedLo] = uaddCarry(control[kCtlReassignedLo], changed, carry);
        control[kCtlReassignedHi] += carry;
        control[kCtlChanging] += 1u;
        if (passes >= uint(uCap)) {
            control[kCtlActive] = 0u;
            control[kCtlConverged] = 0u;
        }
    }
    if (control[kCtlActive] == 0u) control[kCtlGroupsX] = 0u;
}
