// Point and mesh files: every finite double survives a write/read cycle bit for bit, malformed
// input is rejected with the exact file and line, and writers never leave half-written files.

#include <geometry/MeshIO.h>
#include <geometry/MeshSvg.h>
#include <geometry/PointIO.h>

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace fl::geom {
namespace {

namespace fs = std::filesystem;

fs::path fixture(const std::string& name) {
    return test::dataDir() / "data" / "points" / name;
}

std::size_t countOf(const std::string& text, const std::string& needle) {
    std::size_t n = 0;
    for (std::size_t pos = text.find(needle); pos != std::string::npos;
         pos = text.find(needle, pos + needle.size()))
        ++n;
    return n;
}

// Files in `dir` whose names start with '.', i.e. temporaries a failed write left behind.
std::vector<std::string> hiddenFiles(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().starts_with(".")) out.push_back(e.path().string());
    return out;
}

// A fresh, empty output folder per test.
fs::path freshDir(const std::string& name) {
    const fs::path dir = test::outputDir("point_io") / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Values at the edges of the double range, where text conversions usually go wrong.
std::vector<glm::dvec2> awkwardPoints() {
    constexpr double kMax = std::numeric_limits<double>::max();
    constexpr double kMinNormal = std::numeric_limits<double>::min();
    constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
    std::vector<glm::dvec2> p = {
        {1e-300, 1e300},
        {-1e-300, -1e300},
        {kMax, -kMax},
        {kMinNormal, kDenormMin},
        {-kDenormMin, 2.2250738585072009e-308},
        {0.0, -0.0},
        {0.1, 1.0 / 3.0},
        {3.141592653589793, -2.718281828459045},
        {1e22, 9007199254740993.0},
        {5e-324, 123456789.0},
        {0.1, 0.1}, // a duplicate stays a duplicate
    };
    // Random bit patterns cover every exponent.
    std::mt19937_64 rng(12345);
    while (p.size() < 500) {
        const double x = std::bit_cast<double>(rng()), y = std::bit_cast<double>(rng());
        if (std::isfinite(x) && std::isfinite(y)) p.emplace_back(x, y);
    }
    return p;
}

void expectBitIdentical(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        for (int k = 0; k < 2; ++k) {
            EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i][k]), std::bit_cast<std::uint64_t>(b[i][k]))
                << "point " << i << " axis " << k << ": " << a[i][k] << " became " << b[i][k];
        }
    }
}

TEST(PointIO, EveryFormatRoundTripsBitForBit) {
    const fs::path dir = freshDir("round_trip");
    const std::vector<glm::dvec2> points = awkwardPoints();
    for (const char* name : {"p.node", "p.txt", "p.xy", "p.bin", "p.f64"}) {
        SCOPED_TRACE(name);
        writePoints(dir / name, points);
        expectBitIdentical(readPoints(dir / name), points);
    }
    const NodeFile node = readNodeFile(dir / "p.node");
    EXPECT_EQ(node.indexBase, 0);
    EXPECT_EQ(test::fileContents(dir / "p.bin").size(), 16 * points.size());
    EXPECT_TRUE(hiddenFiles(dir).empty());
}

TEST(PointIO, EmptyPointSetsRoundTrip) {
    const fs::path dir = freshDir("empty");
    for (const char* name : {"e.node", "e.txt", "e.bin"}) {
        writePoints(dir / name, {});
        EXPECT_TRUE(readPoints(dir / name).empty()) << name;
    }
    EXPECT_EQ(test::fileContents(dir / "e.node"), "0 2 0 0\n");
}

TEST(PointIO, FormatOverrideBeatsTheExtension) {
    const fs::path dir = freshDir("override");
    const std::vector<glm::dvec2> points = {{1, 2}, {3, 4}};
    writePoints(dir / "points.dat", points, PointFormat::Binary);
    expectBitIdentical(readPoints(dir / "points.dat", PointFormat::Binary), points);
    EXPECT_THROW(readPoints(dir / "points.dat"), PointFileError);
    EXPECT_EQ(pointFormatFromExtension("A.NODE"), PointFormat::Node);
    EXPECT_EQ(pointFormatFromExtension("a.xy"), PointFormat::Text);
    EXPECT_EQ(pointFormatFromExtension("a.f64"), PointFormat::Binary);
}

