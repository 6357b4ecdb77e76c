// The one translation unit that includes OpenImageIO.
#include "asos/image/image_io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <span>
#include <system_error>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "asos/image/encoding.hpp"
#include "asos/util/function_ref.hpp"
#include "src/image/pfm.hpp"

namespace asos {
namespace {

namespace fs = std::filesystem;

// A writer of our own, for a format OpenImageIO cannot write: linear float
// samples (its row in the table allows float only), interleaved, top row
// first, into `file`. Returns why it failed, empty on success.
using OwnWriter = std::string (*)(const fs::path& file, int width, int height, int channels,
                                  std::span<const float> samples);

struct FormatCaps {
    const char* extension;
    bool uint8, uint16, half, float32;
    SampleFormat preferred;
    OwnWriter writer = nullptr;  // null: OpenImageIO writes it
};

// What each format we know can store. An extension not listed here is still
// written when OpenImageIO has a writer for it, as an 8-bit integer format.
constexpr FormatCaps kFormats[] = {
    {".png", true, true, false, false, SampleFormat::UInt8},
    {".tif", true, true, true, true, SampleFormat::UInt8},
    {".tiff", true, true, true, true, SampleFormat::UInt8},
    {".jpg", true, false, false, false, SampleFormat::UInt8},
    {".jpeg", true, false, false, false, SampleFormat::UInt8},
    {".bmp", true, false, false, false, SampleFormat::UInt8},
    {".tga", true, true, false, false, SampleFormat::UInt8},
    {".ppm", true, true, false, false, SampleFormat::UInt8},
    {".pnm", true, true, false, false, SampleFormat::UInt8},
    {".webp", true, false, false, false, SampleFormat::UInt8},
    {".exr", false, false, true, true, SampleFormat::Float},
    {".hdr", false, false, false, true, SampleFormat::Float},
    {".pfm", false, false, false, true, SampleFormat::Float, writePfm},
};

// writeImage hands our own writers float samples only.
static_assert(std::ranges::all_of(kFormats, [](const FormatCaps& f) {
    return !f.writer || (!f.uint8 && !f.uint16 && !f.half && f.float32);
}));

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

const FormatCaps* findFormat(const std::string& ext) {
    for (const FormatCaps& f : kFormats)
        if (ext == f.extension) return &f;
    return nullptr;
}

const char* formatName(SampleFormat f) {
    switch (f) {
        case SampleFormat::UInt8: return "8-bit";
        case SampleFormat::UInt16: return "16-bit";
        case SampleFormat::Half: return "half-float";
        case SampleFormat::Float: return "float";
        case SampleFormat::Auto: break;
    }
    return "default";
}

bool isInteger(SampleFormat f) { return f == SampleFormat::UInt8 || f == SampleFormat::UInt16; }

struct ResolvedFormat {
    SampleFormat samples = SampleFormat::Auto;
    OwnWriter writer = nullptr;  // null: OpenImageIO writes it
    std::string error{};         // empty when the format can hold the samples
};

// Resolves Auto and checks that the format can hold the samples.
ResolvedFormat resolveFormat(const fs::path& path, SampleFormat requested) {
    const std::string ext = lowerExtension(path);
    if (ext.empty())
        return {.error = "cannot choose an image format for '" + path.string() +
                         "': the file name has no extension (use .png, .exr, .tif, ...)"};
    const FormatCaps* caps = findFormat(ext);
    if (!caps) {
        // Unknown to us: ask OpenImageIO whether it has a writer.
        auto probe = OIIO::ImageOutput::create(path.string());
        if (!probe) {
            (void)OIIO::geterror();
            return {.error = "cannot write '" + path.string() + "': no image format for extension '" + ext +
                             "' (use .png, .exr, .tif, .jpg, ...)"};
        }
        const SampleFormat samples = requested == SampleFormat::Auto ? SampleFormat::UInt8 : requested;
        if (!isInteger(samples))
            return {.error = "cannot write " + std::string(formatName(samples)) + " samples to '" + ext +
                             "' files (use .exr or .tif)"};
        return {.samples = samples};
    }
    const SampleFormat samples = requested == SampleFormat::Auto ? caps->preferred : requested;
    const bool supported = (samples == SampleFormat::UInt8 && caps->uint8) ||
                           (samples == SampleFormat::UInt16 && caps->uint16) ||
                           (samples == SampleFormat::Half && caps->half) ||
                           (samples == SampleFormat::Float && caps->float32);
    if (!supported) return {.error = "'" + ext + "' files cannot store " + formatName(samples) + " samples"};
    return {.samples = samples, .writer = caps->writer};
}

OIIO::TypeDesc typeOf(SampleFormat f) {
    switch (f) {
        case SampleFormat::UInt8: return OIIO::TypeDesc::UINT8;
        case SampleFormat::UInt16: return OIIO::TypeDesc::UINT16;
        case SampleFormat::Half: return OIIO::TypeDesc::HALF;
        default: return OIIO::TypeDesc::FLOAT;
    }
}

// A new, empty, uniquely named file next to `path` (created with O_EXCL so
// that two writers never share it). Returns an empty path and sets `error`
// when the directory cannot take it.
fs::path createTemporaryFile(const fs::path& path, std::string& error) {
    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::random_device device;
    for (int attempt = 0; attempt < 16; ++attempt) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, ".tmp-%08x%08x", device(), device());
        std::string name = ".";
        name += path.filename().string();
        name += suffix;
        const fs::path candidate = dir / name;
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return candidate;
        }
        if (errno != EEXIST) {
            error = "cannot create a file in '" + dir.string() + "': " + std::strerror(errno);
            return {};
        }
    }
    error = "cannot create a temporary file in '" + dir.string() + "'";
    return {};
}

