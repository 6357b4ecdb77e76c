// Where POV-Ray keeps its include files on this machine: what its own
// configuration says (Library_Path=… and +L… lines of povray.ini), then the
// folders a package installs.
#include <cstdlib>
#include <fstream>

#include "asos/lang/interpreter.hpp"

namespace asos::lang {

namespace {

std::string trimmed(std::string s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

// The folders a povray.ini names: `Library_Path=DIR` (any case, the value
// maybe quoted) and `+LDIR`; `;` starts a comment.
std::vector<std::filesystem::path> iniLibraryPaths(const std::filesystem::path& ini) {
    std::vector<std::filesystem::path> paths;
    std::ifstream in(ini);
    std::string line;
    while (std::getline(in, line)) {
        if (const auto comment = line.find(';'); comment != std::string::npos) line.erase(comment);
        line = trimmed(line);
        std::string value;
        if (line.size() > 2 && line[0] == '+' && (line[1] == 'L' || line[1] == 'l')) {
            value = line.substr(2);
        } else if (const auto eq = line.find('='); eq != std::string::npos) {
            std::string key = trimmed(line.substr(0, eq));
            for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            if (key == "library_path") value = trimmed(line.substr(eq + 1));
        }
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
        if (!value.empty()) paths.emplace_back(value);
    }
    return paths;
}

}  // namespace

std::vector<std::filesystem::path> povrayLibraryPaths() {
    std::vector<std::filesystem::path> candidates;
    auto fromIni = [&](const std::filesystem::path& ini) {
        for (auto& p : iniLibraryPaths(ini)) candidates.push_back(std::move(p));
    };
    if (const char* home = std::getenv("HOME")) fromIni(std::filesystem::path(home) / ".povray/3.7/povray.ini");
    fromIni("/etc/povray/3.7/povray.ini");
    fromIni("/usr/local/etc/povray/3.7/povray.ini");
    candidates.emplace_back("/usr/share/povray-3.7/include");
    candidates.emplace_back("/usr/local/share/povray-3.7/include");

    std::vector<std::filesystem::path> paths;
    for (const auto& c : candidates) {
        std::error_code ec;
        if (!std::filesystem::is_directory(c, ec)) continue;
        if (std::find(paths.begin(), paths.end(), c) == paths.end()) paths.push_back(c);
    }
    return paths;
}

}  // namespace asos::lang
