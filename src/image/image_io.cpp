// The one translation unit that includes OpenImageIO.
#include "asos/image/image_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "asos/image/encoding.hpp"
#include "asos/util/staged_file.hpp"
#include "src/image/pfm.hpp"

namespace asos {
namespace {

namespace fs = std::filesystem;

// An encoder of our own, for a format OpenImageIO cannot write: linear float
// samples (its row in the table allows float only), interleaved, top row
// first, as the file's bytes.
using OwnWriter = PfmBytes (*)(int width, int height, int channels, std::span<const float> samples);

struct FormatCaps {
    const char* extension;
    bool uint8, uint16, half, float32;
    SampleFormat preferred;
    OwnWriter writer = nullptr;  // null: OpenImageIO writes it
    // OpenImageIO's writer writes the file itself rather than into memory:
    // 2.4's TIFF writer takes an IOProxy but writes a file without its image
    // size through one (libtiff reads back what it wrote).
    bool writesFile = false;
};

// What each format we know can store. An extension not listed here is still
// written when OpenImageIO has a writer for it, as an 8-bit integer format.
constexpr FormatCaps kFormats[] = {
    {".png", true, true, false, false, SampleFormat::UInt8},
    {".tif", true, true, true, true, SampleFormat::UInt8, nullptr, true},
    {".tiff", true, true, true, true, SampleFormat::UInt8, nullptr, true},
    {".jpg", true, false, false, false, SampleFormat::UInt8},
    {".jpeg", true, false, false, false, SampleFormat::UInt8},
    {".bmp", true, false, false, false, SampleFormat::UInt8},
    {".tga", true, true, false, false, SampleFormat::UInt8},
    {".ppm", true, true, false, false, SampleFormat::UInt8},
    {".pnm", true, true, false, false, SampleFormat::UInt8},
    {".webp", true, false, false, false, SampleFormat::UInt8},
    {".exr", false, false, true, true, SampleFormat::Float},
    {".hdr", false, false, false, true, SampleFormat::Float},
    {".pfm", false, false, false, true, SampleFormat::Float, encodePfm},
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
    bool writesFile = false;     // FormatCaps::writesFile
    bool inTable = false;        // one of kFormats
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
    return {.samples = samples, .writer = caps->writer, .writesFile = caps->writesFile, .inTable = true};
}

OIIO::TypeDesc typeOf(SampleFormat f) {
    switch (f) {
        case SampleFormat::UInt8: return OIIO::TypeDesc::UINT8;
        case SampleFormat::UInt16: return OIIO::TypeDesc::UINT16;
        case SampleFormat::Half: return OIIO::TypeDesc::HALF;
        default: return OIIO::TypeDesc::FLOAT;
    }
}

// A writer's error on one line: some (jpeg2000) add lines of their own.
std::string oneLine(std::string e) {
    while (!e.empty() && e.back() == '\n') e.pop_back();
    for (std::size_t at = e.find('\n'); at != std::string::npos; at = e.find('\n', at)) e.replace(at, 1, "; ");
    return e;
}

std::string oiioError(const OIIO::ImageOutput& out) {
    std::string e = out.geterror();
    return oneLine(e.empty() ? OIIO::geterror() : e);
}

// Opens, writes and closes `out` (given its ioproxy, if any, already): every
// step checked, and, for a writer outside asos's table (`tableFormat`
// false), its error state after close too, since some (jpeg2000) report a
// failed encode only there. (The TIFF writer leaves an error there about
// its Exif directory on files it writes whole: the table's writers report
// failures by their return values.) Returns why it failed, empty on success.
std::string writeAll(OIIO::ImageOutput& out, const std::string& name, const OIIO::ImageSpec& spec,
                     OIIO::TypeDesc type, const void* pixels, bool tableFormat) {
    if (!out.open(name, spec)) return oiioError(out);
    if (!out.write_image(type, pixels)) {
        const std::string e = oiioError(out);
        out.close();
        return e;
    }
    if (!out.close()) return oiioError(out);
    if (!tableFormat && out.has_error()) return oneLine(out.geterror());
    return {};
}

struct Encoded {
    std::vector<unsigned char> bytes;
    std::string error;
};

// The file's bytes, encoded in memory by a writer that can write through an
// IOProxy; `out` must support("ioproxy").
Encoded encodeInMemory(OIIO::ImageOutput& out, const fs::path& path, const OIIO::ImageSpec& spec,
                       OIIO::TypeDesc type, const void* pixels, bool tableFormat) {
    Encoded e;
    OIIO::Filesystem::IOVecOutput memory(e.bytes);
    out.set_ioproxy(&memory);
    e.error = writeAll(out, path.string(), spec, type, pixels, tableFormat);
    out.set_ioproxy(nullptr);
    return e;
}

}  // namespace

IoStatus checkOutputPath(const fs::path& path, SampleFormat format, int width, int height) {
    const ResolvedFormat resolved = resolveFormat(path, format);
    if (!resolved.error.empty()) return {resolved.error};
    if (std::string e = checkWritable(path); !e.empty()) return {e};
    if (resolved.writer || findFormat(lowerExtension(path))) return {};
    // A format outside the table: OpenImageIO has a writer, but some fail on
    // some images and say so only after close (jpeg2000 on small ones), so
    // encode a grey image of the size in memory first.
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out || !out->supports("ioproxy")) return {};
    const std::size_t count = std::size_t(std::max(width, 1)) * std::size_t(std::max(height, 1)) * 3;
    const SampleFormat samples = resolved.samples;
    std::vector<std::uint16_t> grey(count, samples == SampleFormat::UInt8 ? 128 : 32768);
    std::vector<std::uint8_t> grey8(samples == SampleFormat::UInt8 ? count : 0, 128);
    const OIIO::ImageSpec spec(std::max(width, 1), std::max(height, 1), 3, typeOf(samples));
    const Encoded probe = encodeInMemory(*out, path, spec, typeOf(samples),
                                         samples == SampleFormat::UInt8 ? static_cast<const void*>(grey8.data())
                                                                        : static_cast<const void*>(grey.data()),
                                         false);
    if (!probe.error.empty() || probe.bytes.empty())
        return {"cannot write '" + path.string() + "': the " + out->format_name() + " writer fails on a " +
                std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image" +
                (probe.error.empty() ? std::string() : ": " + probe.error)};
    return {};
}

