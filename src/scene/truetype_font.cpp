#include "asos/scene/truetype_font.hpp"

#include <algorithm>
#include <cstring>
#include <string>

namespace asos {

namespace {

constexpr unsigned kOnCurve = 0x01, kXShort = 0x02, kYShort = 0x04, kRepeat = 0x08, kXSame = 0x10,
                   kYSame = 0x20;
constexpr unsigned kArgsAreWords = 0x0001, kArgsAreXY = 0x0002, kHaveScale = 0x0008,
                   kMoreComponents = 0x0020, kHaveXYScale = 0x0040, kHaveTwoByTwo = 0x0080,
                   kUseMyMetrics = 0x0200;
constexpr unsigned kKernHorizontal = 0x01, kKernMinimum = 0x02, kKernCrossStream = 0x04,
                   kKernOverride = 0x08;

// Big-endian reads that throw past the end.
struct Bytes {
    const std::vector<unsigned char>& b;
    void need(std::size_t at, std::size_t n) const {
        if (at > b.size() || n > b.size() - at) throw TrueTypeError("the TrueType font file is cut short");
    }
    unsigned u8(std::size_t at) const {
        need(at, 1);
        return b[at];
    }
    unsigned u16(std::size_t at) const {
        need(at, 2);
        return (unsigned(b[at]) << 8) | b[at + 1];
    }
    int s16(std::size_t at) const { return int(std::int16_t(std::uint16_t(u16(at)))); }
    std::uint32_t u32(std::size_t at) const {
        need(at, 4);
        return (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) |
               (std::uint32_t(b[at + 2]) << 8) | std::uint32_t(b[at + 3]);
    }
};

// POV-Ray keeps a glyph's box in 16-bit integers, also when it widens it by
// a composite's points (em units, truncated).
int asShort(double v) { return int(std::int16_t(static_cast<long>(v))); }

}  // namespace

TrueTypeFont TrueTypeFont::read(std::vector<unsigned char> bytes) {
    TrueTypeFont f;
    f.bytes_ = std::move(bytes);
    const Bytes r{f.bytes_};
    std::size_t base = 0;
    r.need(0, 4);
    if (std::memcmp(f.bytes_.data(), "ttcf", 4) == 0) base = r.u32(8);  // a collection: its first font
    const unsigned numTables = r.u16(base + 4);
    std::size_t head = 0, loca = 0, maxp = 0, kern = 0, hhea = 0, hmtx = 0;
    for (unsigned i = 0; i < numTables && i < 40; ++i) {
        const std::size_t e = base + 12 + 16 * std::size_t(i);
        r.need(e, 16);
        const std::string tag(reinterpret_cast<const char*>(&f.bytes_[e]), 4);
        const std::size_t off = r.u32(e + 8);
        if (tag == "cmap") f.cmap_ = off;
        else if (tag == "glyf") f.glyf_ = off;
        else if (tag == "head") head = off;
        else if (tag == "loca") loca = off;
        else if (tag == "maxp") maxp = off;
        else if (tag == "kern") kern = off;
        else if (tag == "hhea") hhea = off;
        else if (tag == "hmtx") hmtx = off;
    }
    if (!f.cmap_ || !f.glyf_ || !head || !loca || !maxp || !hhea || !hmtx)
        throw TrueTypeError("not a TrueType font (a table of cmap, glyf, head, loca, maxp, hhea, hmtx is missing)");
    f.unitsPerEm_ = r.u16(head + 18);
    const int indexToLocFormat = r.s16(head + 50);
    if ((indexToLocFormat != 0 && indexToLocFormat != 1) || f.unitsPerEm_ < 16 || f.unitsPerEm_ > 16384)
        throw TrueTypeError("invalid TrueType font data (head table)");
    f.numGlyphs_ = r.u16(maxp + 4);
    f.loca_.resize(std::size_t(f.numGlyphs_) + 1);
    for (std::size_t i = 0; i <= f.numGlyphs_; ++i)
        f.loca_[i] = indexToLocFormat == 0 ? 2 * r.u16(loca + 2 * i) : r.u32(loca + 4 * i);
    const unsigned numberOfHMetrics = r.u16(hhea + 34);
    f.hmtx_.resize(f.numGlyphs_);
    unsigned lastAdvance = 0;
    for (std::size_t i = 0; i < f.numGlyphs_; ++i) {
        if (i < numberOfHMetrics) {
            lastAdvance = r.u16(hmtx + 4 * i);
            f.hmtx_[i] = {lastAdvance, r.s16(hmtx + 4 * i + 2)};
        } else {
            f.hmtx_[i] = {lastAdvance, r.s16(hmtx + 4 * numberOfHMetrics + 2 * (i - numberOfHMetrics))};
        }
    }
    if (kern) {
        const unsigned nTables = r.u16(kern + 2);
        std::size_t at = kern + 4;
        for (unsigned t = 0; t < nTables; ++t) {
            const unsigned length = r.u16(at + 2), coverage = r.u16(at + 4);
            KernTable table;
            table.coverage = coverage;
            if ((coverage >> 8) == 0) {
                const unsigned nPairs = r.u16(at + 6);
                for (unsigned k = 0; k < nPairs; ++k) {
                    const std::size_t p = at + 14 + 6 * std::size_t(k);
                    table.pairs.push_back({r.u16(p), r.u16(p + 2), r.s16(p + 4)});
                }
            }
            f.kern_.push_back(std::move(table));
            at += length;
        }
    }
    return f;
}

unsigned TrueTypeFont::mapFormat4(std::size_t table, unsigned code) const {
    const Bytes r{bytes_};
    const unsigned segCount = r.u16(table + 6) >> 1;
    const std::size_t ends = table + 14, starts = ends + 2 * segCount + 2, deltas = starts + 2 * segCount,
                      ranges = deltas + 2 * segCount;
    for (int pass = 0; pass < 2; ++pass) {
        unsigned index = 0;
        for (unsigned i = 0; i < segCount; ++i) {
            if (code > r.u16(ends + 2 * i)) continue;
            const unsigned start = r.u16(starts + 2 * i);
            if (code >= start) {
                const unsigned delta = r.u16(deltas + 2 * i), range = r.u16(ranges + 2 * i);
                if (range == 0) {
                    index = (code + delta) & 0xFFFF;
                } else {
                    index = r.u16(ranges + 2 * i + range + 2 * (code - start));
                    if (index != 0) index = (index + delta) & 0xFFFF;
                }
            }
            break;
        }
        if (index != 0 || code >= 0x100) return index;
        code += 0xF000;  // where Microsoft puts the symbols of a symbol font
    }
    return 0;
}

unsigned TrueTypeFont::glyphIndex(unsigned code) const {
    const Bytes r{bytes_};
    const unsigned count = r.u16(cmap_ + 2);
    static constexpr unsigned kPlatforms[4] = {1, 3, 0, 3};
    for (unsigned platform : kPlatforms) {
        for (unsigned i = 0; i < count; ++i) {
            const std::size_t e = cmap_ + 4 + 8 * std::size_t(i);
            if (r.u16(e) != platform) continue;
            const std::size_t table = cmap_ + r.u32(e + 4);
            const unsigned format = r.u16(table);
            if (format == 0) return code < 256 ? r.u8(table + 6 + code) : 0;
            if (format == 4) return mapFormat4(table, code);
            if (format == 6) {
                const unsigned first = r.u16(table + 6), entries = r.u16(table + 8);
                return code >= first && code - first < entries ? r.u16(table + 10 + 2 * (code - first)) : 0;
            }
        }
    }
    return 0;
}

HorizontalMetric TrueTypeFont::metric(unsigned index) const {
    return index < hmtx_.size() ? hmtx_[index] : HorizontalMetric{};
}

void TrueTypeFont::readGlyph(Glyph& g, unsigned index, bool space, int depth) const {
    if (space || index >= numGlyphs_) return;
    if (depth > 8) throw TrueTypeError("a composite glyph nests too deep");
    const Bytes r{bytes_};
    std::size_t at = glyf_ + loca_[index];
    const int numContours = r.s16(at);
    g.xMin = r.s16(at + 2);
    g.yMin = r.s16(at + 4);
    g.xMax = r.s16(at + 6);
    g.yMax = r.s16(at + 8);
    at += 10;
    const double em = double(unitsPerEm_);
    if (numContours > 0) {
        std::vector<unsigned> ends(numContours);
        for (int i = 0; i < numContours; ++i) ends[i] = r.u16(at + 2 * i);
        at += 2 * std::size_t(numContours);
        at += 2 + r.u16(at);  // the instructions
        const unsigned n = ends.back() + 1;
        std::vector<unsigned> flags(n);
        for (unsigned i = 0; i < n; ++i) {
            flags[i] = r.u8(at++);
            if (flags[i] & kRepeat) {
                for (unsigned repeat = r.u8(at++); repeat > 0 && i + 1 < n; --repeat, ++i) flags[i + 1] = flags[i];
            }
        }
        std::vector<int> xs(n), ys(n);
        for (int axis = 0; axis < 2; ++axis) {
            const unsigned shortBit = axis == 0 ? kXShort : kYShort, sameBit = axis == 0 ? kXSame : kYSame;
            int& lo = axis == 0 ? g.xMin : g.yMin;
            int& hi = axis == 0 ? g.xMax : g.yMax;
            std::vector<int>& out = axis == 0 ? xs : ys;
            int coord = 0;
            for (unsigned i = 0; i < n; ++i) {
                if (flags[i] & shortBit) {
                    const int d = int(r.u8(at++));
                    coord += (flags[i] & sameBit) ? d : -d;
                } else if (!(flags[i] & sameBit)) {
                    coord += r.s16(at);
                    at += 2;
                }
                coord = int(std::int16_t(coord));
                hi = std::max(hi, coord);
                lo = std::min(lo, coord);
                out[i] = coord;
            }
        }
        unsigned first = 0;
        for (unsigned end : ends) {
            std::vector<OutlinePoint> contour;
            for (unsigned i = first; i <= end && i < n; ++i)
                contour.push_back({xs[i] / em, ys[i] / em, (flags[i] & kOnCurve) != 0});
            first = end + 1;
            g.contours.push_back(std::move(contour));
        }
    } else if (numContours < 0) {
        unsigned flags = 0;
        do {
            flags = r.u16(at);
            const unsigned sub = r.u16(at + 2);
            at += 4;
            int arg1, arg2;
            if (flags & kArgsAreWords) {
                arg1 = r.s16(at);
                arg2 = r.s16(at + 2);
                at += 4;
            } else {
                // POV-Ray reads the two bytes as unsigned.
                arg1 = int(r.u8(at));
                arg2 = int(r.u8(at + 1));
                at += 2;
            }
            double xx = 1.0, xy = 0.0, yx = 0.0, yy = 1.0;
            if (flags & kHaveScale) {
                xx = yy = r.s16(at) / 16384.0;
                at += 2;
            } else if (flags & kHaveXYScale) {
                xx = r.s16(at) / 16384.0;
                yy = r.s16(at + 2) / 16384.0;
                at += 4;
            } else if (flags & kHaveTwoByTwo) {
                xx = r.s16(at) / 16384.0;
                xy = r.s16(at + 2) / 16384.0;
                yx = r.s16(at + 4) / 16384.0;
                yy = r.s16(at + 6) / 16384.0;
                at += 8;
            }
            if (!(flags & kArgsAreXY)) continue;  // anchored by points: POV-Ray leaves the part out
            if (flags & kUseMyMetrics) g.metrics = sub;
            Glyph part;
            readGlyph(part, sub, false, depth + 1);
            for (auto& contour : part.contours) {
                for (OutlinePoint& p : contour) {
                    const double x = xx * p.x + xy * p.y + arg1 / em, y = yx * p.x + yy * p.y + arg2 / em;
                    p.x = x;
                    p.y = y;
                    if (x < g.xMin) g.xMin = asShort(x);
                    if (x > g.xMax) g.xMax = asShort(x);
                    if (y < g.yMin) g.yMin = asShort(y);
                    if (y > g.yMax) g.yMax = asShort(y);
                }
                g.contours.push_back(std::move(contour));
            }
        } while (flags & kMoreComponents);
    }
}

Glyph TrueTypeFont::glyph(unsigned index, bool space) const {
    Glyph g;
    g.index = index;
    g.metrics = index;
    readGlyph(g, index, space, 0);
    return g;
}

int TrueTypeFont::kerning(unsigned left, unsigned right) const {
    int value = 0, minimum = -int(unitsPerEm_);
    // POV-Ray reads the coverage of the first table for every table.
    const unsigned coverage = kern_.empty() ? 0 : kern_.front().coverage;
    for (const KernTable& table : kern_) {
        if (!(coverage & kKernHorizontal)) continue;
        for (const KernPair& p : table.pairs) {
            if (p.left == left && p.right == right) {
                if (coverage & kKernMinimum) {
                    if (!(coverage & kKernCrossStream)) minimum = p.value;
                } else if (!(coverage & kKernCrossStream)) {
                    value = (coverage & kKernOverride) ? p.value : value + p.value;
                }
                break;
            }
            if (p.left > left) break;
        }
    }
    return std::max(value, minimum);
}

std::vector<OutlineSegment> contourSegments(const std::vector<OutlinePoint>& c) {
    std::vector<OutlineSegment> out;
    const std::size_t n = c.size();
    if (n < 2) return out;
    // Start at an on-curve point (or the midpoint of two off-curve ones).
    std::size_t s = 0;
    while (s < n && !c[s].onCurve) ++s;
    double sx, sy;
    if (s < n) {
        sx = c[s].x;
        sy = c[s].y;
    } else {
        s = 0;
        sx = 0.5 * (c[0].x + c[1].x);
        sy = 0.5 * (c[0].y + c[1].y);
    }
    double px = sx, py = sy;
    bool haveControl = false;
    double qx = 0.0, qy = 0.0;
    const bool midStart = !c[s].onCurve;
    for (std::size_t k = 1; k <= n; ++k) {
        const OutlinePoint& p = c[(s + k) % n];
        const bool closing = k == n;
        if (closing && midStart) {
            // p is c[s] again, off-curve; end at the start midpoint.
            if (haveControl) {
                const double mx = 0.5 * (qx + p.x), my = 0.5 * (qy + p.y);
                out.push_back({px, py, qx, qy, mx, my});
                px = mx;
                py = my;
            }
            out.push_back({px, py, p.x, p.y, sx, sy});
            break;
        }
        if (p.onCurve) {
            if (haveControl) out.push_back({px, py, qx, qy, p.x, p.y});
            else out.push_back({px, py, 0.5 * (px + p.x), 0.5 * (py + p.y), p.x, p.y});
            px = p.x;
            py = p.y;
            haveControl = false;
        } else if (haveControl) {
            const double mx = 0.5 * (qx + p.x), my = 0.5 * (qy + p.y);
            out.push_back({px, py, qx, qy, mx, my});
            px = mx;
            py = my;
            qx = p.x;
            qy = p.y;
        } else {
            qx = p.x;
            qy = p.y;
            haveControl = true;
        }
    }
    // Drop pieces of no length (a contour's repeated points).
    std::erase_if(out, [](const OutlineSegment& g) {
        return g.x0 == g.x2 && g.y0 == g.y2 && g.cx == g.x0 && g.cy == g.y0;
    });
    return out;
}

std::vector<PlacedGlyph> layoutText(const TrueTypeFont& font, std::string_view text, double offsetX,
                                    double offsetY) {
    std::vector<PlacedGlyph> out;
    const double unit = 1.0 / font.unitsPerEm();
    double totalX = 0.0, totalY = 0.0;
    unsigned last = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned code = static_cast<unsigned char>(text[i]);
        const unsigned index = font.glyphIndex(code);
        PlacedGlyph p{font.glyph(index, code == ' ')};
        const HorizontalMetric m = font.metric(p.glyph.metrics);
        if (i == 0) {
            p.x = -p.glyph.xMin * unit;
            p.y = 0.0;
            totalX = (double(m.advanceWidth) - m.leftSideBearing) * unit;
        } else {
            const int kern = font.kerning(last, p.glyph.metrics);
            p.x = totalX + double(m.leftSideBearing - p.glyph.xMin + kern) * unit;
            p.y = totalY;
            totalX += double(int(m.advanceWidth) + kern) * unit;
        }
        totalX += offsetX;
        totalY += offsetY;
        last = index;
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace asos
