// Expressions, with POV-Ray 3.7's rules: a float promotes to every component
// of a vector or colour; vectors of different sizes meet at the larger size
// with zeros; = != <= >= and conditions use POV-Ray's epsilon.
#include <charconv>
#include <cmath>
#include <cstdio>

#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

const char* sizeName(int dim) {
    switch (dim) {
    case 2: return "a 2-component vector";
    case 4: return "a 4-component vector";
    case 5: return "a 5-component vector";
    default: return "a vector";
    }
}

// `a` widened to `dim` components (colour: five).
Num widen(const Num& a, int dim, bool colour) {
    Num r = a;
    if (a.isFloat()) {
        r.v.fill(a.v[0]);
    } else {
        for (int i = a.dim; i < 5; ++i) r.v[i] = 0.0;
    }
    r.dim = static_cast<std::uint8_t>(dim);
    r.colour = colour;
    return r;
}

std::string utf8(std::uint32_t c) {
    std::string s;
    if (c < 0x80) {
        s += static_cast<char>(c);
    } else if (c < 0x800) {
        s += static_cast<char>(0xC0 | (c >> 6));
        s += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        s += static_cast<char>(0xE0 | (c >> 12));
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        s += static_cast<char>(0xF0 | (c >> 18));
        s += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (c & 0x3F));
    }
    return s;
}

}  // namespace

bool isFinite(const Num& n) {
    const int count = n.colour ? 5 : n.dim;
    for (int i = 0; i < count; ++i)
        if (!std::isfinite(n.v[i])) return false;
    return true;
}

std::string describeNumbers(const Num& n) {
    if (n.isFloat()) return formatNumber(n.v[0]);
    std::string s = "<";
    const int count = n.colour ? 5 : n.dim;
    for (int i = 0; i < count; ++i) s += (i ? ", " : "") + formatNumber(n.v[i]);
    return s + ">";
}

std::string describe(const Num& n) {
    if (n.colour) return "a colour";
    if (n.dim == 1) return "a float";
    return sizeName(n.dim);
}

std::string describe(const Value& v) {
    struct Visitor {
        std::string operator()(const Num& n) const { return describe(n); }
        std::string operator()(const std::string&) const { return "a string"; }
        std::string operator()(const std::shared_ptr<const ObjectTree>& o) const {
            return o->kind == ObjectTree::Kind::Light ? "a light_source" : "an object";
        }
        std::string operator()(const std::shared_ptr<const Pigment>&) const { return "a pigment"; }
        std::string operator()(const std::shared_ptr<const Finish>&) const { return "a finish"; }
        std::string operator()(const std::shared_ptr<const Texture>&) const { return "a texture"; }
        std::string operator()(const std::shared_ptr<const CameraValue>&) const { return "a camera"; }
        std::string operator()(const std::shared_ptr<ArrayValue>&) const { return "an array"; }
        std::string operator()(const std::shared_ptr<const MacroDef>&) const { return "a macro"; }
        std::string operator()(const std::shared_ptr<const ColourMapValue>&) const { return "a colour map"; }
        std::string operator()(const std::shared_ptr<const PigmentMapValue>&) const { return "a pigment map"; }
        std::string operator()(const std::shared_ptr<const Normal>&) const { return "a normal"; }
        std::string operator()(const Poison&) const { return "an erroneous value"; }
        std::string operator()(const Unset&) const { return "an element without a value"; }
        std::string operator()(const std::shared_ptr<const FunctionValue>&) const { return "a function"; }
        std::string operator()(const std::shared_ptr<const Interior>&) const { return "an interior"; }
        std::string operator()(const std::shared_ptr<const MaterialValue>&) const { return "a material"; }
        std::string operator()(const std::shared_ptr<const SkySphere>&) const { return "a sky_sphere"; }
        std::string operator()(const std::shared_ptr<const Fog>&) const { return "a fog"; }
        std::string operator()(const std::shared_ptr<UserFile>&) const { return "a file handle"; }
    };
    return std::visit(Visitor{}, v);
}

