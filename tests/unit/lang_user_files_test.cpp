// #fopen, #read, #write, #fclose and file_exists(): what #write writes is what
// POV-Ray 3.7 writes, and #read gives it back; files go to the folder of
// InterpreterOptions::writeFolder (here a temporary folder, never the source
// or build tree), whole or not at all.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "interpret_text.hpp"

using namespace asos;
using namespace asos::lang;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

// A fresh folder under the system's temporary folder, removed at the end.
struct TempFolder {
    fs::path path;
    explicit TempFolder(const std::string& name) {
        path = fs::temp_directory_path() / ("asos-user-files-" + std::to_string(getpid()) + "-" + name);
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

test::Run runIn(const TempFolder& folder, const std::string& text) {
    InterpreterOptions options;
    options.writeFolder = folder.path;
    return test::run(text, options);
}

std::vector<std::string> debugLines(const test::Run& r) {
    std::vector<std::string> lines;
    for (const auto& d : r.diagnostics.all())
        if (d.severity == Severity::Debug) lines.push_back(d.message);
    return lines;
}

std::vector<Vec3> centres(const SceneDescription& scene) {
    std::vector<Vec3> out;
    for (const auto& o : scene.objects) out.push_back(std::get<SphereShape>(o.shape).center);
    return out;
}

}  // namespace

TEST_CASE("#write writes strings, floats and vectors as POV-Ray 3.7 does", "[lang][files]") {
    const TempFolder folder("write");
    const auto r = runIn(folder, R"(
#declare S = "str";
#fopen F "out.txt" write
#write (F, "hello", 1.5, ",", <1/3, 1e20, -2>, "|", <1,2>, "|", <1,2,3,4,5>, "|", 1/3*1e-5, "|", 123456789)
#write (F "|" -0 "|" pi, S, "\"quoted\"\n")
#write (F)
#fclose F
sphere { 0, 1 })");
    test::ok(r);
    // What POV-Ray 3.7 writes for the same lines (checked with povray).
    CHECK(readText(folder.path / "out.txt") ==
          "hello1.5,<0.333333,1e+20,-2> |<1,2> |<1,2,3,4,5> |3.33333e-06|1.23457e+08|-0|3.14159str\"quoted\"\n");
}

TEST_CASE("#read gives back what #write wrote: floats, vectors and strings", "[lang][files]") {
    const TempFolder folder("round-trip");
    const auto r = runIn(folder, R"(
#fopen Out "data.txt" write
#write (Out, 0.25, ",", -1e-7, ",", 1e20, ",", 1/3, ",\n")
#write (Out, <1, -2.5, 3>, ",", <0.5, 1e-3>, ",", <1, 2, 3, 4, 5>, ",\n")
#write (Out, "\"a, b\",", "\"tab\\there\"\n")
#fclose Out
#fopen In "data.txt" read
#read (In, A, B, C, D)
#read (In, V3, V2, V5, S1, S2)
#if (defined(In)) #error "the file should be closed at its end" #end
sphere { <A, B, C>, 1 }
sphere { <D, 0, 0>, 1 }
sphere { V3, 1 }
sphere { <V2.x, V2.y, 0>, 1 }
sphere { <V5.x, V5.t, V5.transmit>, 1 }
#debug S1
#debug S2
)");
    const auto& scene = test::ok(r);
    const auto c = centres(scene);
    REQUIRE(c.size() == 5);
    CHECK(c[0] == Vec3(0.25, -1e-7, 1e20));
    CHECK(c[1].x == 0.333333);  // %g keeps six digits, as in POV-Ray
    CHECK(c[2] == Vec3(1, -2.5, 3));
    CHECK(c[3] == Vec3(0.5, 1e-3, 0));
    CHECK(c[4] == Vec3(1, 4, 5));
    CHECK(debugLines(r) == std::vector<std::string>{"a, b", "tab\there"});
}

TEST_CASE("a file read in a #while (defined(Handle)) loop ends as POV-Ray's does", "[lang][files]") {
    const TempFolder folder("loop");
    test::writeFile(folder.path / "three.txt", "1, 2, 3\n");
    test::writeFile(folder.path / "trailing.txt", "// a comment\n1, /* two */ 2,\n");
    // Without a trailing comma the end is seen as the last value is read: three passes.
    auto r = runIn(folder, R"(
#fopen F "three.txt" read
#while (defined(F))
  #read (F, V)
  sphere { <V, 0, 0>, 1 }
#end
#fclose F  // closed already: no error, as in POV-Ray
)");
    CHECK(centres(test::ok(r)).size() == 3);
    // After a trailing comma one more #read finds the end, and leaves V as it was.
    r = runIn(folder, R"(
#fopen F "trailing.txt" read
#while (defined(F))
  #read (F, V)
  sphere { <V, 0, 0>, 1 }
#end
)");
    const auto c = centres(test::ok(r));
    REQUIRE(c.size() == 3);
    CHECK(c[2].x == 2);
}

TEST_CASE("#fopen append adds to the file, and file_exists finds files", "[lang][files]") {
    const TempFolder folder("append");
    test::writeFile(folder.path / "log.txt", "first\n");
    const auto r = runIn(folder, R"(
#fopen L "log.txt" append
#write (L, "second\n")
#fclose L
#if (!file_exists("log.txt") | file_exists("no_such_file.txt")) #error "file_exists" #end
sphere { 0, 1 })");
    test::ok(r);
    CHECK(readText(folder.path / "log.txt") == "first\nsecond\n");
}

TEST_CASE("a parse that stops with an error writes no file and keeps the old one", "[lang][files]") {
    const TempFolder folder("error");
    test::writeFile(folder.path / "kept.txt", "old\n");
    const auto r = runIn(folder, R"(
#fopen A "kept.txt" write
#fopen B "new.txt" write
#write (A, "new\n")
#write (B, "new\n")
#error "stop"
)");
    CHECK_FALSE(r.scene);
    CHECK(readText(folder.path / "kept.txt") == "old\n");
    CHECK_FALSE(fs::exists(folder.path / "new.txt"));
    CHECK(std::distance(fs::directory_iterator(folder.path), fs::directory_iterator()) == 1);
    // Without the error, files still open at the end are written.
    const auto done = runIn(folder, "#fopen A \"kept.txt\" write\n#write (A, \"new\\n\")\nsphere { 0, 1 }");
    test::ok(done);
    CHECK(readText(folder.path / "kept.txt") == "new\n");
}

TEST_CASE("file directives: located errors for bad handles, modes and data", "[lang][files]") {
    const TempFolder folder("errors");
    test::writeFile(folder.path / "in.txt", "1, 2\n");
    test::writeFile(folder.path / "bad.txt", "1,\n  abc, 2\n");
    test::writeFile(folder.path / "nocomma.txt", "1 2\n");
    test::writeFile(folder.path / "vector.txt", "<1, 2\n");
    auto errorOf = [&](const std::string& text) {
        const auto r = runIn(folder, text + "\nsphere { 0, 1 }");
        CHECK_FALSE(r.scene);
        return r.errors();
    };
    CHECK_THAT(errorOf("#fopen F \"missing.txt\" read"), Contains("1:10: cannot find the file 'missing.txt' to read"));
    CHECK_THAT(errorOf("#declare F = 1;\n#fopen F \"in.txt\" read"),
               Contains("2:8: #fopen needs a name not in use, as in POV-Ray; 'F' is a float"));
    CHECK_THAT(errorOf("#fopen F \"in.txt\" read\n#write (F, \"x\")"),
               Contains("2:9: cannot write to 'in.txt': it is open for reading"));
    CHECK_THAT(errorOf("#fopen F \"o.txt\" write\n#read (F, A)"),
               Contains("2:8: cannot read from 'o.txt': it is open for writing"));
    CHECK_THAT(errorOf("#read (G, A)"), Contains("1:8: 'G' is not declared: no file is open under that name"));
    CHECK_THAT(errorOf("#declare G = 1;\n#write (G, 1)"), Contains("2:9: #write needs a file handle; 'G' is a float"));
    CHECK_THAT(errorOf("#fopen F \"o.txt\" write\n#write (F, rgb 1)"),
               Contains("2:12: #write writes strings, floats and vectors, as POV-Ray; this is a colour"));
    CHECK_THAT(errorOf("#fopen F \"o.txt\" frobnicate"), Contains("1:18: expected read, write or append"));
    CHECK_THAT(errorOf("#fopen F \"no_such_folder/o.txt\" write"), Contains("1:10: cannot open 'no_such_folder/o.txt' for writing"));

    // Data errors are located in the data file, with the #read that met them.
    auto r = runIn(folder, "#fopen F \"bad.txt\" read\n#read (F, A, B)\nsphere { 0, 1 }");
    REQUIRE(r.diagnostics.all().size() == 1);
    const Diagnostic& d = r.diagnostics.all()[0];
    CHECK(d.loc.line == 2);
    CHECK(d.loc.column == 3);
    CHECK_THAT(*d.loc.file, Contains("bad.txt"));
    CHECK(d.sourceLine == "  abc, 2");
    CHECK_THAT(d.message, Contains("expected a float, a vector or a string in double quotes, found 'abc'"));
    REQUIRE_FALSE(d.context.empty());
    CHECK(d.context[0].what == "read by #read at");
    CHECK(d.context[0].loc.line == 2);
    CHECK_THAT(errorOf("#fopen F \"nocomma.txt\" read\n#read (F, A, B)"), Contains("1:3: expected ',' after the value read"));
    CHECK_THAT(errorOf("#fopen F \"vector.txt\" read\n#read (F, A)"), Contains("1:6: expected ',' or '>' to close the vector"));
}
