// The real-model benchmark's mesh readers (bench/support/MeshImport.h): OBJ with negative
// indices and a quad, a binary STL, an ASCII and a binary PLY; crease-angle normals (smooth
// across a shallow fold, split across a sharp one); bad input as one message naming the line
// or element.

#include <MeshImport.h>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace fl::bench {
namespace {

std::span<const unsigned char> bytesOf(const std::string& s) {
    return {reinterpret_cast<const unsigned char*>(s.data()), s.size()};
}

// Two triangles sharing the edge (0,0,0)-(1,0,0), folded about it by `degrees` (0: flat).
std::vector<glm::vec3> foldedPair(float degrees) {
    const float a = glm::radians(degrees);
    return {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, // in the plane z = 0
            {1, 0, 0}, {0, 0, 0}, {0.5f, -std::cos(a), -std::sin(a)}};
}

// A binary STL of the given triangles (facet normals zero, as many exporters write them).
std::string binaryStl(const std::vector<glm::vec3>& corners) {
    std::string out(80, ' ');
    const auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(v >> (8 * i)));
    };
    u32(static_cast<std::uint32_t>(corners.size() / 3));
    for (std::size_t t = 0; t < corners.size(); t += 3) {
        for (int i = 0; i < 3; ++i) u32(0);
        for (std::size_t k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) u32(std::bit_cast<std::uint32_t>(corners[t + k][a]));
        out += std::string(2, '\0');
    }
    return out;
}

void expectUnitNormals(const Mesh& m) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

// The normals the mesh gives the shared edge's two ends, per triangle: how many distinct ones.
std::size_t normalsAtSharedEdge(const Mesh& m) {
    std::vector<glm::vec3> seen;
    for (std::uint32_t i : m.indices) {
        if (m.positions[i] != glm::vec3(0, 0, 0)) continue;
        bool known = false;
        for (const glm::vec3& n : seen) known = known || n == m.normals[i];
        if (!known) seen.push_back(m.normals[i]);
    }
    return seen.size();
}

TEST(MeshImport, ObjQuadWithNegativeIndicesIsTwoTriangles) {
    const std::string obj = "# a unit quad and a triangle, in two groups\n"
                            "g quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                            "f -4 -3 -2 -1\n"
                            "g tri\nv 0 0 1\nv +1 0 1\r\nv 0 1 1\n"
                            "f 5 -2 7\n";
    const ImportedMesh m = readObj(obj, "quad.obj");
    EXPECT_EQ(m.polygons, 2u);
    ASSERT_EQ(m.mesh.triangleCount(), 3u);
    EXPECT_EQ(m.mesh.positions.size(), 7u);
    EXPECT_TRUE(m.mesh.normals.empty()); // the file has none
    // The fan of the quad: (0,1,2), (0,2,3), at the quad's corners.
    EXPECT_EQ(m.mesh.positions[m.mesh.indices[2]], glm::vec3(1, 1, 0));
    EXPECT_EQ(m.mesh.positions[m.mesh.indices[5]], glm::vec3(0, 1, 0));
    EXPECT_EQ(m.mesh.positions[m.mesh.indices[7]], glm::vec3(1, 0, 1));
}

TEST(MeshImport, ObjKeepsItsNormals) {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                            "f 1/1/1 2/2/1 3/3/1\n";
    const ImportedMesh m = readObj(obj, "t.obj");
    ASSERT_EQ(m.mesh.normals.size(), 3u);
    EXPECT_EQ(m.mesh.normals[1], glm::vec3(0, 0, 1));
    ASSERT_EQ(m.mesh.texcoords.size(), 3u);
    EXPECT_EQ(m.mesh.texcoords[2], glm::vec2(0, 0)); // v flipped: glTF's origin is top-left
}

TEST(MeshImport, BinaryStlOfTwoTriangles) {
    const ImportedMesh m = readStl(bytesOf(binaryStl(foldedPair(0.0f))), "pair.stl");
    EXPECT_EQ(m.format, "binary STL");
    ASSERT_EQ(m.mesh.triangleCount(), 2u);
    EXPECT_EQ(m.mesh.positions[m.mesh.indices[2]], glm::vec3(0.5f, 1, 0));
    EXPECT_EQ(m.mesh.positions[m.mesh.indices[5]], glm::vec3(0.5f, -1, 0));
}

TEST(MeshImport, AsciiStl) {
    const std::string stl = "solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                            "   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid s\n";
    const ImportedMesh m = readStl(bytesOf(stl), "a.stl");
    EXPECT_EQ(m.format, "ASCII STL");
    EXPECT_EQ(m.mesh.triangleCount(), 1u);
}

TEST(MeshImport, AsciiPlyWithAQuadAndAnUnusedElement) {
    const std::string ply = "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 4\n"
                            "property float x\nproperty float y\nproperty float z\n"
                            "property uchar red\nelement face 1\n"
                            "property list uchar int vertex_indices\nelement extra 1\n"
                            "property int n\nend_header\n"
                            "0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 0 9\n4 0 1 2 3\n7\n";
    const ImportedMesh m = readPly(bytesOf(ply), "q.ply");
    EXPECT_EQ(m.format, "ASCII PLY");
    EXPECT_EQ(m.polygons, 1u);
    ASSERT_EQ(m.mesh.triangleCount(), 2u);
    EXPECT_EQ(m.mesh.positions[m.mesh.indices[4]], glm::vec3(1, 1, 0));
    EXPECT_TRUE(m.mesh.normals.empty());
}