TEST(PointIO, ReadsValidFixtures) {
    const NodeFile one = readNodeFile(fixture("valid_1based_attributes_markers.node"));
    EXPECT_EQ(one.indexBase, 1);
    EXPECT_EQ(one.attributeCount, 1u);
    EXPECT_TRUE(one.hasBoundaryMarkers);
    expectBitIdentical(one.points, {{0, 0}, {1, 0}, {1, 1}, {0, 1e-300}});

    const NodeFile zero = readNodeFile(fixture("valid_0based_header_only_count.node"));
    EXPECT_EQ(zero.indexBase, 0);
    expectBitIdentical(zero.points, {{-1.5, 2}, {3, -0.0}, {1e300, -1e300}});

    expectBitIdentical(readPoints(fixture("valid_commas_and_comments.txt")),
                       {{0.5, 1.5}, {-2, 3}, {4, 5}, {1e-300, -1e300}});
    expectBitIdentical(readPoints(fixture("valid_crlf.xy")), {{1, 2}, {3, 4}});
    for (const char* empty : {"empty.node", "empty.txt", "comments_only.txt"})
        EXPECT_TRUE(readPoints(fixture(empty)).empty()) << empty;
}

struct BadFile {
    const char* file;
    std::size_t line;
    const char* problem; // the whole message after "FILE:LINE: "
};

TEST(PointIO, MalformedFixturesNameFileAndLine) {
    const BadFile cases[] = {
        {"nan_on_line_3.node", 3, "x is NaN"},
        {"inf_on_line_4.txt", 4, "y is infinite"},
        {"truncated_header_says_5.node", 4,
         "file ends after 3 of the 5 vertices the header announced"},
        {"dimension_3_on_line_2.node", 2, "dimension is 3; only 2D points are read"},
        {"non_consecutive_index_on_line_4.node", 4,
         "vertex index 3 where 2 was expected (indices must be consecutive)"},
        {"first_index_2_on_line_2.node", 2, "first vertex index is 2; expected 0 or 1"},
        {"too_many_values_on_line_3.node", 3, "expected 3 values (index x y), found 4"},
        {"too_few_values_on_line_5.node", 5,
         "expected 4 values (index x y + 1 attribute), found 3"},
        {"bad_marker_count_on_line_1.node", 1, "boundary marker count is 2; expected 0 or 1"},
        {"extra_vertex_on_line_4.node", 4,
         "unexpected values after the 2 vertices the header announced"},
        {"not_a_number_on_line_2.txt", 2, "y 'x2' is not a number"},
        {"too_few_values_on_line_3.txt", 3, "expected 2 values (x y), found 1"},
        {"too_many_values_on_line_1.xy", 1, "expected 2 values (x y), found 3"},
        {"overflow_on_line_5.txt", 5, "x '1e999' overflows double (magnitude above 1.8e308)"},
        {"underflow_on_line_2.txt", 2, "x '1e-999' underflows double (nonzero but below 4.9e-324)"},
    };
    for (const BadFile& c : cases) {
        const fs::path path = fixture(c.file);
        try {
            readPoints(path);
            ADD_FAILURE() << c.file << ": no error";
        } catch (const PointFileError& e) {
            EXPECT_EQ(std::string(e.what()),
                      path.string() + ":" + std::to_string(c.line) + ": " + c.problem);
            EXPECT_EQ(e.line(), c.line) << c.file;
            EXPECT_EQ(e.file(), path.string());
        }
    }
}

