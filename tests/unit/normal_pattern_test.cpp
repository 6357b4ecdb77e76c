// The normal patterns (render/normal_pattern.hpp): POV-Ray's arithmetic at
// known points: a slope pattern's tilt in closed form (gradient's ramp
// measured over POV-Ray's tetrahedron), how a pattern's transform carries
// it, the noise patterns' tilt from PovNoise's vector noise, the wave
// sources, and that every result is unit. Against POV-Ray's renders:
// tests/golden/povray/normals.pov.
#include <catch2/catch.hpp>

#include <cmath>

#include "asos/render/normal_pattern.hpp"
#include "asos/render/pov_noise.hpp"
#include "asos/render/shading.hpp"

using namespace asos;

namespace {

bool near(const Vec3& a, const Vec3& b, double eps = 1e-9) { return glm::length(a - b) <= eps; }

Normal gradientX(double amount) {
    Normal n;
    n.kind = Normal::Kind::Pattern;
    n.pattern.kind = Pigment::Kind::Gradient;
    n.pattern.gradient = Vec3(1.0, 0.0, 0.0);
    n.amount = amount;
    return n;
}

}  // namespace

TEST_CASE("A slope pattern tilts the normal by its slope, POV-Ray's way", "[pattern][normal]") {
    // The four values x + d p_i.x over the regular tetrahedron sum to
    // d (4/3) x; times POV-Ray's amount -5 (0.02 / d), the tilt is
    // -(0.4 / 3) amount along x, whatever the accuracy.
    const Vec3 up(0.0, 1.0, 0.0);
    for (double accuracy : {0.02, 0.05, 0.001}) {
        Normal n = gradientX(0.6);
        n.accuracy = accuracy;
        const Vec3 got = perturbedNormal(n, Vec3(0.4, 0.0, 0.3), up);
        CHECK(near(got, glm::normalize(Vec3(-0.4 / 3.0 * 0.6, 1.0, 0.0)), 1e-7));
    }
    // A uniform scale changes nothing; a stretch along x halves the tilt
    // (the normal goes through the pattern's transform and back).
    Normal scaled = gradientX(0.6);
    scaled.pattern.worldFromPattern = Transform::scale(Vec3(2.0));
    CHECK(near(perturbedNormal(scaled, Vec3(0.4, 0.0, 0.3), up),
               glm::normalize(Vec3(-0.4 / 3.0 * 0.6, 1.0, 0.0)), 1e-7));
    Normal stretched = gradientX(0.6);
    stretched.pattern.worldFromPattern = Transform::scale(Vec3(2.0, 1.0, 1.0));
    CHECK(near(perturbedNormal(stretched, Vec3(0.4, 0.0, 0.3), up),
               glm::normalize(Vec3(-0.2 / 3.0 * 0.6, 1.0, 0.0)), 1e-7));
    // Where the ramp wraps between the four points the slope is steep and
    // the other way.
    CHECK(perturbedNormal(gradientX(0.6), Vec3(0.999, 0.0, 0.0), up).x > 0.5);
}

TEST_CASE("bumps, dents and wrinkles add POV-Ray's vector noise", "[pattern][normal]") {
    const PovNoise& noise = PovNoise::tables();
    const Vec3 up(0.0, 0.0, -1.0);
    const Vec3 p(0.31, -1.7, 2.2);
    Normal bumps;
    bumps.amount = 0.8;
    CHECK(near(perturbedNormal(bumps, p, up), glm::normalize(up + 0.8 * noise.dnoise(p))));
    // Pattern space: scaled by 0.1, the noise is taken at 10 p.
    bumps.pattern.worldFromPattern = Transform::scale(Vec3(0.1));
    CHECK(near(perturbedNormal(bumps, p, up), glm::normalize(up + 0.8 * noise.dnoise(10.0 * p))));

    Normal dents;
    dents.kind = Normal::Kind::Dents;
    dents.amount = 2.0;
    const double v = noise.noise(p, 2);
    CHECK(near(perturbedNormal(dents, p, up), glm::normalize(up + v * v * v * 2.0 * noise.dnoise(p))));

    Normal wrinkles;
    wrinkles.kind = Normal::Kind::Wrinkles;
    Vec3 sum(0.0);
    for (int i = 0; i < 10; ++i) sum += glm::abs(noise.dnoise(p * std::ldexp(1.0, i))) / std::ldexp(1.0, i);
    CHECK(near(perturbedNormal(wrinkles, p, up), glm::normalize(up + 0.5 * sum)));
}

