#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "asos/scene/truetype_font.hpp"

using namespace asos;

namespace {
TrueTypeFont font(const std::string& name) {
    // POV-Ray's own fonts, as installed with it (scripts/setup.sh).
    const std::filesystem::path file = std::filesystem::path("/usr/share/povray-3.7/include") / name;
    REQUIRE(std::filesystem::exists(file));
    std::ifstream in(file, std::ios::binary);
    return TrueTypeFont::read(std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {}));
}

struct Box {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
};

// The union of the placed glyphs' boxes, as POV-Ray bounds text.
Box extent(const TrueTypeFont& f, const std::string& s) {
    Box b;
    const double u = 1.0 / f.unitsPerEm();
    for (const PlacedGlyph& p : layoutText(f, s, 0.0, 0.0)) {
        b.x0 = std::min(b.x0, p.x + p.glyph.xMin * u);
        b.x1 = std::max(b.x1, p.x + p.glyph.xMax * u);
        b.y0 = std::min(b.y0, p.y + p.glyph.yMin * u);
        b.y1 = std::max(b.y1, p.y + p.glyph.yMax * u);
    }
    return b;
}
}  // namespace

TEST_CASE("TrueType layout: POV-Ray's extents of text", "[text][truetype]") {
    // min_extent/max_extent of text { ttf F S 1, 0 } as povray 3.7 prints
    // them (its bounding box is ~1e-5 larger on every side).
    struct Case {
        const char* file;
        const char* text;
        double x1, y0, y1;
    };
    const Case cases[] = {
        {"timrom.ttf", "A", 0.736, 0.0, 0.696},     {"timrom.ttf", "O", 0.682, -0.016, 0.696},
        {"timrom.ttf", "AV", 1.278, -0.016, 0.696}, {"timrom.ttf", "A V", 1.719, -0.016, 0.696},
        {"timrom.ttf", "To", 1.012, -0.010, 0.680}, {"cyrvetic.ttf", "Hi", 0.795, 0.0, 0.728},
        {"crystal.ttf", "Wg", 0.91993, -0.2002, 0.68897}, {"povlogo.ttf", "P", 0.66992, 0.00195, 1.00195},
    };
    for (const Case& c : cases) {
        INFO(c.file << " " << c.text);
        const Box b = extent(font(c.file), c.text);
        CHECK(b.x0 == Approx(0.0).margin(2e-5));
        CHECK(b.x1 == Approx(c.x1).margin(2e-5));
        CHECK(b.y0 == Approx(c.y0).margin(2e-5));
        CHECK(b.y1 == Approx(c.y1).margin(2e-5));
    }
}

TEST_CASE("TrueType glyphs: advance, contours, the missing glyph", "[text][truetype]") {
    const TrueTypeFont f = font("timrom.ttf");
    CHECK(f.unitsPerEm() == 1000);
    const unsigned o = f.glyphIndex('O');
    REQUIRE(o != 0);
    // 'O' is an outer and an inner contour, each closed by its pieces.
    const Glyph g = f.glyph(o, false);
    REQUIRE(g.contours.size() == 2);
    for (const auto& contour : g.contours) {
        const auto pieces = contourSegments(contour);
        REQUIRE(pieces.size() >= 4);
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            const OutlineSegment& a = pieces[i];
            const OutlineSegment& b = pieces[(i + 1) % pieces.size()];
            CHECK(a.x2 == b.x0);
            CHECK(a.y2 == b.y0);
        }
    }
    // A space has no outline but its advance: "A V" is wider than "AV" by
    // the space's advance less the A-V kerning.
    const Glyph space = f.glyph(f.glyphIndex(' '), true);
    CHECK(space.contours.empty());
    CHECK(f.metric(space.metrics).advanceWidth > 0);
    const int kernAV = f.kerning(f.glyphIndex('A'), f.glyphIndex('V'));
    CHECK(kernAV < 0);
    // A character the font lacks maps to glyph 0.
    CHECK(f.glyphIndex(0x4E00) == 0);
}

TEST_CASE("TrueType: a file that is not a font is refused", "[text][truetype]") {
    CHECK_THROWS_AS(TrueTypeFont::read({'n', 'o', 't', ' ', 'a', ' ', 'f', 'o', 'n', 't', 0, 0}), TrueTypeError);
    CHECK_THROWS_AS(TrueTypeFont::read({}), TrueTypeError);
}

TEST_CASE("contourSegments: implied on-curve points between off-curve ones", "[text][truetype]") {
    // A square of four off-curve points: four quadratic pieces through the
    // side midpoints.
    const std::vector<OutlinePoint> c = {{0, 0, false}, {1, 0, false}, {1, 1, false}, {0, 1, false}};
    const auto s = contourSegments(c);
    REQUIRE(s.size() == 4);
    CHECK(s[0].x0 == 0.5);
    CHECK(s[0].y0 == 0.0);
    CHECK(s[0].cx == 1.0);
    CHECK(s[0].cy == 0.0);
    CHECK(s[0].x2 == 1.0);
    CHECK(s[0].y2 == 0.5);
    CHECK(s[3].x2 == 0.5);
    CHECK(s[3].y2 == 0.0);
    // A triangle of on-curve points: three straight pieces.
    const auto t = contourSegments({{0, 0, true}, {1, 0, true}, {0, 1, true}});
    REQUIRE(t.size() == 3);
    CHECK(t[0].cx == 0.5);
    CHECK(t[2].x2 == 0.0);
    CHECK(t[2].y2 == 0.0);
}
