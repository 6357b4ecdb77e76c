#pragma once
// Image files through OpenImageIO (src/image/image_io.cpp is the only
// translation unit that includes it), and PFM, which OpenImageIO 2.4 reads
// but cannot write, through a writer of our own (src/image/pfm.cpp). Nothing
// here prints: every failure comes back as a message.
#include <filesystem>
#include <optional>
#include <string>

#include "asos/image/image.hpp"
#include "asos/util/staged_file.hpp"

namespace asos {

// How samples are stored. Auto picks by extension: 8-bit for .png, .tif,
// .jpg and the other integer formats, 32-bit float for .exr, .hdr and .pfm.
enum class SampleFormat { Auto, UInt8, UInt16, Half, Float };

// How values are encoded. Auto: integer formats get the sRGB transfer
// function (as POV-Ray 3.7 writes them, asos/image/encoding.hpp), float
// formats stay linear. Raw writes the values as they are (clipped and
// quantised for integer formats): for images already in display values, such
// as the samples heat map.
enum class Transfer { Auto, Srgb, Linear, Raw };

struct WriteOptions {
    SampleFormat format = SampleFormat::Auto;
    Transfer transfer = Transfer::Auto;
    // The scene's working gamma (GlobalSettings::assumedGamma); none: gamma
    // correction off, values written as they are (asos/image/encoding.hpp).
    std::optional<double> assumedGamma = 1.0;
};

struct IoStatus {
    std::string error;  // empty on success
    bool ok() const { return error.empty(); }
};

// Encodes `image` for `path`, choosing the file format by extension, and
// writes it to a staged file beside `path` (asos/util/staged_file.hpp): in
// place only when committed, so a failed or interrupted write never touches
// the old file. Every format whose OpenImageIO writer takes an IOProxy (all
// in the table in image_io.cpp, and most others) is encoded in memory and
// its bytes written with every write checked; PFM is our own encoder; a
// writer without IOProxy support writes the temporary file itself, which is
// then synced and checked. Integer formats encode every channel; linear
// float formats keep the channel names (EXR). PFM holds 3 channels (RGB) or
// 1 (grey): any other count, an alpha included, is an error.
StagedResult stageImage(const Image& image, const std::filesystem::path& path, const WriteOptions& options = {});

// stageImage, then commit.
IoStatus writeImage(const Image& image, const std::filesystem::path& path,
                    const WriteOptions& options = {});

// Whether asos can write a width x height image to `path`: its extension
// names a format asos can write (OpenImageIO's or PFM) that can store the
// given sample format, its folder takes new files (checkWritable), and, for
// a format outside asos's own table, the writer encodes such an image
// without error. Empty error when it can.
IoStatus checkOutputPath(const std::filesystem::path& path, SampleFormat format = SampleFormat::Auto,
                         int width = 64, int height = 64);

struct ReadResult {
    Image image;
    std::string error;  // empty on success
    bool ok() const { return error.empty(); }
};

// Reads the first subimage as float, values as stored (integer formats scaled
// to [0, 1], no colour conversion): a PNG reads back its encoded values.
ReadResult readImage(const std::filesystem::path& path);

}  // namespace asos
