#pragma once
// A file written whole before it takes its name: the bytes go to a new
// temporary file in the target's folder, every write, the fsync and the close
// checked, and only commit() puts it in place (rename(2), then an fsync of the
// folder). Until then the target keeps its old contents; a file never
// committed is removed. So a full disk, a file size limit or a failing codec
// leaves the old file as it was, and no temporary file behind.
//
// Where the file system allows it (Linux's O_TMPFILE: ext4, xfs, btrfs,
// tmpfs), the temporary file has no name at all until commit() links it a
// moment before the rename, so even SIGKILL during the write leaves nothing.
// Elsewhere it is a named `.NAME.tmp-XXXXXXXXXXXXXXXX` beside the target.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "asos/util/function_ref.hpp"

namespace asos {

class StagedFile;

struct StagedResult;

class StagedFile {
public:
    // Writes `bytes` to a new temporary file beside `target`.
    static StagedResult fromBytes(const std::filesystem::path& target, std::span<const unsigned char> bytes);

    // For a writer that opens the file itself (a codec without an in-memory
    // form): `fill` writes the whole file at the named temporary path it is
    // given and returns why it failed (empty on success); the file is then
    // synced and its close checked here.
    static StagedResult fromWriter(const std::filesystem::path& target,
                                   FunctionRef<std::string(const std::filesystem::path&)> fill);

    StagedFile(StagedFile&& other) noexcept;
    StagedFile& operator=(StagedFile&& other) noexcept;
    StagedFile(const StagedFile&) = delete;
    StagedFile& operator=(const StagedFile&) = delete;
    ~StagedFile();  // removes the temporary file unless committed

    // Puts the file in place of the target. Returns why it could not (the
    // target then keeps its old contents), empty on success.
    std::string commit();

    const std::filesystem::path& target() const { return target_; }

private:
    StagedFile(std::filesystem::path target, int fd, std::filesystem::path named)
        : target_(std::move(target)), fd_(fd), named_(std::move(named)) {}
    void discard();

    std::filesystem::path target_;
    int fd_ = -1;                  // the unnamed (O_TMPFILE) file, open until commit; -1 otherwise
    std::filesystem::path named_;  // the named temporary file, when there is one
};

struct StagedResult {
    std::optional<StagedFile> file;
    std::string error;  // why it could not be written (file name and the OS's reason), when `file` is empty
};

// Whether `target` can be written: its folder exists, is a folder and takes
// new files, and `target` itself is not a folder, a device, a FIFO or a socket
// (a missing target is fine: a symbolic link counts as what it names).
// Returns why not, empty when it can. Checked before work that would be lost.
std::string checkWritable(const std::filesystem::path& target);

}  // namespace asos