StagedResult stageImage(const Image& image, const fs::path& path, const WriteOptions& options) {
    if (image.width() <= 0 || image.height() <= 0)
        return {std::nullopt, "cannot write an empty image to '" + path.string() + "'"};
    const ResolvedFormat resolved = resolveFormat(path, options.format);
    if (!resolved.error.empty()) return {std::nullopt, resolved.error};
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
        // Our own encoder: its format holds float only (the static_assert on
        // kFormats), so `f32` is filled.
        const PfmBytes encoded = resolved.writer(image.width(), image.height(), image.channels(), f32);
        if (!encoded.error.empty()) return {std::nullopt, "cannot write '" + path.string() + "': " + encoded.error};
        return StagedFile::fromBytes(path, encoded.bytes);
    }

    OIIO::ImageSpec spec(image.width(), image.height(), image.channels(), typeOf(format));
    spec.channelnames = image.channelNames();
    spec.attribute("oiio:ColorSpace", transfer == Transfer::Srgb ? "sRGB" : "Linear");
    spec.attribute("Software", "asos");

    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) return {std::nullopt, "cannot write '" + path.string() + "': " + OIIO::geterror()};
    if (out->supports("ioproxy") && !resolved.writesFile) {
        // Encoded in memory, then written by StagedFile with every write
        // checked: a codec never meets a full disk (libjpeg would end the
        // process there).
        const Encoded encoded = encodeInMemory(*out, path, spec, typeOf(format), pixels, resolved.inTable);
        if (!encoded.error.empty()) return {std::nullopt, "cannot write '" + path.string() + "': " + encoded.error};
        return StagedFile::fromBytes(path, encoded.bytes);
    }
    // A writer that only writes files itself: it writes the temporary file,
    // which is then synced and checked.
    return StagedFile::fromWriter(path, [&](const fs::path& temporary) {
        return writeAll(*out, temporary.string(), spec, typeOf(format), pixels, resolved.inTable);
    });
}

IoStatus writeImage(const Image& image, const fs::path& path, const WriteOptions& options) {
    StagedResult staged = stageImage(image, path, options);
    if (!staged.file) return {staged.error};
    return {staged.file->commit()};
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
