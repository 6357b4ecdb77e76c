#include "asos/render/pov_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "asos/scene/pov_tolerances.hpp"

namespace asos {

namespace {

// POV-Ray's random gradient table (core/material/noise.cpp, RTable): the
// values at even places; each odd place holds half the value before it.
constexpr double kRandomTable[267] = {
    -1,         0.604974,   -0.937102,  0.414115,   0.576226,   -0.0161593, 0.432334,   0.103685,   0.590539,
    0.0286412,  0.46981,    -0.84622,   -0.0734112, -0.304097,  -0.40206,   -0.210132,  -0.919127,  0.652033,
    -0.83151,   -0.183948,  -0.671107,  0.852476,   0.043595,   -0.404532,  0.75494,    -0.335653,  0.618433,
    0.605707,   0.708583,   -0.477195,  0.899474,   0.490623,   0.221729,   -0.400381,  -0.853727,  -0.932586,
    0.659113,   0.961303,   0.325948,   -0.750851,  0.842466,   0.734401,   -0.649866,  0.394491,   -0.466056,
    -0.434073,  0.109026,   0.0847028,  -0.738857,  0.241505,   0.16228,    -0.71426,   -0.883665,  -0.150408,
    -0.90396,   -0.686549,  -0.785214,  0.488548,   0.0246433,  0.142473,   -0.602136,  0.375845,   -0.00779736,
    0.498955,   -0.268147,  0.856382,   -0.386007,  -0.596094,  -0.867735,  -0.570977,  -0.914366,  0.28896,
    0.672206,   -0.233783,  0.94815,    0.895262,   0.343252,   -0.173388,  -0.767971,  -0.314748,  0.824308,
    -0.342092,  0.721431,   -0.24004,   -0.63653,   0.553277,   0.376272,   0.158984,   -0.452659,  0.396323,
    -0.420676,  -0.454154,  0.122179,   0.295857,   0.0664225,  -0.202075,  -0.724788,  0.453513,   0.224567,
    -0.908812,  0.176349,   -0.320516,  -0.697139,  0.742702,   -0.900786,  0.471489,   -0.133532,  0.119127,
    -0.889769,  -0.23183,   -0.669673,  -0.046891,  -0.803433,  -0.966735,  0.475578,   -0.652644,  0.0112459,
    -0.730007,  0.128283,   0.145647,   -0.619318,  0.272023,   0.392966,   0.646418,   -0.0207675, -0.315908,
    0.480797,   0.535668,   -0.250172,  -0.83093,   -0.653773,  -0.443809,  0.119982,   -0.897642,  0.89453,
    0.165789,   0.633875,   -0.886839,  0.930877,   -0.537194,  0.587732,   0.722011,   -0.209461,  -0.0424659,
    -0.814267,  -0.919432,  0.280262,   -0.66302,   -0.558099,  -0.537469,  -0.598779,  0.929656,   -0.170794,
    -0.537163,  0.312581,   0.959442,   0.722652,   0.499931,   0.175616,   -0.534874,  -0.685115,  0.444999,
    0.17171,    0.108202,   -0.768704,  -0.463828,  0.254231,   0.546014,   0.869474,   0.875212,   -0.944427,
    0.130724,   -0.110185,  0.312184,   -0.33138,   -0.629206,  0.0606546,  0.722866,   -0.0979477, 0.821561,
    0.0931258,  -0.972808,  0.0318151,  -0.867033,  -0.387228,  0.280995,   -0.218189,  -0.539178,  -0.427359,
    -0.602075,  0.311971,   0.277974,   0.773159,   0.592493,   -0.0331884, -0.630854,  -0.269947,  0.339132,
    0.581079,   0.209461,   -0.317433,  -0.284993,  0.181323,   0.341634,   0.804959,   -0.229572,  -0.758907,
    -0.336721,  0.605463,   -0.991272,  -0.0188754, -0.300191,  0.368307,   -0.176135,  -0.3832,    -0.749569,
    0.62356,    -0.573938,  0.278309,   -0.971313,  0.839994,   -0.830686,  0.439078,   0.66128,    0.694514,
    0.0565042,  0.54342,    -0.438804,  -0.0228428, -0.687068,  0.857267,   0.301991,   -0.494255,  -0.941039,
    0.775509,   0.410575,   -0.362081,  -0.671534,  -0.348379,  0.932433,   0.886442,   0.868681,   -0.225666,
    -0.062211,  -0.0976425, -0.641444,  -0.848112,  0.724697,   0.473503,   0.998749,   0.174701,   0.559625,
    -0.029099,  -0.337392,  -0.958129,  -0.659785,  0.236042,   -0.246937,  0.659449,   -0.027512,  0.821897,
    -0.226215,  0.0181735,  0.500481,   -0.420127,  -0.427878,  0.566186};

// POV-Ray's table generator: the 15 bits above the low 16 of a linear
// congruential sequence (its int arithmetic wraps modulo 2^32).
struct TableRandom {
    std::uint32_t state;
    int next() {
        state = state * 1812433253u + 12345u;
        return static_cast<int>((state >> 16) & 0x7FFF);
    }
};

constexpr int kNoiseMin = -10000;  // POV-Ray's NOISE_MINX: the lattice starts here

double scurve(double t) { return t * t * (3.0 - 2.0 * t); }

// A lattice coordinate: its cell (POV-Ray's "JB fix" rounding for negative
// values) and the fraction within it.
struct LatticeAxis {
    int cell;
    double fraction;
};
LatticeAxis latticeAxis(double x) {
    const int whole = x >= 0.0 ? static_cast<int>(x) : static_cast<int>(x - (1.0 - kPovEpsilon));
    return {(whole - kNoiseMin) & 0xFFF, x - whole};
}

}  // namespace

PovNoise::Cell PovNoise::cellOf(const Vec3& p) const {
    const LatticeAxis ax = latticeAxis(p.x), ay = latticeAxis(p.y), az = latticeAxis(p.z);
    Cell c;
    c.x0 = ax.fraction;
    c.y0 = ay.fraction;
    c.z0 = az.fraction;
    c.x1 = c.x0 - 1.0;
    c.y1 = c.y0 - 1.0;
    c.z1 = c.z0 - 1.0;
    c.sx = scurve(c.x0);
    c.sy = scurve(c.y0);
    c.sz = scurve(c.z0);
    c.tx = 1.0 - c.sx;
    c.ty = 1.0 - c.sy;
    c.tz = 1.0 - c.sz;
    auto hash2 = [&](int a, int b) { return static_cast<int>(hash_[static_cast<int>(hash_[a]) ^ b]); };
    c.h00 = hash2(ax.cell, ay.cell);
    c.h10 = hash2(ax.cell + 1, ay.cell);
    c.h01 = hash2(ax.cell, ay.cell + 1);
    c.h11 = hash2(ax.cell + 1, ay.cell + 1);
    c.iz = az.cell;
    return c;
}

const PovNoise& PovNoise::tables() {
    static const PovNoise instance;
    return instance;
}

PovNoise::PovNoise() {
    // The lattice hash: 0..4095 shuffled, then repeated.
    for (int i = 0; i < 4096; ++i) hash_[i] = static_cast<std::uint16_t>(i);
    TableRandom shuffle{0};
    for (int i = 4095; i >= 0; --i) {
        const int j = shuffle.next() % 4096;
        std::swap(hash_[i], hash_[j]);
    }
    for (int i = 0; i < 4096; ++i) hash_[4096 + i] = hash_[i];

    for (int i = 0; i < 267; ++i) {
        rtable_[2 * i] = kRandomTable[i];
        rtable_[2 * i + 1] = kRandomTable[i] * 0.5;
    }

    // Perlin's generator: unit gradients drawn inside the unit ball, and a
    // permutation, both from one sequence starting at 1 (InitSolidNoise).
    TableRandom draw{1};
    for (int i = 0; i < kEntries; ++i) {
        Vec3 v;
        double s;
        do {
            for (int j = 0; j < 3; ++j) v[j] = double((draw.next() % (kEntries << 1)) - kEntries) / double(kEntries);
            s = glm::dot(v, v);
        } while (s > 1.0 || s < 1.0e-5);
        gradients_[i] = v / std::sqrt(s);
    }
    for (int i = 0; i < kEntries; ++i) permutation_[i] = i;
    for (int i = kEntries; i > 0; i -= 2) {
        const int k = permutation_[i];
        const int j = draw.next() % kEntries;
        permutation_[i] = permutation_[j];
        permutation_[j] = k;
    }
    for (int i = 0; i < kEntries + 2; ++i) {
        permutation_[kEntries + i] = permutation_[i];
        gradients_[kEntries + i] = gradients_[i];
    }
}

double PovNoise::noise(const Vec3& p, int generator) const {
    if (generator == 3) {
        // POV-Ray's correction of the generator's bias to about [0, 1].
        return std::clamp(0.5 * (1.59 * solidNoise(p) + 0.985), 0.0, 1.0);
    }
    const Cell c = cellOf(p);
    // The corner's entry in the random table and its linear term there.
    auto corner = [&](int xy, int z, double weight, double dx, double dy, double dz) {
        const double* m = &rtable_[(hash_[xy ^ z] & 0xFF) * 2];
        return weight * (m[1] + m[2] * dx + m[4] * dy + m[6] * dz);
    };
    // The sum in POV-Ray's order (floating-point addition is not associative).
    double sum = corner(c.h00, c.iz, c.tx * c.ty * c.tz, c.x0, c.y0, c.z0);
    sum += corner(c.h10, c.iz, c.sx * c.ty * c.tz, c.x1, c.y0, c.z0);
    sum += corner(c.h01, c.iz, c.tx * c.sy * c.tz, c.x0, c.y1, c.z0);
    sum += corner(c.h11, c.iz, c.sx * c.sy * c.tz, c.x1, c.y1, c.z0);
    sum += corner(c.h00, c.iz + 1, c.tx * c.ty * c.sz, c.x0, c.y0, c.z1);
    sum += corner(c.h10, c.iz + 1, c.sx * c.ty * c.sz, c.x1, c.y0, c.z1);
    sum += corner(c.h01, c.iz + 1, c.tx * c.sy * c.sz, c.x0, c.y1, c.z1);
    sum += corner(c.h11, c.iz + 1, c.sx * c.sy * c.sz, c.x1, c.y1, c.z1);
    if (generator == 2) {
        // POV-Ray's measured range of the sum, [-1.05242, 0.988997], onto [0, 1].
        sum += 1.05242;
        sum *= 0.48985582;
    } else {
        sum += 0.5;
    }
    return std::clamp(sum, 0.0, 1.0);
}

Vec3 PovNoise::dnoise(const Vec3& p) const {
    const Cell c = cellOf(p);
    // Each component reads the table 8 places further on.
    auto corner = [&](Vec3& r, bool first, int xy, int z, double weight, double dx, double dy, double dz) {
        const double* m = &rtable_[(hash_[xy ^ z] & 0xFF) * 2];
        for (int axis = 0; axis < 3; ++axis, m += 8) {
            const double term = weight * (m[1] + m[2] * dx + m[4] * dy + m[6] * dz);
            r[axis] = first ? term : r[axis] + term;
        }
    };
    Vec3 r(0.0);
    // POV-Ray's order, which differs from the scalar noise's.
    corner(r, true, c.h00, c.iz, c.tx * c.ty * c.tz, c.x0, c.y0, c.z0);
    corner(r, false, c.h10, c.iz, c.sx * c.ty * c.tz, c.x1, c.y0, c.z0);
    corner(r, false, c.h11, c.iz, c.sx * c.sy * c.tz, c.x1, c.y1, c.z0);
    corner(r, false, c.h01, c.iz, c.tx * c.sy * c.tz, c.x0, c.y1, c.z0);
    corner(r, false, c.h01, c.iz + 1, c.tx * c.sy * c.sz, c.x0, c.y1, c.z1);
    corner(r, false, c.h11, c.iz + 1, c.sx * c.sy * c.sz, c.x1, c.y1, c.z1);
    corner(r, false, c.h10, c.iz + 1, c.sx * c.ty * c.sz, c.x1, c.y0, c.z1);
    corner(r, false, c.h00, c.iz + 1, c.tx * c.ty * c.sz, c.x0, c.y0, c.z1);
    return r;
}

double PovNoise::solidNoise(const Vec3& p) const {
    struct Axis {
        int b0, b1;
        double r0, r1;
    };
    auto setup = [](double v) {
        constexpr double kRollover = 10000000.023157213;  // POV-Ray's ROLLOVER
        const double t = v + kRollover;
        const int it = static_cast<int>(std::floor(t));
        const int b0 = it & (kEntries - 1);
        return Axis{b0, (b0 + 1) & (kEntries - 1), t - it, t - it - 1.0};
    };
    const Axis x = setup(p.x), y = setup(p.y), z = setup(p.z);
    const int i = permutation_[x.b0], j = permutation_[x.b1];
    const int b00 = permutation_[i + y.b0], b10 = permutation_[j + y.b0];
    const int b01 = permutation_[i + y.b1], b11 = permutation_[j + y.b1];
    const double sx = scurve(x.r0), sy = scurve(y.r0), sz = scurve(z.r0);
    auto at = [&](int g, double rx, double ry, double rz) {
        const Vec3& q = gradients_[g];
        return rx * q.x + ry * q.y + rz * q.z;
    };
    auto lerp = [](double t, double a, double b) { return a + t * (b - a); };
    double a = lerp(sx, at(b00 + z.b0, x.r0, y.r0, z.r0), at(b10 + z.b0, x.r1, y.r0, z.r0));
    double b = lerp(sx, at(b01 + z.b0, x.r0, y.r1, z.r0), at(b11 + z.b0, x.r1, y.r1, z.r0));
    const double c = lerp(sy, a, b);
    a = lerp(sx, at(b00 + z.b1, x.r0, y.r0, z.r1), at(b10 + z.b1, x.r1, y.r0, z.r1));
    b = lerp(sx, at(b01 + z.b1, x.r0, y.r1, z.r1), at(b11 + z.b1, x.r1, y.r1, z.r1));
    const double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

double PovNoise::turbulence(const Vec3& p, int octaves, double omega, double lambda, int generator) const {
    // Generators 2 and 3 are stretched to fill [0, 1] better, as in POV-Ray
    // (and only the first octave is clipped there).
    auto octave = [&](const Vec3& q) {
        const double n = noise(q, generator);
        return generator == 1 ? n : 2.0 * n - 0.5;
    };
    const double first = generator == 1 ? noise(p, 1) : std::clamp(octave(p), 0.0, 1.0);
    return sumOctaves(first, p, octaves, omega, lambda, octave);
}

Vec3 PovNoise::dturbulence(const Vec3& p, int octaves, double omega, double lambda) const {
    return sumOctaves(dnoise(p), p, octaves, omega, lambda, [&](const Vec3& q) { return dnoise(q); });
}

double PovNoise::cycloidal(double x) { return std::sin(x * 2.0 * std::numbers::pi); }

double triangleWave(double x) {
    const double offset = x >= 0.0 ? x - std::floor(x) : x - (-1.0 - std::floor(std::fabs(x)));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

}  // namespace asos