// The smaller cases, parsed from memory: the message after "t:LINE: ".
TEST(PointIO, MalformedTextNamesTheLine) {
    const struct {
        bool node;
        const char* text;
        const char* message;
    } cases[] = {
        {false, "1,,2\n", "t:1: empty value before ','"},
        {false, "1 2\n, 1 2\n", "t:2: empty value before ','"},
        {false, "\n\n1,\n", "t:3: missing value after ','"},
        {false, "1e 2\n", "t:1: x '1e' is not a number"},
        {false, "0x10 2\n", "t:1: x '0x10' is not a number"},
        {false, "1 2\n3 NaN\n", "t:2: y is NaN"},
        {false, "1 2\n3 infinity\n", "t:2: y is infinite"},
        {false, "1 -1e400\n", "t:1: y '-1e400' overflows double (magnitude above 1.8e308)"},
        {false, "1 1000000000000000000000e-400\n",
         "t:1: y '1000000000000000000000e-400' underflows double (nonzero but below 4.9e-324)"},
        // Exponents whose sum with the digit count overflowed long long (found by fuzz_points).
        {false, "3 4e000000009223372036854775807\n",
         "t:1: y '4e000000009223372036854775807' overflows double (magnitude above 1.8e308)"},
        {false, "3 4e-9223372036854775807\n",
         "t:1: y '4e-9223372036854775807' underflows double (nonzero but below 4.9e-324)"},
        {false, "1 \x01\x02\n", "t:1: y '?\?' is not a number"},
        {true, "3 2 0 0 9\n",
         "t:1: header has 5 values; expected "
         "'#vertices [dimension [#attributes [#markers]]]'"},
        {true, "-3 2\n", "t:1: vertex count '-3' is not a non-negative integer"},
        {true, "1 2 x\n", "t:1: attribute count 'x' is not a non-negative integer"},
        {true, "# c\n2 2 1 1\n1 0 0 5 1\n2 0 0 five 1\n",
         "t:4: attribute 1 'five' is not a number"},
        {true, "1 2 0 1\n1 0 0 1.5\n", "t:2: boundary marker '1.5' is not an integer"},
        {true, "1\n1.0 0 0\n", "t:2: vertex index '1.0' is not an integer"},
        {true, "2\n1 0 0\n1 0 0\n",
         "t:3: vertex index 1 where 2 was expected (indices must be "
         "consecutive)"},
        {true, "2\n\n# only comments follow\n\n",
         "t:4: file ends after 0 of the 2 vertices the "
         "header announced"},
        {true, "1 2 0 1\n1 0 0\n", "t:2: expected 4 values (index x y + marker), found 3"},
        {true, "1,2\n", "t:1: vertex count '1,2' is not a non-negative integer"},
    };
    for (const auto& c : cases) {
        try {
            if (c.node)
                parseNode(c.text, "t");
            else
                parseTextPoints(c.text, "t");
            ADD_FAILURE() << c.text << ": no error";
        } catch (const PointFileError& e) {
            EXPECT_EQ(std::string(e.what()), c.message);
        }
    }
}

TEST(PointIO, LenientWhereOtherProgramsAre) {
    // A leading '+', tabs, a byte order mark and numbers like ".5" and "5." are common in the wild.
    expectBitIdentical(parseTextPoints("\xEF\xBB\xBF+1\t-.5\n5. +2e3\n", "t"),
                       {{1, -0.5}, {5, 2000}});
    EXPECT_EQ(parseNode("2 2\n0 1 2\n1 3 4\n", "t").points.size(), 2u);
}

TEST(PointIO, BinaryErrorsNameTheByteOffset) {
    const fs::path dir = freshDir("binary");
    const std::string bytes(40, '\0');
    std::ofstream(dir / "bad_size_40.bin", std::ios::binary) << bytes;
    try {
        readPoints(dir / "bad_size_40.bin");
        ADD_FAILURE() << "no error";
    } catch (const PointFileError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "bad_size_40.bin").string() +
                                             ": byte 32: file size 40 is not a multiple of 16 "
                                             "(float64 x, y pairs): 8 bytes left over");
        EXPECT_EQ(e.byteOffset(), 32);
    }
    // The y of point 1 is NaN: bytes 24..31.
    const double values[4] = {0, 1, 2, std::numeric_limits<double>::quiet_NaN()};
    std::string raw(sizeof values, '\0');
    std::memcpy(raw.data(), values, sizeof values); // the test machines are little-endian
    try {
        parseBinaryPoints(std::as_bytes(std::span(raw)), "b");
        ADD_FAILURE() << "no error";
    } catch (const PointFileError& e) {
        EXPECT_EQ(std::string(e.what()), "b: byte 24: y of point 1 is NaN");
    }
}