std::string Interpreter::referenceText(const Node& n) const {
    const Node* base = &n;
    while (base->kind == NodeKind::Index) base = &(*base)[0];
    if (base->kind != NodeKind::Name) return "this value";
    return quote(nameOf(*base) + (base == &n ? "" : "[…]"));
}

const Value* Interpreter::lookup(std::uint32_t id) const {
    const Slot* slot = findSlot(id, nullptr);
    if (!slot || slot->refScope < 0) return slot ? &slot->value : nullptr;
    const Scope& scope = scopes_[static_cast<std::size_t>(slot->refScope)];
    auto it = scope.find(slot->refId);
    return it == scope.end() ? nullptr : &it->second.value;
}

Num Interpreter::evalNum(const Node& n) {
    // Numbers and vectors of numbers are most of a big scene: no Value detour.
    if (n.kind == NodeKind::Number) return Num::scalar(n.number);
    Value v = eval(n);
    if (auto* num = std::get_if<Num>(&v)) return *num;
    fail(n, "expected a number, a vector or a colour, found " + describe(v));
}

double Interpreter::evalFloat(const Node& n) {
    if (n.kind == NodeKind::Number) return n.number;
    const Num v = evalNum(n);
    if (!v.isFloat()) fail(n, "expected a float, found " + describe(v));
    return v.v[0];
}

int Interpreter::evalInt(const Node& n, int min) {
    const double v = evalFloat(n);
    if (!(v >= min) || v > 2147483647.0)
        fail(n, "expected a whole number of at least " + std::to_string(min) + ", found " + formatNumber(v));
    return static_cast<int>(v);  // POV-Ray truncates
}

bool Interpreter::evalBool(const Node& n) { return std::abs(evalFloat(n)) > kPovEpsilon; }

Vec3 Interpreter::evalVector(const Node& n) {
    const Num v = evalNum(n);
    if (v.colour) fail(n, "expected a vector, found a colour");
    if (v.dim == 1) return Vec3(v.v[0]);  // a float promotes to <f, f, f>
    if (v.dim > 3) fail(n, std::string("expected a 3-component vector, found ") + sizeName(v.dim));
    return Vec3(v.v[0], v.v[1], v.dim == 3 ? v.v[2] : 0.0);
}

Color Interpreter::toColour(const Num& v, const Node& at, ColourChannels channels) {
    if (v.dim == 2 && !v.colour) fail(at, "expected a colour, found a 2-component vector");
    // A float is all five components where a colour has five, as in POV-Ray
    // (`color 0.5` is half filtering, half transmitting), and a grey where it
    // has three; a 3-, 4- or 5-vector is rgb, rgbf, rgbft.
    Color c;
    if (v.isFloat()) {
        c.rgb = Vec3(v.v[0]);
        if (channels == ColourChannels::Rgbft) c.filter = c.transmit = v.v[0];
        return c;
    }
    c.rgb = Vec3(v.v[0], v.v[1], v.v[2]);
    c.filter = v.dim >= 4 ? v.v[3] : 0.0;
    c.transmit = v.dim >= 5 ? v.v[4] : 0.0;
    return c;
}

Color Interpreter::evalColour(const Node& n, ColourChannels channels) {
    if (n.kind == NodeKind::Colour) {
        const Num c = evalColourNode(n, channels);
        return Color{Vec3(c.v[0], c.v[1], c.v[2]), c.v[3], c.v[4]};
    }
    return toColour(evalNum(n), n, channels);
}

namespace {
// "filter 0.5 and transmit 0.2" (the components that are not zero).
std::string filterAndTransmit(const Color& c) {
    std::string s;
    if (c.filter != 0.0) s = "filter " + formatNumber(c.filter);
    if (c.transmit != 0.0) s += (s.empty() ? "transmit " : " and transmit ") + formatNumber(c.transmit);
    return s;
}
}  // namespace