TEST(MeshImport, BinaryPlyWithNormals) {
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                      "property float x\nproperty float y\nproperty float z\n"
                      "property float nx\nproperty float ny\nproperty float nz\n"
                      "element face 1\nproperty list uchar uint vertex_index\nend_header\n";
    const auto f32 = [&](float v) {
        for (int i = 0; i < 4; ++i)
            ply.push_back(static_cast<char>(std::bit_cast<std::uint32_t>(v) >> (8 * i)));
    };
    for (const glm::vec3& p : {glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(0, 2, 0)}) {
        f32(p.x), f32(p.y), f32(p.z), f32(0), f32(0), f32(1);
    }
    ply.push_back(3);
    for (char i : {0, 1, 2}) ply += std::string{i, 0, 0, 0};
    const ImportedMesh m = readPly(bytesOf(ply), "b.ply");
    EXPECT_EQ(m.format, "binary PLY");
    ASSERT_EQ(m.mesh.triangleCount(), 1u);
    EXPECT_EQ(m.mesh.positions[1], glm::vec3(2, 0, 0));
    ASSERT_EQ(m.mesh.normals.size(), 3u);
    EXPECT_EQ(m.mesh.normals[2], glm::vec3(0, 0, 1));
}

TEST(MeshImport, NormalsAreSmoothBelowTheCreaseAngleAndSplitAbove) {
    for (const float fold : {30.0f, 90.0f}) {
        Mesh m = readStl(bytesOf(binaryStl(foldedPair(fold))), "fold.stl").mesh;
        EXPECT_EQ(computeCreaseNormals(m, kCreaseDegrees), 0u);
        expectUnitNormals(m);
        ASSERT_EQ(m.triangleCount(), 2u);
        // The shared edge's ends are welded (the STL repeats them): one vertex with the mean of
        // both faces' normals below the crease angle, one per face above it.
        EXPECT_EQ(normalsAtSharedEdge(m), fold < kCreaseDegrees ? 1u : 2u) << fold;
        if (fold < kCreaseDegrees) {
            EXPECT_EQ(m.positions.size(), 4u);
            const glm::vec3 n = m.normals[m.indices[0]];
            // Half-way between the faces' normals (0,0,1) and its fold by 30 degrees.
            EXPECT_NEAR(std::acos(n.z), glm::radians(fold / 2), 1e-4f);
        } else {
            EXPECT_EQ(m.positions.size(), 6u);
            EXPECT_EQ(m.normals[m.indices[0]], glm::vec3(0, 0, 1)); // flat: its face's
        }
    }
}

TEST(MeshImport, ZeroAreaTrianglesAreDropped) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    m.indices = {0, 1, 2, 0, 1, 3}; // the second is a line
    EXPECT_EQ(computeCreaseNormals(m), 1u);
    EXPECT_EQ(m.triangleCount(), 1u);
    expectUnitNormals(m);
}

std::string problemOf(const std::function<void()>& read) {
    try {
        read();
    } catch (const MeshFileError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(MeshImport, BadInputNamesTheFileAndLineOrElement) {
    EXPECT_EQ(problemOf([] { (void)readObj("v 0 0 0\nf 1 2 3\n", "a.obj"); }),
              "a.obj:2: face vertex index 2 past the 1 read so far");
    EXPECT_EQ(problemOf([] { (void)readObj("v 0 0\n", "a.obj"); }), "a.obj:1: 'v' needs 3 numbers");
    EXPECT_EQ(problemOf([] { (void)readObj("v 0 0 x\n", "a.obj"); }),
              "a.obj:1: vertex: 'x' is not a number");
    EXPECT_EQ(problemOf([] { (void)readObj("v 0 0 0\nv 1 0 0\nf 1 0 2\n", "a.obj"); }),
              "a.obj:3: face vertex index 0 (OBJ counts from 1)");
    EXPECT_EQ(problemOf([] { (void)readObj("v 0 0 0\nv 1 0 0\nf 1 2\n", "a.obj"); }),
              "a.obj:3: a face of 2 vertices (needs 3)");
    EXPECT_EQ(problemOf([] { (void)readObj("v 0 0 1e300\n", "a.obj"); }),
              "a.obj:1: vertex z must be a finite number in [-1e+15, 1e+15], got 1e+300");
    EXPECT_EQ(problemOf([] { (void)readStl(bytesOf(std::string(90, 'x')), "b.stl"); }),
              "b.stl: binary STL of 2021161080 triangles should be 101058054084 bytes, the file "
              "has 90");
    EXPECT_EQ(problemOf([] { (void)readStl(bytesOf("solid\nvertex 0 0 0\n"), "c.stl"); }),
              "c.stl:2: 'vertex' outside an 'outer loop'");
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n";
    EXPECT_EQ(problemOf([&] { (void)readPly(bytesOf(header + "0 0 0\n1 0 0\n"), "d.ply"); }),
              "d.ply: the file ends in vertex 2");
    EXPECT_EQ(problemOf([&] {
                  (void)readPly(bytesOf(header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n"), "d.ply");
              }),
              "d.ply: a face's vertex index 5 past the 3 vertices");
    EXPECT_EQ(problemOf([] {
                  (void)readPly(bytesOf("ply\nformat binary_big_endian 1.0\nend_header\n"),
                                "e.ply");
              }),
              "e.ply:2: PLY format 'binary_big_endian' is not read (ascii or "
              "binary_little_endian)");
}

} // namespace
} // namespace fl::bench
