#include <renderer/passes/HudPass.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

// stb_easy_font is a header of static functions; not all of them are used here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace fl {

namespace {

constexpr int kLineHeight = 12; // stb_easy_font's row advance, in font units
constexpr int kColumnGap = 8;   // between a tab's two columns, in font units

// stb_easy_font's vertex: position (x, y, z) and an RGBA8 colour; 4 per quad.
struct EasyFontVertex {
    float x, y, z;
    unsigned char rgba[4];
};
static_assert(sizeof(EasyFontVertex) == 16);

void addQuad(std::vector<HudVertex>& out, glm::vec2 a, glm::vec2 b, glm::vec4 color) {
    const HudVertex v00{{a.x, a.y}, color}, v10{{b.x, a.y}, color}, v11{{b.x, b.y}, color},
        v01{{a.x, b.y}, color};
    out.insert(out.end(), {v00, v10, v11, v00, v11, v01});
}

// Only ' '..'~' index stb_easy_font's tables; anything else would read outside them.
std::string printable(const std::string& s) {
    std::string out = s;
    for (char& c : out)
        if (c < 32 || c > 126) c = '?';
    return out;
}

// `line` cut at spaces into pieces at most `limit` font units wide; continuations start with two
// spaces. A word wider than the limit is cut into pieces that fit.
std::vector<std::string> wrapLine(const std::string& line, int limit) {
    std::vector<std::string> out;
    std::string current;
    std::size_t at = 0;
    while (at < line.size()) {
        std::size_t end = line.find(' ', at + 1);
        if (end == std::string::npos) end = line.size();
        std::string word = line.substr(at, end - at); // with its leading space, if any
        // A word wider than the limit (a long path) is cut where it reaches it.
        while (stb_easy_font_width(word.data()) > limit && word.size() > 1) {
            std::size_t fits = 1;
            while (fits < word.size() &&
                   stb_easy_font_width(word.substr(0, fits + 1).data()) <= limit)
                ++fits;
            if (!current.empty()) out.push_back(current);
            out.push_back(word.substr(0, fits));
            current.clear();
            word = word.substr(fits); // shorter each time: fits >= 1
        }
        std::string tried = current + word;
        if (!current.empty() && stb_easy_font_width(tried.data()) > limit) {
            out.push_back(current);
            std::size_t first = word.find_first_not_of(' ');
            current = "  " + (first == std::string::npos ? std::string() : word.substr(first));
        } else {
            current = std::move(tried);
        }
        at = end;
    }
    out.push_back(current);
    return out;
}

} // namespace

HudGeometry layoutHud(std::span<const std::string> given, const HudStyle& style) {
    HudGeometry g;
    if (given.empty()) return g;
    const int scale = std::max(style.scale, 1);
    std::vector<std::string> lines;
    const int limit = (style.maxWidth - 2 * style.margin - 2 * style.padding) / scale;
    for (const std::string& line : given) {
        std::string shown = printable(line.substr(0, line.find('\t')));
        if (style.maxWidth <= 0 || line.find('\t') != std::string::npos ||
            stb_easy_font_width(shown.data()) <= limit) {
            lines.push_back(line);
            continue;
        }
        for (std::string& piece : wrapLine(line, std::max(limit, 1)))
            lines.push_back(std::move(piece));
    }
    // Each line is one or two cells: text before a tab, text after it. The font is proportional,
    // so the second column starts after the widest first cell rather than at a space count.
    struct Row {
        std::string left, right;
        bool hasTab = false;
    };
    std::vector<Row> rows;
    rows.reserve(lines.size());
    int leftWidth = 0;
    for (const std::string& line : lines) {
        Row r;
        const std::size_t tab = line.find('\t');
        r.hasTab = tab != std::string::npos;
        r.left = printable(line.substr(0, tab));
        if (r.hasTab) {
            r.right = printable(line.substr(tab + 1));
            leftWidth = std::max(leftWidth, stb_easy_font_width(r.left.data()));
        }
        rows.push_back(std::move(r));
    }
    const int column = leftWidth + kColumnGap;
    int widest = 0;
    for (Row& r : rows)
        widest = std::max(widest, r.hasTab ? column + stb_easy_font_width(r.right.data())
                                           : stb_easy_font_width(r.left.data()));
    const int count = static_cast<int>(rows.size());
    g.boxMin = glm::ivec2(style.margin);
    g.boxMax = g.boxMin + glm::ivec2(widest * scale, count * kLineHeight * scale) +
               2 * glm::ivec2(style.padding);
    addQuad(g.triangles, g.boxMin, g.boxMax, style.background);

    std::vector<EasyFontVertex> buffer;
    auto print = [&](std::string& text, glm::vec2 origin, glm::vec4 color) {
        // Generous: the densest glyph has well under 32 segment quads of 4 vertices.
        buffer.assign(text.size() * 128 + 4, EasyFontVertex{});
        const int quads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, buffer.data(),
                                              static_cast<int>(buffer.size() * sizeof(buffer[0])));
        for (int q = 0; q < quads; ++q) {
            const EasyFontVertex& a = buffer[static_cast<std::size_t>(q) * 4];
            const EasyFontVertex& b = buffer[static_cast<std::size_t>(q) * 4 + 2];
            addQuad(g.triangles, origin + glm::vec2(a.x, a.y) * float(scale),
                    origin + glm::vec2(b.x, b.y) * float(scale), color);
        }
    };
    for (int i = 0; i < count; ++i) {
        Row& r = rows[static_cast<std::size_t>(i)];
        const glm::vec4 color = !r.left.empty() && r.left[0] == '!' ? style.warning : style.text;
        const glm::vec2 origin(g.boxMin.x + style.padding,
                               g.boxMin.y + style.padding + i * kLineHeight * scale);
        print(r.left, origin, color);
        if (r.hasTab) print(r.right, origin + glm::vec2(column * scale, 0), color);
    }
    return g;
}