TEST(PointIO, MissingFileAndUnknownExtension) {
    const fs::path missing = freshDir("missing") / "nope.node";
    try {
        readPoints(missing);
        ADD_FAILURE() << "no error";
    } catch (const PointFileError& e) {
        EXPECT_EQ(std::string(e.what()), missing.string() + ": does not exist");
    }
    EXPECT_THROW(readPoints(fixture("nan_on_line_3.node").replace_extension(".csv")),
                 PointFileError);
}

// --- Writers: failures --------------------------------------------------------------------------

TEST(PointIO, WriterFailuresThrowAndLeaveNoTemporary) {
    const fs::path dir = freshDir("unwritable");
    const std::vector<glm::dvec2> points = {{0, 0}, {1, 0}, {0, 1}};

    // The target is a directory: the temporary is written, the rename fails and is cleaned up.
    fs::create_directories(dir / "taken.node" / "child");
    try {
        writeNodeFile(dir / "taken.node", points);
        ADD_FAILURE() << "no error";
    } catch (const PointFileError& e) {
        EXPECT_NE(std::string(e.what()).find((dir / "taken.node").string()), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("Is a directory"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(hiddenFiles(dir).empty());

    // The folder does not exist.
    try {
        writeObjFile(dir / "no_such_folder" / "m.obj", points, {0, 1, 2});
        ADD_FAILURE() << "no error";
    } catch (const PointFileError& e) {
        EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos);
    }

    // Invalid input is refused before the disk is touched.
    EXPECT_THROW(writeEleFile(dir / "m.ele", points, {0, 1, 3}), std::invalid_argument);
    EXPECT_THROW(writeObjFile(dir / "m.obj", points, {0, 1}), std::invalid_argument);
    EXPECT_THROW(writeNodeFile(dir / "n.node", {{0, std::numeric_limits<double>::infinity()}}),
                 std::invalid_argument);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(PointIO, ReadOnlyFolderThrows) {
    const std::vector<glm::dvec2> points = {{0, 0}, {1, 0}, {0, 1}};
    // Permissions mean nothing to root, who may run this test.
    const fs::path locked = freshDir("locked");
    ::chmod(locked.c_str(), 0555);
    if (::access(locked.c_str(), W_OK) == 0) {
        ::chmod(locked.c_str(), 0755);
        GTEST_SKIP() << "running as root: a read-only folder is still writable";
    }
    try {
        writeTextPoints(locked / "p.txt", points);
        ADD_FAILURE() << "no error";
    } catch (const PointFileError& e) {
        EXPECT_NE(std::string(e.what()).find("Permission denied"), std::string::npos);
    }
    ::chmod(locked.c_str(), 0755);
    EXPECT_TRUE(fs::is_empty(locked));
}

TEST(PointIO, RewritingReplacesTheWholeFile) {
    const fs::path dir = freshDir("replace");
    writeTextPoints(dir / "p.txt", awkwardPoints());
    writeTextPoints(dir / "p.txt", {{1, 2}});
    EXPECT_EQ(test::fileContents(dir / "p.txt"), "1 2\n");
    EXPECT_TRUE(hiddenFiles(dir).empty());
}

// --- Triangle writers ---------------------------------------------------------------------------

const std::vector<glm::dvec2> kSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const std::vector<std::uint32_t> kSquareTriangles = {0, 1, 2, 0, 2, 3};

TEST(MeshIO, EleMatchesTheNodeIndexBase) {
    const fs::path dir = freshDir("ele");
    writeNodeFile(dir / "sq.node", kSquare);
    writeEleFile(dir / "sq.ele", kSquare, kSquareTriangles);
    EXPECT_EQ(test::fileContents(dir / "sq.node"), "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n");
    EXPECT_EQ(test::fileContents(dir / "sq.ele"), "2 3 0\n0 0 1 2\n1 0 2 3\n");
    writeEleFile(dir / "sq1.ele", kSquare, kSquareTriangles, 1);
    EXPECT_EQ(test::fileContents(dir / "sq1.ele"), "2 3 0\n1 1 2 3\n2 1 3 4\n");
}

TEST(MeshIO, ObjHasOneFacePerTriangleCountingFromOne) {
    const fs::path dir = freshDir("obj");
    writeObjFile(dir / "sq.obj", kSquare, kSquareTriangles);
    const std::string obj = test::fileContents(dir / "sq.obj");
    EXPECT_EQ(countOf(obj, "\nv "), 4u);
    EXPECT_EQ(countOf(obj, "\nf "), 2u);
    EXPECT_NE(obj.find("\nv 1 1 0\n"), std::string::npos);
    EXPECT_NE(obj.find("\nf 1 2 3\nf 1 3 4\n"), std::string::npos);
}

// --- SVG ----------------------------------------------------------------------------------------

// Tags nest and close (enough XML to catch a broken writer); returns the element names seen.
// (A hand-written scan: std::regex trips GCC 12's -Wmaybe-uninitialized in sanitizer builds.)
std::vector<std::string> checkXmlNesting(const std::string& svg) {
    std::vector<std::string> stack, seen;
    for (std::size_t lt = svg.find('<'); lt != std::string::npos; lt = svg.find('<', lt + 1)) {
        const std::size_t gt = svg.find('>', lt);
        EXPECT_NE(gt, std::string::npos) << "unterminated tag at " << lt;
        if (gt == std::string::npos) break;
        const std::string tag = svg.substr(lt + 1, gt - lt - 1);
        EXPECT_EQ(tag.find('<'), std::string::npos) << "'<' inside a tag at " << lt;
        const bool closing = tag.starts_with("/");
        const std::size_t nameStart = closing ? 1 : 0;
        std::size_t nameEnd = nameStart;
        while (nameEnd < tag.size() && std::isalpha(static_cast<unsigned char>(tag[nameEnd])))
            ++nameEnd;
        const std::string name = tag.substr(nameStart, nameEnd - nameStart);
        EXPECT_FALSE(name.empty()) << "tag without a name at " << lt;
        if (closing) {
            EXPECT_FALSE(stack.empty()) << "unopened </" << name << ">";
            if (stack.empty()) break;
            EXPECT_EQ(stack.back(), name);
            stack.pop_back();
        } else {
            seen.push_back(name);
            if (!tag.ends_with("/")) stack.push_back(name);
        }
    }
    EXPECT_TRUE(stack.empty()) << "unclosed <" << (stack.empty() ? "" : stack.back()) << ">";
    return seen;
}

// The value of `attr="..."` at its first occurrence after `from`.
double attribute(const std::string& svg, const std::string& attr, std::size_t from = 0) {
    const std::size_t at = svg.find(" " + attr + "=\"", from);
    EXPECT_NE(at, std::string::npos) << attr;
    return std::stod(svg.substr(at + attr.size() + 3));
}

TEST(MeshSvg, TriangulationPictureIsWellFormed) {
    const fs::path dir = freshDir("svg");
    writeSvg(dir / "sq.svg", triangulationPicture(kSquare, kSquareTriangles));
    const std::string svg = test::fileContents(dir / "sq.svg");
    EXPECT_TRUE(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
    const std::vector<std::string> names = checkXmlNesting(svg);
    ASSERT_FALSE(names.empty());
    EXPECT_EQ(names.front(), "svg");
    EXPECT_EQ(std::count(names.begin(), names.end(), "circle"), 4);
    EXPECT_EQ(countOf(svg, "M"), 5u); // 5 distinct edges, the shared diagonal once
    // y is flipped: (1, 1) is drawn at SVG y = -1, and the viewBox has a 5% margin around it.
    EXPECT_NE(svg.find("cx=\"1\" cy=\"-1\""), std::string::npos);
    EXPECT_NE(svg.find("viewBox=\"-0.05 -1.05 1.1 1.1\""), std::string::npos) << svg;
    EXPECT_THROW(triangulationPicture(kSquare, {0, 1, 4}), std::invalid_argument);
}

TEST(MeshSvg, CoordinatesKeepFullPrecision) {
    SvgPicture picture;
    picture.addLayer("p", SvgStyle::markers("red")).addPoint({0.1 + 0.2, 1.0 / 3.0});
    const std::string svg = picture.render();
    EXPECT_NE(svg.find("cx=\"0.30000000000000004\" cy=\"-0.3333333333333333\""), std::string::npos)
        << svg;
}

// Markers and lines measured in pixels of the 1024-pixel picture stay visible without swamping.
TEST(MeshSvg, SizesStayVisibleFrom10To100kPoints) {
    for (const int n : {10, 100000}) {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<glm::dvec2> points(n);
        for (glm::dvec2& p : points) p = {u(rng), u(rng)};
        SvgPicture picture;
        picture.addLayer("edges", SvgStyle::lines("black")).addSegment(points[0], points[1]);
        picture.addLayer("sites", SvgStyle::markers("red")).addPoints(points);
        const std::string svg = picture.render();
        const double pxPerUnit = attribute(svg, "width") / 1.1; // unit square plus 2 x 5% margin
        const double linePx = attribute(svg, "stroke-width", svg.find("id=\"edges\"")) * pxPerUnit;
        const double markerPx = attribute(svg, "r", svg.find("<circle")) * pxPerUnit;
        EXPECT_NEAR(attribute(svg, "width"), 1024, 0.5);
        EXPECT_GE(linePx, 0.3) << n;
        EXPECT_LE(linePx, 1.6) << n;
        EXPECT_GE(markerPx, 0.75) << n;
        EXPECT_LE(markerPx, 4.1) << n;
        EXPECT_EQ(countOf(svg, "<circle"), static_cast<std::size_t>(n));
    }
}

TEST(MeshSvg, LabelGridMergesRunsAndSkipsEmptyPixels) {
    SvgLabelGrid grid;
    grid.width = 4;
    grid.height = 2;
    grid.origin = {10, 20};
    grid.pixelSize = {0.5, 0.5};
    grid.labels = {0, 0, 1, 1, -1, 2, 2, 2}; // bottom row first
    SvgPicture picture;
    picture.setBackground("");
    picture.setBounds({10, 20}, {12, 21});
    picture.addLayer("cells", SvgStyle::areas()).addLabelGrid(grid);
    const std::string svg = picture.render();
    checkXmlNesting(svg);
    EXPECT_EQ(countOf(svg, "<rect"), 3u);
    // Label 2's run covers x 10.5..12 in the top row (y 20.5..21, drawn at SVG y = -21).
    EXPECT_NE(svg.find("<rect x=\"10.5\" y=\"-21\" width=\"1.5\" height=\"0.5\" fill=\"" +
                       svgPaletteColour(2) + "\"/>"),
              std::string::npos)
        << svg;
    EXPECT_NE(svgPaletteColour(0), svgPaletteColour(1));
    grid.labels.pop_back();
    EXPECT_THROW(SvgPicture().addLayer("x").addLabelGrid(grid), std::invalid_argument);
}

TEST(MeshSvg, EscapesCallerTextAndRejectsNonFinitePoints) {
    SvgPicture picture;
    SvgLayer& layer = picture.addLayer("a<b & \"c\"", SvgStyle::lines("#000"));
    layer.addPolygon({{0, 0}, {1, 0}, {0, 1}}, "url(#x)\"");
    const std::string svg = picture.render();
    checkXmlNesting(svg);
    EXPECT_NE(svg.find("id=\"a&lt;b &amp; &quot;c&quot;\""), std::string::npos);
    EXPECT_THROW(layer.addPoint({std::nan(""), 0}), std::invalid_argument);
    // A single point still gets a picture with a positive extent.
    SvgPicture one;
    one.addLayer("p", SvgStyle::markers("red")).addPoint({5, 5});
    EXPECT_NO_THROW(checkXmlNesting(one.render()));
}

} // namespace
} // namespace fl::geom