TEST_CASE("ripples and waves run from POV-Ray's ten wave sources", "[pattern][normal]") {
    const WaveSources& w = WaveSources::tables();
    for (int i = 0; i < WaveSources::kCount; ++i) {
        CHECK(glm::length(w.sources[static_cast<std::size_t>(i)]) == Approx(1.0));
        // POV-Ray's frequencies: its generator's 15 bits scaled into [0.01, 1.01).
        CHECK(w.frequencies[static_cast<std::size_t>(i)] >= 0.01);
        CHECK(w.frequencies[static_cast<std::size_t>(i)] < 1.01);
    }
    // The first of POV-Ray's generator after -560851967, by hand: its 15
    // bits above the 16th of -560851967 * 1812433253 + 12345 (mod 2^32).
    const std::uint32_t next = static_cast<std::uint32_t>(-560851967) * 1812433253u + 12345u;
    CHECK(w.frequencies[0] == Approx(((next >> 16) & 0x7FFFu) * 0.000030518509476 + 0.01));
    // A ripple is a sum of the ten waves' directions: at a source's own
    // point that source adds nothing (POV-Ray takes its length as 1, its
    // direction is zero).
    Normal ripples;
    ripples.kind = Normal::Kind::Ripples;
    const Vec3 up(0.0, 1.0, 0.0);
    const Vec3 got = perturbedNormal(ripples, Vec3(3.0, 0.2, -1.0), up);
    CHECK(glm::length(got) == Approx(1.0));
    CHECK(!near(got, up, 1e-6));
}

TEST_CASE("A layer's tilted normal lights it and mirrors the ray", "[shading][normal]") {
    // Light straight above a flat floor, a normal tilted by a slope: the
    // diffuse term is the cosine to the tilted normal.
    Texture t;
    t.pigment.color1 = Color{Vec3(1.0), 0.0, 0.0};
    t.finish.ambient = Vec3(0.0);
    t.finish.diffuse = 1.0;
    t.normal = gradientX(0.6);
    SurfaceHit hit;
    hit.position = Vec3(0.4, 0.0, 0.3);
    hit.normal = Vec3(0.0, 1.0, 0.0);
    const Ray ray{Vec3(0.4, 5.0, 0.3), Vec3(0.0, -1.0, 0.0)};
    Light light;
    light.position = Vec3(0.4, 10.0, 0.3);
    const std::vector<Light> lights{light};
    LightSample sample = pointLightSample(light.position, light.color, hit.position);
    const Vec3 c = shadeSurface({hit, t, ray}, lights, ShadingSettings{},
                                [&](const ShadingPoint&) { return std::span<const LightSample>(&sample, 1); },
                                [](const Ray&, int, double) { return Vec3(0.0); });
    const Vec3 tilted = glm::normalize(Vec3(-0.4 / 3.0 * 0.6, 1.0, 0.0));
    CHECK(c.x == Approx(tilted.y).epsilon(1e-9));
    // A mirror direction off a tilted normal stays above the surface.
    const Vec3 grazing = glm::normalize(Vec3(1.0, -0.05, 0.0));
    const Vec3 steep = glm::normalize(Vec3(-0.5, 1.0, 0.0));
    CHECK(glm::dot(mirrorDirection(grazing, steep, hit.normal), hit.normal) >= 0.0);
    CHECK(mirrorDirection(grazing, hit.normal, hit.normal) == reflectDirection(grazing, hit.normal));
}
