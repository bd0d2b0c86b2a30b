// Vertex posing shared by every pass that draws the scene (forward.vert.glsl for the eye,
// shadow_depth.vert.glsl for the light): morph targets, then skinning or the instance's
// transform, for this frame and for the frame before (the surfaces pass's motion target).
// GpuScene::setPose uploads what these read; renderer/scene/Pose.cpp (posedVertices) is the CPU
// twin. Static scenes take the uniform branches that skip all of it.
#include "bindings.glsl"
layout(location = 4) in uvec4 aJoints; // JOINTS_0 (skinned meshes only)
layout(location = 5) in vec4 aWeights; // WEIGHTS_0

// Every skin's joint matrices, this frame's then the previous frame's.
layout(std430, binding = FL_SSBO_POSE_JOINTS) readonly buffer PoseJoints { mat4 poseJoints[]; };
// Every mesh's morph deltas: per target, its vertices' position deltas then their normal deltas.
layout(std430, binding = FL_SSBO_POSE_MORPHS) readonly buffer PoseMorphs { vec4 poseMorphs[]; };

const int kMaxMorphTargets = 32; // renderer/scene/Scene.h kMaxMorphTargets

uniform mat4 uModel;
uniform mat4 uPreviousModel;
uniform int uJointBase = -1;         // first joint of this instance's skin; < 0: not skinned
uniform int uPreviousJointBase = -1;
uniform int uMorphBase = 0;           // first delta of this mesh in poseMorphs
uniform int uMorphCount = 0;          // its targets (0: none)
uniform int uMorphVertices = 0;       // its vertex count
uniform int uBaseVertex = 0;          // its first vertex in the vertex buffer
uniform float uMorphWeights[kMaxMorphTargets];
uniform float uPreviousMorphWeights[kMaxMorphTargets];

/// The vertex's position (part 0) or normal (part 1) with the morph targets applied.
vec3 morphed(vec3 base, int part, bool previous) {
    int v = gl_VertexID - uBaseVertex;
    for (int t = 0; t < uMorphCount; ++t) {
        float w = previous ? uPreviousMorphWeights[t] : uMorphWeights[t];
        base += w * poseMorphs[uMorphBase + (2 * t + part) * uMorphVertices + v].xyz;
    }
    return base;
}

/// Model -> world for this vertex: its skin's blend of joint matrices, or the instance's.
mat4 poseModel(bool previous) {
    int base = previous ? uPreviousJointBase : uJointBase;
    if (base < 0) return previous ? uPreviousModel : uModel;
    return aWeights.x * poseJoints[base + int(aJoints.x)] +
           aWeights.y * poseJoints[base + int(aJoints.y)] +
           aWeights.z * poseJoints[base + int(aJoints.z)] +
           aWeights.w * poseJoints[base + int(aJoints.w)];
}

/// This frame's (or the previous frame's) world position of the vertex.
vec4 poseWorld(vec3 position, bool previous) {
    return poseModel(previous) * vec4(morphed(position, 0, previous), 1.0);
}
