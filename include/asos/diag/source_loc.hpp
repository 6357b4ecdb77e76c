#pragma once
// A position in a scene file. Every record of the scene description carries
// one, so that an error found long after parsing still points at the source.
#include <memory>
#include <string>

namespace asos {

struct SourceLoc {
    std::shared_ptr<const std::string> file;  // path as given or resolved; null when synthetic
    int line = 0;                             // 1-based; 0 when unknown
    int column = 0;                           // 1-based, in bytes

    const std::string& fileName() const {
        static const std::string none = "<none>";
        return file ? *file : none;
    }
};

}  // namespace asos
