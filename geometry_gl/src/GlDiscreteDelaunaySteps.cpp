// Steps G1-G6 of the thesis (§6.3.2) as GL compute dispatches (shaders/delaunay_*.glsl); the
// CPU twins are in DiscreteVoronoi*.cpp and DiscreteTriangles*.cpp. No step reads anything back:
// every count a later step needs stays on the GPU (indirect dispatch, a prefix sum), and what the
// host needs lands in one result buffer (GlDiscreteDelaunayResult.cpp reads it).
#include "GlDiscreteDelaunayDetail.h"

#include <gpu/BindScope.h>

#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fl::geom {

namespace {

constexpr GLuint kNoSiteValue = kNoSite;
constexpr int kItemGroup = 64; // local size of the 1D kernels (sites, rows)
constexpr int kTileSide = 8;   // local size of the 2D kernels (8 x 8 texels)
constexpr GLsizeiptr kControlWords = 16;
constexpr GLintptr kChangedOffset = gl_stages::kCtlChanged * sizeof(GLuint);

// Every later reader of a step's output: samplers, images, atomic counters, SSBOs, indirect
// dispatches, pixel-pack copies and the host's map. One generous barrier per dispatch costs
// little next to the dispatch and leaves no reader to forget.
constexpr GLbitfield kAfterWrites =
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT |
    GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT;

// The steps' uniforms, one table per shader (delaunay_*.comp.glsl).
constexpr struct {
    gl::Uniform<int> count{"uCount"};
    gl::Uniform<int> mode{"uMode"};
} kSites;
constexpr gl::Uniform<glm::ivec2> kIdsSize{"uSize"};
constexpr gl::Uniform<glm::ivec2> kIslandsSize{"uSize"};
constexpr struct {
    gl::Uniform<glm::ivec2> groups{"uGroups"};
    gl::Uniform<int> cap{"uCap"};
    gl::Uniform<int> reset{"uReset"};
} kIslandsControl;
constexpr gl::Uniform<glm::ivec2> kResolveSize{"uSize"};
constexpr gl::Uniform<glm::ivec2> kCornersSize{"uSize"};
constexpr struct {
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<int> step{"uStep"};
    gl::Uniform<int> fromCorners{"uFromCorners"};
} kChain;
constexpr struct {
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<int> mode{"uMode"};
    gl::Uniform<int> vertexCapacity{"uVertexCapacity"};
    gl::Uniform<int> triangleCapacity{"uTriangleCapacity"};
} kTriangles;
constexpr gl::Uniform<int> kScanRows{"uRows"};

// One step's program, its uniform table bound.
gl::Program buildStep(const gl::ShaderLibrary& shaders, const char* file,
                      std::initializer_list<const gl::UniformBase*> uniforms) {
    gl::Program program = gl::Program::build(shaders, {{GL_COMPUTE_SHADER, file}});
    program.bindUniforms(uniforms);
    return program;
}

// A buffer of at least `bytes` (never empty: zero-sized storage is a GL error, and the kernels
// declare every buffer whether or not a run uses it); keeps the contents only when it fits.
void ensureBuffer(gl::Buffer& buffer, std::size_t bytes, GLbitfield flags = 0) {
    const auto need = static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 16));
    if (buffer && buffer.size() >= need) return;
    // Growing by half again keeps repeated runs with slowly rising counts from reallocating.
    const GLsizeiptr size = std::max(need, buffer.size() + buffer.size() / 2);
    buffer = gl::Buffer(size, nullptr, GL_DYNAMIC_STORAGE_BIT | flags);
}

// One invocation per item; more than 65535 groups (2^24 sites) spill into y (dispatchIndex()).
void dispatchItems(std::size_t count) {
    if (count == 0) return;
    const std::size_t groups = (count + kItemGroup - 1) / kItemGroup;
    const std::size_t x = std::min<std::size_t>(groups, 65535);
    glDispatchCompute(static_cast<GLuint>(x), static_cast<GLuint>((groups + x - 1) / x), 1);
    glMemoryBarrier(kAfterWrites);
}

glm::ivec2 texelGroups(int w, int h) {
    return {(w + kTileSide - 1) / kTileSide, (h + kTileSide - 1) / kTileSide};
}

// One invocation per texel of a W x H texture.
void dispatchTexels(int w, int h) {
    const glm::ivec2 groups = texelGroups(w, h);
    glDispatchCompute(static_cast<GLuint>(groups.x), static_cast<GLuint>(groups.y), 1);
    glMemoryBarrier(kAfterWrites);
}

void dispatchOne() {
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(kAfterWrites);
}