void rasterizeHud(const HudGeometry& geometry, ByteImage& image) {
    for (std::size_t q = 0; q + 5 < geometry.triangles.size(); q += 6) {
        const glm::vec2 a = geometry.triangles[q].pos, b = geometry.triangles[q + 2].pos;
        const glm::vec4 c = geometry.triangles[q].color;
        // Pixel (x, y) is covered when its centre (x + 0.5, y + 0.5) lies inside [a, b).
        const int x0 = std::max(0, static_cast<int>(std::ceil(std::min(a.x, b.x) - 0.5f)));
        const int x1 =
            std::min(image.width, static_cast<int>(std::ceil(std::max(a.x, b.x) - 0.5f)));
        const int y0 = std::max(0, static_cast<int>(std::ceil(std::min(a.y, b.y) - 0.5f)));
        const int y1 =
            std::min(image.height, static_cast<int>(std::ceil(std::max(a.y, b.y) - 0.5f)));
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                std::uint8_t* p =
                    &image.data[(static_cast<std::size_t>(y) * image.width + x) * image.channels];
                for (int ch = 0; ch < std::min(image.channels, 3); ++ch) {
                    const float dst = static_cast<float>(p[ch]) / 255.0f;
                    const float v = c[ch] * c.a + dst * (1.0f - c.a);
                    p[ch] =
                        static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
                }
                if (image.channels == 4) {
                    const float dst = static_cast<float>(p[3]) / 255.0f;
                    const float v = c.a * c.a + dst * (1.0f - c.a);
                    p[3] =
                        static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
                }
            }
    }
}

namespace {
constexpr gl::Uniform<glm::vec2> kHudViewport{"uViewport"}; // hud.vert.glsl: pixels to NDC
} // namespace

HudPass::HudPass(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(
          shaders, {{GL_VERTEX_SHADER, "hud.vert.glsl"}, {GL_FRAGMENT_SHADER, "hud.frag.glsl"}})),
      vao_(gl::VertexArray::create()) {
    glEnableVertexArrayAttrib(vao_.id(), 0);
    glVertexArrayAttribFormat(vao_.id(), 0, 2, GL_FLOAT, GL_FALSE, offsetof(HudVertex, pos));
    glVertexArrayAttribBinding(vao_.id(), 0, 0);
    glEnableVertexArrayAttrib(vao_.id(), 1);
    glVertexArrayAttribFormat(vao_.id(), 1, 4, GL_FLOAT, GL_FALSE, offsetof(HudVertex, color));
    glVertexArrayAttribBinding(vao_.id(), 1, 0);
    program_.bindUniforms({&kHudViewport});
}

void HudPass::draw(std::span<const std::string> lines, int width, int height, const HudStyle& given,
                   GLuint framebuffer) {
    if (width <= 0 || height <= 0) return;
    HudStyle style = given;
    if (style.maxWidth == 0) style.maxWidth = width; // the HUD fits the window
    const HudGeometry g = layoutHud(lines, style);
    if (g.triangles.empty()) return;
    const gl::Buffer vertices(static_cast<GLsizeiptr>(g.triangles.size() * sizeof(HudVertex)),
                              g.triangles.data());
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices.id(), 0, sizeof(HudVertex));

    // Save what is changed below, so the caller's state survives the HUD.
    GLint viewport[4], drawFbo = 0, program = 0, vao = 0, src[2], dst[2], eq[2];
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
    glGetIntegerv(GL_BLEND_SRC_RGB, &src[0]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &src[1]);
    glGetIntegerv(GL_BLEND_DST_RGB, &dst[0]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &dst[1]);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &eq[0]);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &eq[1]);
    const GLboolean blend = glIsEnabled(GL_BLEND), depth = glIsEnabled(GL_DEPTH_TEST),
                    cull = glIsEnabled(GL_CULL_FACE), scissor = glIsEnabled(GL_SCISSOR_TEST);

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    program_.set(kHudViewport, glm::vec2(width, height));
    glUseProgram(program_.id());
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(g.triangles.size()));

    auto restore = [](GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); };
    restore(GL_BLEND, blend);
    restore(GL_DEPTH_TEST, depth);
    restore(GL_CULL_FACE, cull);
    restore(GL_SCISSOR_TEST, scissor);
    glBlendEquationSeparate(static_cast<GLenum>(eq[0]), static_cast<GLenum>(eq[1]));
    glBlendFuncSeparate(static_cast<GLenum>(src[0]), static_cast<GLenum>(dst[0]),
                        static_cast<GLenum>(src[1]), static_cast<GLenum>(dst[1]));
    glBindVertexArray(static_cast<GLuint>(vao));
    glUseProgram(static_cast<GLuint>(program));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFbo));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glVertexArrayVertexBuffer(vao_.id(), 0, 0, 0, sizeof(HudVertex)); // buffer dies here
}

} // namespace fl
