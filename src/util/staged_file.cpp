#include "asos/util/staged_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <utility>

namespace asos {
namespace {

namespace fs = std::filesystem;

fs::path folderOf(const fs::path& target) {
    return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// 'path', built by appending (GCC 12 warns falsely about "'" + string).
std::string quoted(const fs::path& path) {
    std::string q = "'";
    q += path.string();
    q += '\'';
    return q;
}

std::string cannotWrite(const fs::path& target, const std::string& why) {
    return "cannot write " + quoted(target) + ": " + why;
}

std::string osReason(int error) { return std::strerror(error); }

// write(2) may take fewer bytes than asked (a signal, a file size limit
// reached part way): go on until all are written or it fails. Returns why it
// failed, empty on success.
std::string writeAll(int fd, const unsigned char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return osReason(errno);
        if (n == 0) return "the file takes no more bytes";
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return {};
}

// A name for a temporary file beside `target`, not yet taken.
fs::path temporaryName(const fs::path& target) {
    static thread_local std::random_device device;
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".tmp-%08x%08x", device(), device());
    std::string name = ".";
    name += target.filename().string();
    name += suffix;
    return folderOf(target) / name;
}

struct NamedFile {
    fs::path path;
    int fd = -1;
    std::string error;
};

// A new, empty, uniquely named file beside `target` (O_EXCL: two writers
// never share one), open for writing.
NamedFile createNamed(const fs::path& target) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        fs::path candidate = temporaryName(target);
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return {std::move(candidate), fd, {}};
        if (errno != EEXIST)
            return {{}, -1, "cannot create a file in " + quoted(folderOf(target)) + ": " + osReason(errno)};
    }
    return {{}, -1, "cannot create a temporary file in " + quoted(folderOf(target))};
}

// fsync, then close, both checked: a full disk or a failing device may show
// only there.
std::string syncAndClose(int fd) {
    std::string error;
    if (::fsync(fd) != 0 && errno != EINVAL) error = osReason(errno);  // EINVAL: a file that cannot sync
    if (::close(fd) != 0 && error.empty()) error = osReason(errno);
    return error;
}

}  // namespace

StagedResult StagedFile::fromBytes(const fs::path& target, std::span<const unsigned char> bytes) {
    // An unnamed file first; a file system without O_TMPFILE gets a named one.
    int fd = ::open(folderOf(target).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (fd >= 0) {
        std::string error = writeAll(fd, bytes.data(), bytes.size());
        if (error.empty() && ::fsync(fd) != 0 && errno != EINVAL) error = osReason(errno);
        if (!error.empty()) {
            ::close(fd);
            return {std::nullopt, cannotWrite(target, error)};
        }
        return {StagedFile(target, fd, {}), {}};
    }
    NamedFile named = createNamed(target);
    if (named.fd < 0) return {std::nullopt, cannotWrite(target, named.error)};
    StagedFile staged(target, -1, named.path);  // removes the file on every failure below
    std::string error = writeAll(named.fd, bytes.data(), bytes.size());
    if (std::string e = syncAndClose(named.fd); error.empty()) error = e;
    if (!error.empty()) return {std::nullopt, cannotWrite(target, error)};
    return {std::move(staged), {}};
}

StagedResult StagedFile::fromWriter(const fs::path& target, FunctionRef<std::string(const fs::path&)> fill) {
    NamedFile named = createNamed(target);
    if (named.fd < 0) return {std::nullopt, cannotWrite(target, named.error)};
    ::close(named.fd);
    StagedFile staged(target, -1, named.path);
    if (std::string e = fill(named.path); !e.empty()) return {std::nullopt, cannotWrite(target, e)};
    const int fd = ::open(named.path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return {std::nullopt, cannotWrite(target, osReason(errno))};
    if (std::string e = syncAndClose(fd); !e.empty()) return {std::nullopt, cannotWrite(target, e)};
    return {std::move(staged), {}};
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : target_(std::move(other.target_)),
      fd_(std::exchange(other.fd_, -1)),
      named_(std::exchange(other.named_, {})) {}

StagedFile& StagedFile::operator=(StagedFile&& other) noexcept {
    if (this != &other) {
        discard();
        target_ = std::move(other.target_);
        fd_ = std::exchange(other.fd_, -1);
        named_ = std::exchange(other.named_, {});
    }
    return *this;
}

StagedFile::~StagedFile() { discard(); }

void StagedFile::discard() {
    if (fd_ >= 0) ::close(std::exchange(fd_, -1));
    if (!named_.empty()) {
        ::unlink(named_.c_str());
        named_.clear();
    }
}

std::string StagedFile::commit() {
    if (fd_ >= 0) {
        // Give the unnamed file a temporary name (linkat cannot replace a
        // file), closed, then rename it: the name exists only in between.
        const std::string self = "/proc/self/fd/" + std::to_string(fd_);
        std::string linkError;
        for (int attempt = 0; attempt < 16 && named_.empty(); ++attempt) {
            fs::path candidate = temporaryName(target_);
            if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, candidate.c_str(), AT_SYMLINK_FOLLOW) == 0)
                named_ = std::move(candidate);
            else if (errno != EEXIST) {
                linkError = osReason(errno);
                break;
            }
        }
        const int fd = std::exchange(fd_, -1);
        const bool closed = ::close(fd) == 0;
        const int closeErrno = errno;
        if (named_.empty())
            return cannotWrite(target_, linkError.empty() ? "cannot name the temporary file" : linkError);
        if (!closed) {
            discard();
            return cannotWrite(target_, osReason(closeErrno));
        }
    }
    if (named_.empty()) return cannotWrite(target_, "nothing to commit");
    if (::rename(named_.c_str(), target_.c_str()) != 0) {
        const int e = errno;
        discard();
        return cannotWrite(target_, osReason(e));
    }
    named_.clear();
    // Make the rename itself durable. The new file is in place either way,
    // so a folder that cannot be synced is not a failure of the write.
    if (const int dir = ::open(folderOf(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return {};
}

std::string checkWritable(const fs::path& target) {
    const fs::path folder = folderOf(target);
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0) return cannotWrite(target, "folder " + quoted(folder) + ": " + osReason(errno));
    if (!S_ISDIR(st.st_mode)) return cannotWrite(target, quoted(folder) + " is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return cannotWrite(target, "folder " + quoted(folder) + ": " + osReason(errno));
    if (::stat(target.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return cannotWrite(target, "it is a folder");
        // A device or a FIFO would be replaced by the file renamed over it
        // (as root, /dev/full by a plain file): refused, as a folder is.
        if (!S_ISREG(st.st_mode))
            return cannotWrite(target, "it is not a regular file (a device, a FIFO or a socket)");
    }
    return {};
}

}  // namespace asos