// Leaves no program or buffer target behind a step (DESIGN: no global GL state outside a pass);
// the step's BindScope unbinds its textures, images and buffer binding points.
void endStep() {
    glUseProgram(0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

void bindImage(gl::BindScope& scope, gl::ImageUnit unit, const gl::Texture& texture,
               GLenum access) {
    scope.image(unit, texture.id(), access, texture.format());
}

// Binds `bytes` at `offset` of `buffer` (a result part; never an empty range, a GL error).
void bindPart(gl::BindScope& scope, gl::StorageBinding binding, const gl::Buffer& buffer,
              std::size_t offset, std::size_t bytes) {
    scope.storage(binding, buffer.id(), static_cast<GLintptr>(offset),
                  static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, sizeof(GLuint))));
}

// The result header, bound whole.
void bindHeader(gl::BindScope& scope, const gl::Buffer& result) {
    bindPart(scope, gl::bind::DelaunayHeader, result, 0, gl_stages::kHeaderWords * sizeof(GLuint));
}

std::size_t alignUp(std::size_t bytes, std::size_t alignment) {
    return (bytes + alignment - 1) / alignment * alignment;
}

} // namespace

namespace gl_stages {

ResultLayout layoutResult(std::size_t sites, std::size_t texels, std::size_t vertexCap,
                          std::size_t triangleCap, std::size_t alignment) {
    ResultLayout l;
    l.sites = sites;
    l.texels = texels;
    l.vertexCap = vertexCap;
    l.triangleCap = triangleCap;
    // Each part gets at least a word so that binding it is never an empty range.
    std::size_t at = alignUp(kHeaderWords * sizeof(GLuint), alignment);
    const auto place = [&](std::size_t& offset, std::size_t words) {
        offset = at;
        at = alignUp(at + std::max<std::size_t>(words, 1) * sizeof(GLuint), alignment);
    };
    place(l.keepers, sites);
    place(l.cleaned, texels);
    place(l.vertices, 6 * vertexCap);
    place(l.triangles, 3 * triangleCap);
    place(l.triangleVertex, triangleCap);
    l.end = at;
    return l;
}

} // namespace gl_stages

GlDiscreteDelaunay::Impl::Impl(const gl::ShaderLibrary& shaders, jfa::GlKernelKind flood)
    : sitesProgram(buildStep(shaders, "delaunay_sites.comp.glsl", {&kSites.count, &kSites.mode})),
      idsProgram(buildStep(shaders, "delaunay_ids.comp.glsl", {&kIdsSize})),
      islandsProgram(buildStep(shaders, "delaunay_islands.comp.glsl", {&kIslandsSize})),
      controlProgram(
          buildStep(shaders, "delaunay_islands_control.comp.glsl",
                    {&kIslandsControl.groups, &kIslandsControl.cap, &kIslandsControl.reset})),
      resolveProgram(buildStep(shaders, "delaunay_islands_resolve.comp.glsl", {&kResolveSize})),
      cornersProgram(buildStep(shaders, "delaunay_corners.comp.glsl", {&kCornersSize})),
      chainProgram(buildStep(shaders, "delaunay_chain.comp.glsl",
                             {&kChain.size, &kChain.step, &kChain.fromCorners})),
      trianglesProgram(buildStep(shaders, "delaunay_triangles.comp.glsl",
                                 {&kTriangles.size, &kTriangles.mode, &kTriangles.vertexCapacity,
                                  &kTriangles.triangleCapacity})),
      scanProgram(buildStep(shaders, "delaunay_rows_scan.comp.glsl", {&kScanRows})),
      floodKernel(shaders, flood),
      control(kControlWords * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT) {
    GLint alignment = 0;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
    storageAlignment = std::max<std::size_t>(storageAlignment, std::size_t(alignment));
    gl::throwIfErrors("GL discrete Delaunay setup");
}

void GlDiscreteDelaunay::Impl::resize(int w, int h) {
    if (w == width && h == height) return;
    owner = gl::Texture(GL_R32UI, w, h);
    seeds = gl::Texture(GL_RGBA32F, w, h);
    voronoi = gl::Texture(GL_R32UI, w, h);
    for (gl::Texture& t : islands) t = gl::Texture(GL_R32UI, w, h);
    cleaned = gl::Texture(GL_R32UI, w, h);
    corners = gl::Texture(GL_R8UI, w, h);
    for (gl::Texture& t : chain) t = gl::Texture(GL_R32I, w, h);
    width = w;
    height = h;
}

void GlDiscreteDelaunay::Impl::uploadPixels(const std::vector<glm::ivec2>& sitePixels) {
    static_assert(sizeof(glm::ivec2) == 2 * sizeof(GLint), "std430 ivec2 layout");
    ensureBuffer(pixels, sitePixels.size() * sizeof(glm::ivec2));
    if (sitePixels.empty()) return;
    glNamedBufferSubData(pixels.id(), 0,
                         static_cast<GLsizeiptr>(sitePixels.size() * sizeof(glm::ivec2)),
                         sitePixels.data());
    ++extras.uploads;
}

