#pragma once
// The canonical dump of a scene description: every value fully evaluated, in
// a fixed order, every number written so that it reads back to the same bits,
// each record preceded by a comment with its source location. The dump is
// itself a scene in our language, and parse → dump → parse → dump is a fixed
// point: an object's shape is written in object space, then `matrix` with its
// world-from-object transform, then its texture, whose pigment carries its
// own full transform (a pigment written after a transform is not moved by it).
#include <iosfwd>
#include <string>

#include "asos/scene/description.hpp"

namespace asos {

struct DumpOptions {
    bool locations = true;  // the "// file:line:col" comments
};

void writeDump(std::ostream& out, const SceneDescription& scene, const DumpOptions& options = {});
std::string dumpScene(const SceneDescription& scene, const DumpOptions& options = {});

}  // namespace asos
