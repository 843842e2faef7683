// libFuzzer target: obj_mesh loading (tinyobjloader plus lancer's checks and
// MTL mapping) through the real scene path, obj_mesh { "file.obj" }.
//
// Input layout: the OBJ text, optionally followed by a line "#MTL" and the
// text of an MTL file. Both are written to a private temporary folder as
// fuzz.obj / fuzz.mtl (the OBJ may say "mtllib fuzz.mtl"), because the loader
// reads files, as it does for users.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "lancer/parser.h"

namespace {

std::string make_folder() {
    char pattern[] = "/tmp/lancer-fuzz-obj-XXXXXX";
    const char* folder = mkdtemp(pattern);
    if (!folder) std::abort();
    return folder;
}

void write(const std::string& path, std::string_view text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string folder = make_folder();
    std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string_view obj = input, mtl;
    size_t split = input.find("\n#MTL\n");
    if (split != std::string_view::npos) {
        obj = input.substr(0, split);
        mtl = input.substr(split + 6);
    }
    write(folder + "/fuzz.obj", obj);
    write(folder + "/fuzz.mtl", mtl);
    std::string scene = "obj_mesh { \"" + folder + "/fuzz.obj\" }";
    lancer::ParseResult result = lancer::parse_scene_string(scene, "<fuzz>", lancer::ParseOptions{});
    for (const auto& diagnostic : result.diagnostics) (void)lancer::format_diagnostic(diagnostic);
    return 0;
}
