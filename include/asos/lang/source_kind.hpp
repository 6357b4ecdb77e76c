#pragma once
// What a path names, asked before it is read as a scene or an include: only
// a regular file is opened (a FIFO would block, /dev/zero never end). The
// interpreter and the command line word it each for their own messages.
#include <sys/stat.h>

#include <cerrno>
#include <filesystem>

namespace asos::lang {

enum class SourceKind { Regular, Unreachable, Folder, Fifo, Device, Other };

struct SourceCheck {
    SourceKind kind = SourceKind::Unreachable;
    int error = 0;  // Unreachable: stat's errno (missing, no permission, ...)
};

inline SourceCheck checkSource(const std::filesystem::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return {SourceKind::Unreachable, errno};
    if (S_ISREG(st.st_mode)) return {SourceKind::Regular};
    if (S_ISDIR(st.st_mode)) return {SourceKind::Folder};
    if (S_ISFIFO(st.st_mode)) return {SourceKind::Fifo};
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return {SourceKind::Device};
    return {SourceKind::Other};
}

}  // namespace asos::lang
