// text { ttf "font.ttf" "string" thickness, <offset> }: POV-Ray 3.7's text
// object, a union of one extruded outline per glyph (its
// core/shape/truetype.cpp). The font is found as an include file is.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "asos/diag/format_number.hpp"
#include "asos/scene/truetype_font.hpp"
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

// A glyph's outline in the prism's plane: (x, y) of the glyph is (x, -y)
// there, and the prism's frame turned +90 degrees about x carries it back
// (y up, the thickness along +z).
std::shared_ptr<const std::vector<OutlineContour>> glyphOutline(const Glyph& glyph) {
    auto out = std::make_shared<std::vector<OutlineContour>>();
    for (const auto& contour : glyph.contours) {
        OutlineContour c;
        for (const OutlineSegment& s : contourSegments(contour)) {
            OutlinePiece p;
            const bool straight = s.cx == 0.5 * (s.x0 + s.x2) && s.cy == 0.5 * (s.y0 + s.y2);
            if (straight) {
                p.degree = 1;
                p.p = {s.x0, -s.y0, s.x2, -s.y2, 0, 0, 0, 0};
            } else {
                p.degree = 2;
                p.p = {s.x0, -s.y0, s.cx, -s.cy, s.x2, -s.y2, 0, 0};
            }
            c.pieces.push_back(p);
        }
        if (!c.pieces.empty()) out->push_back(std::move(c));
    }
    return out;
}

}  // namespace

void Interpreter::evalText(const Node& block, ObjectTree& t) {
    const auto args = block.children();
    const std::string name = evalString(args[0]);
    const std::string text = evalString(args[1]);
    const double thickness = evalFloat(args[2]);
    const Vec3 offset = evalVector(args[3]);
    if (!(std::isfinite(thickness) && thickness > 0.0))
        fail(args[2], "the thickness of a text must be positive and finite, not " + formatNumber(thickness));
    if (!(std::isfinite(offset.x) && std::isfinite(offset.y) && std::isfinite(offset.z)))
        fail(args[3], "the offset of a text must be finite");
    for (const char c : text)
        if (static_cast<unsigned char>(c) >= 0x80)
            fail(args[1], "a character beyond ASCII in a text (POV-Ray's charset utf8) is not supported by asos");

    // Beside the current file, beside the scene, in each -L folder, then in
    // POV-Ray's library folders, as an include file.
    const std::filesystem::path asked(name);
    const std::vector<std::filesystem::path> folders =
        asked.is_absolute() ? std::vector<std::filesystem::path>{std::filesystem::path()} : searchFolders();
    std::filesystem::path found;
    std::error_code ec;
    // As POV-Ray, a name without an extension is tried with ".ttf" too.
    std::vector<std::filesystem::path> names{asked};
    if (!asked.has_extension()) names.push_back(std::filesystem::path(name + ".ttf"));
    for (const auto& dir : folders) {
        for (const auto& n : names) {
            const std::filesystem::path candidate = dir.empty() ? n : dir / n;
            if (std::filesystem::is_regular_file(candidate, ec)) {
                found = std::filesystem::weakly_canonical(candidate, ec);
                if (ec) found = candidate;
                break;
            }
        }
        if (!found.empty()) break;
    }
    if (found.empty()) {
        std::string where;
        for (const auto& dir : folders)
            if (!dir.empty()) where += (where.empty() ? "" : ", ") + dir.string();
        fail(args[0], "cannot find the font file '" + name + "'" + (where.empty() ? "" : " (looked in " + where + ")"));
    }
    std::shared_ptr<const TrueTypeFont>& font = fonts_[found.string()];
    if (!font) {
        std::ifstream in(found, std::ios::binary);
        if (!in) fail(args[0], "cannot read the font file '" + found.string() + "'");
        std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        try {
            font = std::make_shared<const TrueTypeFont>(TrueTypeFont::read(std::move(bytes)));
        } catch (const TrueTypeError& e) {
            fail(args[0], "cannot read the font file '" + found.string() + "': " + e.what());
        }
    }

    t.kind = ObjectTree::Kind::Union;
    t.op = CsgTree::Op::Union;
    t.leaves = 0;
    t.nodes = 1;
    const Transform upright = Transform::rotateDegrees(Vec3(90.0, 0.0, 0.0));
    for (const PlacedGlyph& p : layoutText(*font, text, offset.x, offset.y)) {
        auto outline = glyphOutline(p.glyph);
        if (outline->empty()) continue;  // a space: its advance only
        ObjectTree glyph;
        glyph.loc = t.loc;
        glyph.shape = ExtrusionShape{std::move(outline), 0.0, thickness, "text"};
        glyph.worldFromObject = Transform::translate(Vec3(p.x, p.y, 0.0)) * upright;
        t.children.push_back(std::move(glyph));
        ++t.leaves;
        ++t.nodes;
    }
    checkObjects(block, t.leaves, "this text");
}

}  // namespace asos::lang