Vec3 Interpreter::evalRgb(const Node& n, std::string_view usedAs) {
    const Color c = evalColour(n, ColourChannels::Rgb);
    if (c.filter != 0.0 || c.transmit != 0.0) {
        const bool both = c.filter != 0.0 && c.transmit != 0.0;
        report(Severity::Warning, n,
               filterAndTransmit(c) + (both ? " have" : " has") + " no effect on " + std::string(usedAs) +
                   ", which is red, green and blue only (POV-Ray warns and ignores " +
                   (both ? "them" : "it") + " too)");
    }
    return c.rgb;
}

std::string Interpreter::evalString(const Node& n) {
    Value v = eval(n);
    if (auto* s = std::get_if<std::string>(&v)) return std::move(*s);
    fail(n, "expected a string, found " + describe(v));
}

namespace {

double component(const Num& a, int i) { return a.isFloat() ? a.v[0] : a.v[i]; }

// POV-Ray's str() and vstr() format: printf("%<w>.<p>f"), a negative width
// padding with zeros, a negative precision leaving printf's (6 digits). Widths
// beyond 256 and precisions beyond 64 are clipped (POV-Ray's buffer is 256).
std::string formatStr(double value, int width, int precision) {
    const std::string format = std::string("%") + (width < 0 ? "0" : "") + "*.*f";
    const int w = static_cast<int>(std::min<std::int64_t>(std::abs(std::int64_t{width}), 256));  // INT_MIN too
    const int p = precision < 0 ? 6 : std::min(precision, 64);
    const int size = std::snprintf(nullptr, 0, format.c_str(), w, p, value);
    std::string s(static_cast<std::size_t>(std::max(size, 0)), '\0');
    std::snprintf(s.data(), s.size() + 1, format.c_str(), w, p, value);
    return s;
}

// Arithmetic and logic of two floats or vectors, POV-Ray's way.
bool isComparison(Word op) {
    return op == Word::OpLess || op == Word::OpLessEqual || op == Word::OpEqual || op == Word::OpNotEqual ||
           op == Word::OpGreaterEqual || op == Word::OpGreater;
}

}  // namespace

// `color X red R …`: a whole colour (with `color`, any expression), then
// components that override it. `channels` says what a float base means.
Num Interpreter::evalColourNode(const Node& n, ColourChannels channels) {
    Num c;
    c.dim = 5;
    c.colour = true;
    std::size_t i = 0;
    if (n.flags) c = Num::fromColour(evalColour(n[i++], channels));
    for (; i < n.count; ++i) {
        const Node& item = n[i];
        const Num value = evalNum(item[0]);
        auto needs = [&](int dim) {
            if (!value.isFloat() && !(value.colour) && value.dim != dim)
                fail(item[0], quote(wordText(item.word)) + " takes a float or a " +
                                  std::to_string(dim) + "-component vector, found " + describe(value));
        };
        auto setAll = [&](std::initializer_list<int> slots) {
            int k = 0;
            for (int s : slots) c.v[s] = component(value, value.colour ? s : k++);
        };
        switch (item.word) {
        case Word::Rgb: needs(3); setAll({0, 1, 2}); break;
        case Word::Rgbf: needs(4); setAll({0, 1, 2, 3}); break;
        case Word::Rgbt:
            needs(4);
            c.v[0] = component(value, 0);
            c.v[1] = component(value, 1);
            c.v[2] = component(value, 2);
            c.v[4] = component(value, value.colour ? 4 : 3);
            break;
        case Word::Rgbft: needs(5); setAll({0, 1, 2, 3, 4}); break;
        default: {
            if (!value.isFloat())
                fail(item[0], quote(wordText(item.word)) + " takes a float, found " +
                                  describe(value));
            const int slot = item.word == Word::Red     ? 0
                             : item.word == Word::Green ? 1
                             : item.word == Word::Blue  ? 2
                             : item.word == Word::Filter ? 3
                                                        : 4;
            c.v[slot] = value.v[0];
        }
        }
    }
    return c;
}