// Writes `path` through `fill`, which writes the whole file at the path it is
// given and returns why it failed (empty on success): that path is a new
// temporary file beside `path`, renamed onto it only when `fill` succeeded and
// removed otherwise. Every format, OpenImageIO's or our own, goes through here.
IoStatus writeThroughTemporary(const fs::path& path, FunctionRef<std::string(const fs::path&)> fill) {
    std::string error;
    const fs::path temporary = createTemporaryFile(path, error);
    if (temporary.empty()) return {"cannot write '" + path.string() + "': " + error};
    // Removes the temporary file however this returns, a throw included,
    // unless it has taken the name.
    struct Discard {
        const fs::path& file;
        bool renamed = false;
        ~Discard() {
            std::error_code ignored;
            if (!renamed) fs::remove(file, ignored);
        }
    } discard{temporary};
    if (std::string e = fill(temporary); !e.empty()) return {"cannot write '" + path.string() + "': " + e};
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) return {"cannot write '" + path.string() + "': " + ec.message()};
    discard.renamed = true;
    return {};
}

std::string oiioError(const OIIO::ImageOutput& out) {
    std::string e = out.geterror();
    return e.empty() ? OIIO::geterror() : e;
}

}  // namespace

IoStatus checkOutputPath(const fs::path& path, SampleFormat format) {
    return {resolveFormat(path, format).error};
}

IoStatus writeImage(const Image& image, const fs::path& path, const WriteOptions& options) {
    if (image.width() <= 0 || image.height() <= 0)
        return {"cannot write an empty image to '" + path.string() + "'"};
    const ResolvedFormat resolved = resolveFormat(path, options.format);
    if (!resolved.error.empty()) return {resolved.error};
    const SampleFormat format = resolved.samples;

    Transfer transfer = options.transfer;
    if (transfer == Transfer::Auto) transfer = isInteger(format) ? Transfer::Srgb : Transfer::Linear;

    // Convert the samples ourselves so that the rounding is exactly POV-Ray's
    // (asos/image/encoding.hpp) rather than a library's.
    const std::vector<float>& src = image.data();
    std::vector<std::uint8_t> u8;
    std::vector<std::uint16_t> u16;
    std::vector<float> f32;
    const void* pixels = nullptr;
    auto value = [&](float v) -> double {
        switch (transfer) {
            case Transfer::Srgb: return workingToSrgb(v, options.assumedGamma);
            case Transfer::Linear: return workingToLinear(v, options.assumedGamma);
            default: return v;
        }
    };
    if (format == SampleFormat::UInt8 || format == SampleFormat::UInt16) {
        const double scale = format == SampleFormat::UInt8 ? 255.0 : 65535.0;
        auto code = [&](float v) {
            const double x = value(v);
            return std::lround(std::isnan(x) ? 0.0 : std::clamp(x, 0.0, 1.0) * scale);
        };
        if (format == SampleFormat::UInt8) {
            u8.resize(src.size());
            for (std::size_t i = 0; i < src.size(); ++i) u8[i] = static_cast<std::uint8_t>(code(src[i]));
            pixels = u8.data();
        } else {
            u16.resize(src.size());
            for (std::size_t i = 0; i < src.size(); ++i) u16[i] = static_cast<std::uint16_t>(code(src[i]));
            pixels = u16.data();
        }
    } else {
        f32.resize(src.size());
        for (std::size_t i = 0; i < src.size(); ++i) f32[i] = static_cast<float>(value(src[i]));
        pixels = f32.data();
    }

    if (resolved.writer) {
        // Our own writer: its format holds float only (the static_assert on
        // kFormats), so `f32` is filled.
        return writeThroughTemporary(path, [&](const fs::path& temporary) {
            return resolved.writer(temporary, image.width(), image.height(), image.channels(), f32);
        });
    }

    OIIO::ImageSpec spec(image.width(), image.height(), image.channels(), typeOf(format));
    spec.channelnames = image.channelNames();
    spec.attribute("oiio:ColorSpace", transfer == Transfer::Srgb ? "sRGB" : "Linear");
    spec.attribute("Software", "asos");

    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) return {"cannot write '" + path.string() + "': " + OIIO::geterror()};
    return writeThroughTemporary(path, [&](const fs::path& temporary) -> std::string {
        if (!out->open(temporary.string(), spec)) return oiioError(*out);
        if (!out->write_image(typeOf(format), pixels)) {
            const std::string e = oiioError(*out);
            out->close();
            return e;
        }
        if (!out->close()) return oiioError(*out);
        return {};
    });
}

ReadResult readImage(const fs::path& path) {
    ReadResult result;
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
        result.error = "cannot read '" + path.string() + "': " + OIIO::geterror();
        return result;
    }
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<std::string> names = spec.channelnames;
    names.resize(spec.nchannels);
    for (int c = 0; c < spec.nchannels; ++c)
        if (names[c].empty()) names[c] = "channel" + std::to_string(c);
    Image image(spec.width, spec.height, names);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data().data())) {
        result.error = "cannot read '" + path.string() + "': " + in->geterror();
        return result;
    }
    in->close();
    result.image = std::move(image);
    return result;
}

}  // namespace asos