void GlDiscreteDelaunay::Impl::prepareResult(std::size_t sites, std::size_t texels,
                                             std::size_t vertexCap, std::size_t triangleCap) {
    layout = gl_stages::layoutResult(sites, texels, vertexCap, triangleCap, storageAlignment);
    ensureBuffer(result, layout.end, GL_MAP_READ_BIT);
    const GLuint zero = 0;
    glClearNamedBufferSubData(result.id(), GL_R32UI, 0, gl_stages::kHeaderWords * sizeof(GLuint),
                              GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void GlDiscreteDelaunay::Impl::claimPixels(std::size_t count) {
    glClearTexImage(owner.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &kNoSiteValue);
    const jfa::Cell empty = jfa::kEmptyCell;
    glClearTexImage(seeds.id(), 0, GL_RGBA, GL_FLOAT, &empty);
    if (count == 0) return;
    glUseProgram(sitesProgram.id());
    gl::BindScope scope;
    bindImage(scope, gl::bind::DelaunayOwner, owner, GL_READ_WRITE);
    bindImage(scope, gl::bind::DelaunaySeeds, seeds, GL_WRITE_ONLY);
    scope.storage(gl::bind::DelaunayPixels, pixels.id());
    bindPart(scope, gl::bind::DelaunayKeepers, result, layout.keepers, count * sizeof(GLuint));
    sitesProgram.set(kSites.count, static_cast<int>(count));
    // Two dispatches: every claim must land before any site reads its pixel's owner.
    for (int mode : {0, 1}) {
        sitesProgram.set(kSites.mode, mode);
        dispatchItems(count);
    }
    endStep();
}

void GlDiscreteDelaunay::Impl::flood(const jfa::Plan& plan) {
    // The CPU's criterion exactly (integer sites), so the GL kernel's cells equal the CPU
    // kernel's texel for texel.
    const gl::Texture& cells = floodKernel.run(plan, seeds, jfa::NearestSite{true});
    glUseProgram(idsProgram.id());
    gl::BindScope scope;
    scope.texture(gl::bind::DelaunayCells, cells.id());
    bindImage(scope, gl::bind::DelaunayOut, voronoi, GL_WRITE_ONLY);
    idsProgram.set(kIdsSize, glm::ivec2(width, height));
    dispatchTexels(width, height);
    endStep();
}

void GlDiscreteDelaunay::Impl::removeIslands(const gl::Texture& in, int bound) {
    // The CPU's cap (removeIslands): 2 N passes end it should recolouring ever cycle.
    const int cap = 2 * std::max(width, height);
    const int passes = std::clamp(bound, 1, cap);
    glUseProgram(controlProgram.id());
    gl::BindScope scope;
    scope.storage(gl::bind::DelaunayControl, control.id());
    controlProgram.set(kIslandsControl.groups, texelGroups(width, height));
    controlProgram.set(kIslandsControl.cap, cap);
    controlProgram.set(kIslandsControl.reset, 1);
    dispatchOne();
    controlProgram.set(kIslandsControl.reset, 0);
    islandsProgram.set(kIslandsSize, glm::ivec2(width, height));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, control.id());
    scope.storage(gl::bind::DelaunayPixels, pixels.id())
        .counter(gl::bind::ChangedCounter, control.id(), kChangedOffset, sizeof(GLuint));
    const gl::Texture* src = &in;
    for (int pass = 0; pass < passes; ++pass) {
        // Ping-pong: a pass reads only the previous pass' texture, as on the CPU. Once the loop
        // has ended the control pass has set the dispatch to zero groups: queued, never run.
        const gl::Texture& dst = islands[pass % 2];
        glUseProgram(islandsProgram.id());
        scope.texture(gl::bind::DelaunayIslandsIn, src->id());
        bindImage(scope, gl::bind::DelaunayOut, dst, GL_WRITE_ONLY);
        glDispatchComputeIndirect(0);
        glMemoryBarrier(kAfterWrites);
        glUseProgram(controlProgram.id());
        dispatchOne();
        src = &dst;
    }
    scope.release();
    endStep();
    glUseProgram(resolveProgram.id());
    scope.texture(gl::bind::DelaunayIslandsIn, in.id())
        .texture(gl::bind::DelaunayPing, islands[0].id())
        .texture(gl::bind::DelaunayPong, islands[1].id());
    bindImage(scope, gl::bind::DelaunayOut, cleaned, GL_WRITE_ONLY);
    scope.storage(gl::bind::DelaunayControl, control.id());
    bindHeader(scope, result);
    resolveProgram.set(kResolveSize, glm::ivec2(width, height));
    dispatchTexels(width, height);
    endStep();
}

void GlDiscreteDelaunay::Impl::classifyCorners(const gl::Texture& ids) {
    glUseProgram(cornersProgram.id());
    gl::BindScope scope;
    scope.texture(gl::bind::DelaunayIds, ids.id());
    bindImage(scope, gl::bind::DelaunayOut, corners, GL_WRITE_ONLY);
    bindHeader(scope, result);
    cornersProgram.set(kCornersSize, glm::ivec2(width, height));
    dispatchTexels(width, height);
    endStep();
}

const gl::Texture& GlDiscreteDelaunay::Impl::chainRows() {
    // jfaSteps(width), as chainRowsJfa runs them. (Fusing the short steps into one
    // shared-memory dispatch gave the same chains but no speed-up on llvmpipe, where a group
    // barrier costs about what a pass does.)
    std::vector<int> steps = jfa::jfaSteps(width);
    // A one-texel-wide texture has no steps; one pass that reads nothing to its right still
    // seeds the chain.
    if (steps.empty()) steps.push_back(width);
    glUseProgram(chainProgram.id());
    chainProgram.set(kChain.size, glm::ivec2(width, height));
    gl::BindScope scope;
    scope.texture(gl::bind::DelaunayCorners, corners.id());
    int current = 1; // the first pass reads the corners; chain[1] is only bound, never read
    bool first = true;
    for (int step : steps) {
        const int dst = current ^ 1;
        chainProgram.set(kChain.step, step);
        chainProgram.set(kChain.fromCorners, first ? 1 : 0);
        scope.texture(gl::bind::DelaunayChainIn, chain[current].id());
        bindImage(scope, gl::bind::DelaunayOut, chain[dst], GL_WRITE_ONLY);
        dispatchTexels(width, height);
        current = dst;
        first = false;
    }
    endStep();
    return chain[current];
}

void GlDiscreteDelaunay::Impl::buildTriangles(const gl::Texture& ids,
                                              const gl::Texture& chainTexture) {
    const int rowCount = height - 1; // corner rows; the top row's corners lie on the border
    if (rowCount <= 0 || width < 2) return;
    ensureBuffer(rows, std::size_t(rowCount) * 4 * sizeof(GLuint));
    glUseProgram(trianglesProgram.id());
    gl::BindScope scope;
    scope.texture(gl::bind::DelaunayIds, ids.id())
        .texture(gl::bind::DelaunayCorners, corners.id())
        .texture(gl::bind::DelaunayChain, chainTexture.id())
        .storage(gl::bind::DelaunayPixels, pixels.id());
    bindHeader(scope, result);
    scope.storage(gl::bind::DelaunayRows, rows.id());
    bindPart(scope, gl::bind::DelaunayVertices, result, layout.vertices,
             6 * layout.vertexCap * sizeof(GLuint));
    bindPart(scope, gl::bind::DelaunayTriangles, result, layout.triangles,
             3 * layout.triangleCap * sizeof(GLuint));
    bindPart(scope, gl::bind::DelaunayTriangleVertex, result, layout.triangleVertex,
             layout.triangleCap * sizeof(GLuint));
    trianglesProgram.set(kTriangles.size, glm::ivec2(width, height));
    trianglesProgram.set(kTriangles.vertexCapacity, static_cast<int>(layout.vertexCap));
    trianglesProgram.set(kTriangles.triangleCapacity, static_cast<int>(layout.triangleCap));
    trianglesProgram.set(kTriangles.mode, 0);
    dispatchItems(std::size_t(rowCount));
    // Each row's first vertex and triangle: the CPU's row-major order, no host copying.
    glUseProgram(scanProgram.id());
    scanProgram.set(kScanRows, rowCount);
    dispatchOne();
    glUseProgram(trianglesProgram.id());
    trianglesProgram.set(kTriangles.mode, 1);
    dispatchItems(std::size_t(rowCount));
    endStep();
}

void GlDiscreteDelaunay::Impl::packCleaned() {
    if (layout.texels == 0) return;
    // A copy on the GPU into the result buffer, so that the one read-back brings it along.
    glBindBuffer(GL_PIXEL_PACK_BUFFER, result.id());
    GLint alignment = 4;
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(cleaned.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                      static_cast<GLsizei>(layout.texels * sizeof(GLuint)),
                      reinterpret_cast<void*>(static_cast<std::uintptr_t>(layout.cleaned)));
    glPixelStorei(GL_PACK_ALIGNMENT, alignment);
    glMemoryBarrier(kAfterWrites);
    endStep();
}

} // namespace fl::geom