// A float made a C int where POV-Ray makes one (a width, a position, a
// generator's number): truncated, but refused when it cannot be one.
int Interpreter::toInt(double v, const Node& at, const char* what) {
    if (!(v > -2147483649.0 && v < 2147483648.0))
        fail(at, std::string(what) + " must be a whole number between -2147483648 and 2147483647, not " +
                     formatNumber(v));
    return static_cast<int>(v);
}

// One step of a chain of binary operators: `acc op n[1]`. & and | leave their
// right side alone once the left decides (POV-Ray's domains are wider than
// ours: `(X >= 0 & sqrt(X) < 2)` must not fail for X < 0).
Num Interpreter::binaryStep(const Node& n, const Num& acc) {
    const Word op = n.word;
    if (op == Word::OpAnd) return Num::scalar(std::abs(acc.v[0]) > kPovEpsilon && evalBool(n[1]) ? 1.0 : 0.0);
    if (op == Word::OpOr) return Num::scalar(std::abs(acc.v[0]) > kPovEpsilon || evalBool(n[1]) ? 1.0 : 0.0);
    if (isComparison(op)) {
        const double x = acc.v[0];
        const double y = evalFloat(n[1]);
        bool r = false;
        switch (op) {
        case Word::OpLess: r = x < y; break;
        case Word::OpLessEqual: r = x < y || std::abs(x - y) < kPovEpsilon; break;
        case Word::OpEqual: r = std::abs(x - y) < kPovEpsilon; break;
        case Word::OpNotEqual: r = !(std::abs(x - y) < kPovEpsilon); break;
        case Word::OpGreaterEqual: r = x > y || std::abs(x - y) < kPovEpsilon; break;
        default: r = x > y; break;
        }
        return Num::scalar(r ? 1.0 : 0.0);
    }
    Num a = acc;
    Num b = evalNum(n[1]);
    if (!(a.isFloat() && b.isFloat())) {
        const bool colour = a.colour || b.colour;
        const int dim = colour ? 5 : std::max<int>(a.dim, b.dim);
        a = widen(a, dim, colour);
        b = widen(b, dim, colour);
    }
    Num r = a;
    for (int i = 0; i < a.dim; ++i) {
        const double x = a.v[i];
        const double y = b.v[i];
        switch (op) {
        case Word::OpAdd: r.v[i] = x + y; break;
        case Word::OpSub: r.v[i] = x - y; break;
        case Word::OpMul: r.v[i] = x * y; break;
        default:
            if (y == 0.0) fail(n, "division by zero");
            r.v[i] = x / y;
        }
        // Operands are finite (every value is): only an overflow leaves it.
        if (!std::isfinite(r.v[i]))
            fail(n, formatNumber(x) + " " + std::string(wordText(op)) + " " + formatNumber(y) +
                        " overflows: the result is not a finite number");
    }
    return r;
}

// The left operand of `op`: logic and comparisons take floats, arithmetic numbers.
Num Interpreter::operand(Word op, const Node& n) {
    if (op == Word::OpAnd || op == Word::OpOr || isComparison(op)) return Num::scalar(evalFloat(n));
    return evalNum(n);
}

