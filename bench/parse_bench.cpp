// Reading scene text (issue 21): the scanner alone and the whole parse, in
// MB/s of text, on the two kinds of text big scenes are made of: mesh data
// as exporters write it, and many small objects as scenes written by hand
// or by macros are.
//
//     build/bin/lancer_bench --benchmark_filter='Scan|Parse'
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "lancer/parser.h"
#include "raw_token.h"

namespace {

using namespace lancer;

// A mesh2 of a columns x rows vertex grid, as bench/mesh2_parse.sh writes it.
std::string mesh2_text(int columns, int rows) {
    std::string text = "mesh2 {\n vertex_vectors { " + std::to_string(columns * rows) + ",\n";
    char line[128];
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const double u = double(i) / (columns - 1), v = double(j) / (rows - 1);
            std::snprintf(line, sizeof line, "  <%.6f,%.6f,%.6f>,\n", u * 4 - 2,
                          0.2 * std::sin(u * 20) * std::cos(v * 13), v * 2 - 1);
            text += line;
        }
    text += " }\n face_indices { " + std::to_string(2 * (columns - 1) * (rows - 1)) + ",\n";
    for (int j = 0; j + 1 < rows; ++j)
        for (int i = 0; i + 1 < columns; ++i) {
            const int a = j * columns + i;
            std::snprintf(line, sizeof line, "  <%d,%d,%d>, <%d,%d,%d>,\n", a, a + 1, a + columns, a + 1,
                          a + columns + 1, a + columns);
            text += line;
        }
    return text + " }\n}\n";
}

// Many small objects, each with a pigment, a finish and transforms.
std::string objects_text(int count) {
    std::string text = "#version 3.7;\ncamera { location <0, 2, -10> look_at 0 }\n";
    char object[320];
    for (int k = 0; k < count; ++k) {
        const double x = (k % 100) * 0.1, y = (k / 100) * 0.1;
        std::snprintf(object, sizeof object,
                      "sphere { <%.3f, %.3f, 0>, 0.04\n  pigment { color rgb <%.2f, 0.5, %.2f> }\n"
                      "  finish { ambient 0.1 diffuse 0.7 specular 0.3 }\n  scale 1.5 rotate <0, %d, 0> "
                      "translate <0, 0, %.2f>\n}\n",
                      x, y, (k % 7) / 7.0, (k % 5) / 5.0, k % 360, (k % 13) * 0.1);
        text += object;
    }
    return text;
}

void scan(benchmark::State& state, const std::string& text) {
    for (auto _ : state) {
        parse::TokenBuffer buffer;
        std::vector<Diagnostic> diagnostics;
        if (!parse::scan_text(text, buffer, diagnostics)) state.SkipWithError("the text does not scan");
        benchmark::DoNotOptimize(buffer.tokens.data());
        state.counters["tokens"] = double(buffer.tokens.size());
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(text.size()));
}

void parse_whole(benchmark::State& state, const std::string& text) {
    for (auto _ : state) {
        ParseResult result = parse_scene_string(text);
        if (!result.ok()) state.SkipWithError("the text does not parse");
        benchmark::DoNotOptimize(result.scene->objects.data());
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(text.size()));
}

const std::string& mesh2() {
    static const std::string text = mesh2_text(400, 250);  // 198,702 triangles, 8 MB
    return text;
}
const std::string& objects() {
    static const std::string text = objects_text(20000);  // 3.5 MB
    return text;
}

void BM_ScanMesh2(benchmark::State& state) {
    scan(state, mesh2());
}
void BM_ScanObjects(benchmark::State& state) {
    scan(state, objects());
}
void BM_ParseMesh2(benchmark::State& state) {
    parse_whole(state, mesh2());
}
void BM_ParseObjects(benchmark::State& state) {
    parse_whole(state, objects());
}

}  // namespace

BENCHMARK(BM_ScanMesh2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ScanObjects)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseMesh2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseObjects)->Unit(benchmark::kMillisecond)->UseRealTime();
