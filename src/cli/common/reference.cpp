#include "cli/common/reference.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <system_error>

#include "asos/image/image_io.hpp"
#include "asos/testing/culled_grid_light.hpp"

namespace asos::cli {

namespace {

// FNV-1a, 64 bits: stable across runs and builds, which std::hash is not.
class Fnv1a {
public:
    void add(std::string_view bytes) {
        for (const unsigned char c : bytes) {
            hash_ ^= c;
            hash_ *= 0x100000001b3ULL;
        }
        // A separator, so that ("ab", "c") and ("a", "bc") differ.
        hash_ ^= 0xff;
        hash_ *= 0x100000001b3ULL;
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace

RenderSettings referenceRenderSettings(const ReferenceSettings& r) {
    RenderSettings s;
    s.method = RenderMethod::Jitter;
    s.width = r.width;
    s.height = r.height;
    s.samples = r.eyeSamples;
    s.lightMethod = LightMethod::Grid;
    s.lightSamples = r.lightSamples;
    // The light's true area, stratified: the lattice's jitter would widen it.
    s.areaLightSampler = culledGridAreaLightSamples;
    s.threads = r.threads;
    return s;
}

SceneDescription withEveryLightPoint(SceneDescription description) {
    for (Light& light : description.lights)
        if (light.area) {
            light.area->adaptive.reset();
            light.area->jitter = true;
        }
    return description;
}

std::optional<std::filesystem::path> referenceCacheFolder() {
    if (const char* own = std::getenv("ASOS_REFERENCE_CACHE"); own && *own) return std::filesystem::path(own);
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "asos" / "references";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "asos" / "references";
    return std::nullopt;
}

std::string referenceFileName(const std::filesystem::path& scene, const std::string& sceneText,
                              const ReferenceSettings& settings, const std::vector<std::string>& defines,
                              double clock) {
    Fnv1a h;
    h.add("asos reference 2");  // the recipe's version: bump when the reference's method changes
    h.add(sceneText);
    h.add(std::to_string(settings.eyeSamples) + " " + std::to_string(settings.lightSamples));
    for (const std::string& d : defines) h.add(d);
    char clockText[32];
    std::snprintf(clockText, sizeof clockText, "%.17g", clock);
    h.add(clockText);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.value()));
    return scene.stem().string() + "-" + hex + "-" + std::to_string(settings.width) + "x" +
           std::to_string(settings.height) + ".exr";
}

ReferenceImage loadOrRenderReference(const SceneDescription& description, const std::filesystem::path& scene,
                                     const std::string& sceneText, const ReferenceSettings& settings,
                                     const std::vector<std::string>& defines, double clock,
                                     const std::optional<std::filesystem::path>& cacheFolder, bool useCached,
                                     const std::function<void(const TileProgress&)>& progress) {
    ReferenceImage out;
    if (cacheFolder) out.cached = *cacheFolder / referenceFileName(scene, sceneText, settings, defines, clock);
    if (useCached && !out.cached.empty() && std::filesystem::is_regular_file(out.cached)) {
        ReadResult r = readImage(out.cached);
        if (r.ok() && r.image.width() == settings.width && r.image.height() == settings.height &&
            r.image.channels() >= 3) {
            out.image = std::move(r.image);
            out.fromCache = true;
            return out;
        }
    }
    Diagnostics diagnostics;
    const auto start = std::chrono::steady_clock::now();
    RenderSettings renderSettings = referenceRenderSettings(settings);
    renderSettings.progress = progress;
    std::optional<RenderOutput> rendered = render(withEveryLightPoint(description), renderSettings, diagnostics);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!rendered) {
        for (const Diagnostic& d : diagnostics.all()) out.error += formatDiagnostic(d);
        if (out.error.empty()) out.error = "the scene cannot be rendered";
        return out;
    }
    out.image = std::move(rendered->color);
    if (!out.cached.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(out.cached.parent_path(), ec);
        WriteOptions linear;
        linear.format = SampleFormat::Float;
        if (ec || !writeImage(out.image, out.cached, linear).ok()) out.cached.clear();
    }
    return out;
}

}  // namespace asos::cli
