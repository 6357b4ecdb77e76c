#pragma once
// A TrueType font file read as POV-Ray 3.7 reads it for text {} (its
// core/shape/truetype.cpp): the glyph outlines (glyf, loca: quadratic
// B-spline contours, composite glyphs by their x/y offsets and scales), the
// character map (cmap formats 0, 4 and 6, searched in POV-Ray's order for
// its default `charset ascii`), the horizontal metrics (hmtx) and the
// kerning pairs (kern format 0). The layout of a string (layoutText) is
// POV-Ray's: glyphs in em units (font units / unitsPerEm), the first glyph's
// left edge at x = 0, each next one at the previous advance plus its kerning
// and the text's offset.
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace asos {

// A font file that cannot be read as TrueType (what, not where: the caller
// knows the file).
class TrueTypeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct OutlinePoint {
    double x = 0.0, y = 0.0;  // em units
    bool onCurve = true;
};

// A quadratic Bezier piece of a contour, p0 -> p2 with control c; a straight
// piece has c at the middle of p0 and p2.
struct OutlineSegment {
    double x0, y0, cx, cy, x2, y2;
};

struct Glyph {
    unsigned index = 0;    // the glyph's index in the font (0: the missing glyph)
    unsigned metrics = 0;  // the glyph whose hmtx entry it uses
    int xMin = 0, yMin = 0, xMax = 0, yMax = 0;  // font units, as POV-Ray keeps them
    std::vector<std::vector<OutlinePoint>> contours;
};

struct HorizontalMetric {
    unsigned advanceWidth = 0;
    int leftSideBearing = 0;
};

class TrueTypeFont {
public:
    // Throws TrueTypeError for a file that is not TrueType or is cut short.
    static TrueTypeFont read(std::vector<unsigned char> bytes);

    unsigned unitsPerEm() const { return unitsPerEm_; }
    unsigned glyphCount() const { return numGlyphs_; }
    // The glyph index of a character code (0 where the font has none), by
    // POV-Ray's search: the first character map of platform 1, then 3, 0, 3
    // (its order for charset ascii) in format 0, 4 or 6, a code below 0x100
    // not found in a format 4 map looked for again at 0xF000 + code.
    unsigned glyphIndex(unsigned code) const;
    // The outline of a glyph; `space` (the character ' ') has none.
    Glyph glyph(unsigned index, bool space) const;
    HorizontalMetric metric(unsigned index) const;
    // POV-Ray's horizontal kerning between two glyphs, in font units.
    int kerning(unsigned left, unsigned right) const;

private:
    struct KernPair {
        unsigned left, right;
        int value;
    };
    struct KernTable {
        unsigned coverage = 0;
        std::vector<KernPair> pairs;
    };
    void readGlyph(Glyph& g, unsigned index, bool space, int depth) const;
    unsigned mapFormat4(std::size_t table, unsigned code) const;

    std::vector<unsigned char> bytes_;
    std::size_t cmap_ = 0, glyf_ = 0;
    unsigned unitsPerEm_ = 0, numGlyphs_ = 0;
    std::vector<std::uint32_t> loca_;
    std::vector<HorizontalMetric> hmtx_;
    std::vector<KernTable> kern_;
};

// The closed quadratic pieces of a contour (TrueType's implied on-curve
// points between two off-curve ones).
std::vector<OutlineSegment> contourSegments(const std::vector<OutlinePoint>& contour);

struct PlacedGlyph {
    Glyph glyph;
    double x = 0.0, y = 0.0;  // where its outline's origin goes, em units
};

// The glyphs of a string (one byte a character, as charset ascii), placed
// as POV-Ray places them; `offsetX`, `offsetY` are text's offset vector's
// (its z is ignored, as POV-Ray ignores it).
std::vector<PlacedGlyph> layoutText(const TrueTypeFont& font, std::string_view text, double offsetX,
                                    double offsetY);

}  // namespace asos