Value Interpreter::eval(const Node& n) {
    switch (n.kind) {
    case NodeKind::Number:
        return Num::scalar(n.number);
    case NodeKind::String:
        return ast_->strings[n.id];
    case NodeKind::Name: {
        const Value* v = lookup(n.id);
        if (!v) fail(n, "'" + nameOf(n) + "' is not declared");
        if (!deprecations_.empty()) {
            const auto d = deprecations_.find(n.id);
            if (d != deprecations_.end() && !(d->second.once && d->second.warned)) {
                d->second.warned = true;
                report(Severity::Warning, n, d->second.message);
            }
        }
        if (std::holds_alternative<Poison>(*v)) throw Abandon{};
        if (std::holds_alternative<std::shared_ptr<const MacroDef>>(*v))
            fail(n, "'" + nameOf(n) + "' is a macro: call it with its arguments, " + nameOf(n) + "(…)");
        return *v;
    }
    case NodeKind::Constant: {
        switch (n.word) {
        case Word::X: return Num::vector({1, 0, 0});
        case Word::Y: return Num::vector({0, 1, 0});
        case Word::Z: return Num::vector({0, 0, 1});
        case Word::T: {
            Num t;
            t.dim = 4;
            t.v[3] = 1.0;
            return t;
        }
        case Word::U: case Word::V: {
            Num uv;
            uv.dim = 2;
            uv.v[n.word == Word::U ? 0 : 1] = 1.0;
            return uv;
        }
        case Word::Pi: return Num::scalar(3.1415926535897932384626);
        case Word::Clock:
            if (!std::isfinite(options_.clock))
                fail(n, "the clock must be a finite number, not " + formatNumber(options_.clock));
            return Num::scalar(options_.clock);
        case Word::ClockOn: return Num::scalar(options_.clockOn ? 1.0 : 0.0);
        case Word::ClockDelta: return Num::scalar(options_.clockDelta);
        case Word::FrameNumber: return Num::scalar(options_.frameNumber);
        case Word::InitialFrame: return Num::scalar(options_.initialFrame);
        case Word::FinalFrame: return Num::scalar(options_.finalFrame);
        case Word::InitialClock: return Num::scalar(options_.initialClock);
        case Word::FinalClock: return Num::scalar(options_.finalClock);
        case Word::Version: return Num::scalar(versionHundredths_ / 100.0);
        case Word::True: case Word::On: case Word::Yes: return Num::scalar(1.0);
        case Word::False: case Word::Off: case Word::No: return Num::scalar(0.0);
        case Word::ImageWidth: return Num::scalar(options_.imageWidth);
        case Word::ImageHeight: return Num::scalar(options_.imageHeight);
        default: fail(n, quote(wordText(n.word)) + " is not a value");
        }
    }
    case NodeKind::Binary: {
        // A chain `a + b - c …` is a tree leaning left, as deep as it is long:
        // its left side is walked here rather than by recursion.
        const Nested nested(*this, n);
        if (n[0].kind != NodeKind::Binary) return binaryStep(n, operand(n.word, n[0]));
        std::vector<const Node*> chain;
        const Node* left = &n;
        while (left->kind == NodeKind::Binary) {
            chain.push_back(left);
            left = &(*left)[0];
        }
        Num acc = operand(chain.back()->word, *left);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) acc = binaryStep(**it, acc);
        return acc;
    }
    case NodeKind::Index:
        return arrayElement(n);
    case NodeKind::MacroCall:
        return evalMacroValue(n);
    case NodeKind::Function:
        return makeFunction(n);
    case NodeKind::Array:
        return makeArray(n);
    default:
        break;
    }
    const Nested nested(*this, n);
    switch (n.kind) {
    case NodeKind::Vector: {
        Num r;
        r.dim = static_cast<std::uint8_t>(n.count);
        for (std::uint32_t i = 0; i < n.count; ++i) r.v[i] = evalFloat(n[i]);
        return r;
    }
    case NodeKind::Unary: {
        if (n.word == Word::OpNot) return Num::scalar(evalBool(n[0]) ? 0.0 : 1.0);
        Num a = evalNum(n[0]);
        if (n.word == Word::OpSub)
            for (double& c : a.v) c = -c;
        return a;
    }
    case NodeKind::Conditional:
        return evalBool(n[0]) ? eval(n[1]) : eval(n[2]);
    case NodeKind::Member: {
        const Num a = evalNum(n[0]);
        if (a.isFloat())
            fail(n, quote(std::string(".") += wordText(n.word)) + " needs a vector or a colour, found a float");
        int index = 0;
        switch (n.word) {
        case Word::X: case Word::U: case Word::Red: index = 0; break;
        case Word::Y: case Word::V: case Word::Green: index = 1; break;
        case Word::Z: case Word::Blue: index = 2; break;
        case Word::T: case Word::Filter: index = 3; break;
        case Word::Transmit: index = 4; break;
        default: {  // gray: POV-Ray 3.7's weights
            if (a.dim < 3) fail(n, "'.gray' needs a colour or a 3-vector");
            return Num::scalar(0.297 * a.v[0] + 0.589 * a.v[1] + 0.114 * a.v[2]);
        }
        }
        if (index >= a.dim)
            fail(n, describe(a) + " has no " + quote(std::string(".") += wordText(n.word)) + " component");
        return Num::scalar(a.v[index]);
    }
    case NodeKind::Colour:
        return evalColourNode(n, ColourChannels::Rgbft);
    case NodeKind::Call: {
        // No value is NaN or infinite: a function's result that overflows
        // (exp(1000), val("inf")) is refused where it is made.
        Value v = call(n);
        if (const auto* num = std::get_if<Num>(&v); num && !isFinite(*num))
            fail(n, std::string(wordText(n.word)) + ": the result is not a finite number (" + describeNumbers(*num) + ")");
        return v;
    }
    default:
        fail(n, "this is not an expression");
    }
}

