#pragma once
// Golden renders: a scene file through the whole pipeline (interpreter,
// renderer), and the comparison of an image with its reference PNG by
// OpenImageIO's test-suite thresholds (compareImages). References are
// rewritten only by the golden switch (goldens.hpp), and then only those the
// caller owns; a failing comparison never rewrites one, and leaves the
// rendered and difference images in the build tree (goldenOutput).
#include <catch2/catch.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "asos/image/image_io.hpp"
#include "asos/testing/image_comparison.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "goldens.hpp"

namespace asos::test {

// A rendered scene and how `asos render` writes it: in the scene's working
// gamma (none for a scene older than 3.7 without assumed_gamma).
struct RenderedScene {
    Image color;
    WriteOptions encoding;
};

// Renders `scene` at the settings' size on two threads; `defines` are
// declared before the scene runs (as -D does).
inline RenderedScene renderSceneForFile(const std::filesystem::path& scene, RenderSettings settings,
                                        std::vector<std::pair<std::string, std::string>> defines = {}) {
    lang::InterpreterOptions options;
    options.imageWidth = settings.width;
    options.imageHeight = settings.height;
    for (auto& [name, value] : defines) options.defines.push_back({name, value});
    Diagnostics diagnostics;
    const std::optional<SceneDescription> description = lang::interpretFile(scene, options, diagnostics);
    for (const Diagnostic& d : diagnostics.all()) UNSCOPED_INFO(formatDiagnostic(d));
    REQUIRE(description);
    settings.threads = 2;
    std::optional<RenderOutput> out = render(*description, settings, diagnostics);
    REQUIRE(out);
    return {std::move(out->color), {.assumedGamma = description->globals.assumedGamma}};
}

// The image alone, for scenes whose working gamma is 1 (the default
// encoding).
inline Image renderSceneFile(const std::filesystem::path& scene, RenderSettings settings,
                             std::vector<std::pair<std::string, std::string>> defines = {}) {
    return renderSceneForFile(scene, std::move(settings), std::move(defines)).color;
}

// Writes `rendered` as PNG in its encoding (the comparison reads the file's
// values back) and compares it with `reference`, which is first rewritten
// from it when updating and `ownReference` (references made by another
// program are not ours), by OpenImageIO's thresholds unless others are given.
// The rendered image and the difference stay only when they differ.
inline void compareWithReference(const RenderedScene& rendered, const std::filesystem::path& reference,
                                 bool ownReference = true, const CompareThresholds& thresholds = {}) {
    const std::filesystem::path ours = goldenOutput(reference);
    const std::filesystem::path diff = std::filesystem::path(ours).replace_extension(".diff.png");
    std::filesystem::remove(diff);
    REQUIRE(writeImage(rendered.color, ours, rendered.encoding).ok());
    if (ownReference && updatingGoldens())
        std::filesystem::copy_file(ours, reference, std::filesystem::copy_options::overwrite_existing);
    const ReadResult mine = readImage(ours);
    const ReadResult theirs = readImage(reference);
    INFO("reference " << reference.string() << ": " << theirs.error);
    REQUIRE(mine.ok());
    REQUIRE(theirs.ok());
    const ImageComparison cmp = compareImages(mine.image, theirs.image, thresholds);
    if (!cmp.passed && cmp.error.empty())
        (void)writeImage(absoluteDifference(mine.image, theirs.image), diff, {.transfer = Transfer::Raw});
    INFO(reference.filename().string() << ": " << cmp.summary() << "; rendered " << ours.string()
                                       << ", difference " << diff.string());
    CHECK(cmp.passed);
    if (cmp.passed) std::filesystem::remove(ours);
}

// An image in the default encoding (working gamma 1).
inline void compareWithReference(const Image& rendered, const std::filesystem::path& reference,
                                 bool ownReference = true, const CompareThresholds& thresholds = {}) {
    compareWithReference(RenderedScene{rendered, {}}, reference, ownReference, thresholds);
}

}  // namespace asos::test