Value Interpreter::call(const Node& n) {
    const auto args = n.children();
    auto f = [&](std::size_t i) { return evalFloat(args[i]); };
    auto check = [&](bool ok, const char* what) {
        if (!ok) fail(n, std::string(wordText(n.word)) + ": " + what);
    };
    switch (n.word) {
    case Word::Abs: return Num::scalar(std::abs(f(0)));
    case Word::Sqrt: { const double a = f(0); check(a >= 0, "the argument is negative"); return Num::scalar(std::sqrt(a)); }
    case Word::Pow: {
        const double r = std::pow(f(0), f(1));
        check(std::isfinite(r), "the result is not a finite number");
        return Num::scalar(r);
    }
    case Word::Sin: return Num::scalar(std::sin(f(0)));
    case Word::Cos: return Num::scalar(std::cos(f(0)));
    case Word::Tan: return Num::scalar(std::tan(f(0)));
    case Word::Asin: { const double a = f(0); check(a >= -1 && a <= 1, "the argument is outside [-1, 1]"); return Num::scalar(std::asin(a)); }
    case Word::Acos: { const double a = f(0); check(a >= -1 && a <= 1, "the argument is outside [-1, 1]"); return Num::scalar(std::acos(a)); }
    case Word::Atan: return Num::scalar(std::atan(f(0)));
    case Word::Atan2: return Num::scalar(std::atan2(f(0), f(1)));
    case Word::Sinh: return Num::scalar(std::sinh(f(0)));
    case Word::Cosh: return Num::scalar(std::cosh(f(0)));
    case Word::Tanh: return Num::scalar(std::tanh(f(0)));
    case Word::Asinh: return Num::scalar(std::asinh(f(0)));
    case Word::Acosh: { const double a = f(0); check(a >= 1, "the argument is less than 1"); return Num::scalar(std::acosh(a)); }
    case Word::Atanh: { const double a = f(0); check(a > -1 && a < 1, "the argument is outside (-1, 1)"); return Num::scalar(std::atanh(a)); }
    case Word::Min: case Word::Max: {
        double r = f(0);
        for (std::size_t i = 1; i < args.size(); ++i) r = n.word == Word::Min ? std::min(r, f(i)) : std::max(r, f(i));
        return Num::scalar(r);
    }
    case Word::Mod: { const double b = f(1); check(b != 0, "division by zero"); return Num::scalar(std::fmod(f(0), b)); }
    case Word::Div: { const double b = f(1); check(b != 0, "division by zero"); return Num::scalar(std::trunc(f(0) / b)); }
    case Word::Floor: return Num::scalar(std::floor(f(0)));
    case Word::Ceil: return Num::scalar(std::ceil(f(0)));
    case Word::Int: return Num::scalar(std::trunc(f(0)));
    case Word::Sqr: { const double a = f(0); return Num::scalar(a * a); }
    case Word::Radians: return Num::scalar(f(0) * kPi / 180.0);
    case Word::Degrees: return Num::scalar(f(0) * 180.0 / kPi);
    case Word::Exp: return Num::scalar(std::exp(f(0)));
    case Word::Log: { const double a = f(0); check(a > 0, "the argument is not positive"); return Num::scalar(std::log10(a)); }
    case Word::Ln: { const double a = f(0); check(a > 0, "the argument is not positive"); return Num::scalar(std::log(a)); }
    case Word::Vlength: return Num::scalar(glm::length(evalVector(args[0])));
    case Word::Vnormalize: {
        const Vec3 a = evalVector(args[0]);
        check(glm::length(a) > 0, "the vector has zero length");
        return Num::vector(glm::normalize(a));
    }
    case Word::Vcross: return Num::vector(glm::cross(evalVector(args[0]), evalVector(args[1])));
    case Word::Vdot: return Num::scalar(glm::dot(evalVector(args[0]), evalVector(args[1])));
    case Word::Vrotate: {
        const Vec3 a = evalVector(args[0]);
        return Num::vector(Transform::rotateDegrees(evalVector(args[1])).vector(a));
    }
    case Word::VaxisRotate: {
        // Rodrigues' formula; the sense matches `rotate` about the same axis.
        const Vec3 a = evalVector(args[0]);
        const Vec3 axis = evalVector(args[1]);
        check(glm::length(axis) > 0, "the axis has zero length");
        const Vec3 k = glm::normalize(axis);
        const double t = f(2) * kPi / 180.0;
        return Num::vector(a * std::cos(t) + glm::cross(k, a) * std::sin(t) +
                           k * glm::dot(k, a) * (1.0 - std::cos(t)));
    }
    case Word::Sum: case Word::Prod:
        fail(n, quote(wordText(n.word)) + " is allowed only inside a function { … }, as in POV-Ray");
    case Word::Select: {
        const double a = f(0);
        if (args.size() == 3) return eval(args[a < 0 ? 1 : 2]);
        return eval(args[a < 0 ? 1 : a == 0 ? 2 : 3]);
    }
    case Word::Concat: {
        // `#declare S = concat(S, S)` in a loop doubles S: its length is
        // checked before it is allocated.
        std::string s;
        for (const Node& a : args) {
            std::string part = evalString(a);
            if (s.size() + part.size() > options_.maxStringLength) {
                error(n, "concat: the string would be " + std::to_string(s.size() + part.size()) +
                             " characters long, over the limit of " + std::to_string(options_.maxStringLength) +
                             " (raise it with --max-string-length)");
                throw Stop{};  // as past every limit (checkObjects)
            }
            checkMemory(n, s.size() + part.size(), "concat");
            s += part;
        }
        return s;
    }
    case Word::Str: {
        const double value = f(0);
        const int width = toInt(f(1), args[1], "the width of str()");
        const int precision = toInt(f(2), args[2], "the precision of str()");
        return formatStr(value, width, precision);
    }
    case Word::Vstr: {
        // vstr(N, V, separator, width, precision): N components (2 to 5) of V;
        // a float is its first component, the others 0 (POV-Ray's).
        const int count = std::clamp(toInt(f(0), args[0], "the number of components of vstr()"), 2, 5);
        const Num v = evalNum(args[1]);
        const std::string separator = evalString(args[2]);
        const int width = toInt(f(3), args[3], "the width of vstr()");
        const int precision = toInt(f(4), args[4], "the precision of vstr()");
        std::string s;
        for (int i = 0; i < count; ++i) {
            if (i > 0) s += separator;
            s += formatStr(i < v.dim || v.colour ? v.v[i] : 0.0, width, precision);
        }
        return s;
    }
    case Word::Chr: {
        const double c = f(0);
        check(c >= 1 && c <= 0x10FFFF, "the character code is outside 1 to 0x10FFFF");
        return utf8(static_cast<std::uint32_t>(c));
    }
    case Word::Asc: {
        const std::string s = evalString(args[0]);
        return Num::scalar(s.empty() ? 0.0 : static_cast<double>(static_cast<unsigned char>(s[0])));
    }
    case Word::FileExists: return Num::scalar(findReadable(evalString(args[0])).empty() ? 0.0 : 1.0);
    case Word::Strlen: return Num::scalar(static_cast<double>(evalString(args[0]).size()));
    case Word::Strcmp: {
        // POV-Ray: the difference of the first characters that differ.
        const std::string a = evalString(args[0]);
        const std::string b = evalString(args[1]);
        std::size_t i = 0;
        while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
        const int x = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
        const int y = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
        return Num::scalar(static_cast<double>(x - y));
    }
    case Word::Substr: {
        // substr(S, P, L): L characters from position P (the first is 1).
        const std::string s = evalString(args[0]);
        const int position = toInt(f(1), args[1], "the position of substr()");
        const int length = toInt(f(2), args[2], "the length of substr()");
        if (position < 1 || length < 0 || static_cast<std::int64_t>(position) + length - 1 > static_cast<std::int64_t>(s.size()))
            fail(n, "substr: " + countOf(static_cast<std::size_t>(std::max(length, 0)), "character") + " from position " +
                        std::to_string(position) + " are not within the string's " + countOf(s.size(), "character"));
        return s.substr(static_cast<std::size_t>(position - 1), static_cast<std::size_t>(length));
    }
    case Word::Strupr: case Word::Strlwr: {
        std::string s = evalString(args[0]);
        for (char& c : s)
            c = static_cast<char>(n.word == Word::Strupr ? std::toupper(static_cast<unsigned char>(c))
                                                         : std::tolower(static_cast<unsigned char>(c)));
        return s;
    }
    case Word::Val: {
        const std::string s = evalString(args[0]);
        std::size_t start = s.find_first_not_of(" \t");
        if (start == std::string::npos) start = s.size();
        double v = 0.0;
        const char* first = s.data() + start;
        if (start < s.size() && *first == '+') ++first;
        const auto r = std::from_chars(first, s.data() + s.size(), v);
        check(r.ec == std::errc(), "the string does not start with a number");
        return Num::scalar(v);
    }
    case Word::Defined:
        return Num::scalar(isDefined(args[0]) ? 1.0 : 0.0);
    case Word::Seed: {
        // POV-Ray: a new generator, started at the seed; its value is the
        // generator's number, which rand() takes.
        const int seed = toInt(f(0), args[0], "the seed");
        randomStreams_.push_back(static_cast<std::uint32_t>(seed));
        return Num::scalar(static_cast<double>(randomStreams_.size() - 1));
    }
    case Word::Rand: {
        // POV-Ray's generator: a 32-bit linear congruence, scaled to [0, 1].
        const int stream = toInt(f(0), args[0], "the generator given to rand()");
        if (stream < 0 || static_cast<std::size_t>(stream) >= randomStreams_.size())
            fail(args[0], "rand(" + std::to_string(stream) + "): no such generator; make one with seed()");
        std::uint32_t& state = randomStreams_[static_cast<std::size_t>(stream)];
        state = state * 1812433253u + 12345u;
        return Num::scalar(static_cast<double>(state) / 4294967295.0);
    }
    case Word::Dimensions: case Word::DimensionSize: {
        const Value a = eval(args[0]);
        const auto* array = std::get_if<std::shared_ptr<ArrayValue>>(&a);
        if (!array) fail(args[0], std::string(wordText(n.word)) + " takes an array, not " + describe(a));
        const auto& sizes = (*array)->sizes;
        if (n.word == Word::Dimensions) return Num::scalar(static_cast<double>(sizes.size()));
        // A dimension that the array does not have has size 0 (POV-Ray's).
        const int d = toInt(f(1), args[1], "the dimension of dimension_size()");
        return Num::scalar(d >= 1 && static_cast<std::size_t>(d) <= sizes.size() ? sizes[static_cast<std::size_t>(d - 1)] : 0.0);
    }
    default:
        fail(n, quote(wordText(n.word)) + " is not a function");
    }
}

}  // namespace asos::lang
