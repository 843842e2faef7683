// The golden matrix and golden EXR files; see golden_matrix.h.
#include "golden_matrix.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "lancer/host/image_io.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/integrator.h"
#include "lancer/parser.h"
#include "lancer/render_scene.h"
#include "lancer/scene_graph.h"

namespace lancer::golden {

namespace fs = std::filesystem;

std::string source_dir() {
    return LANCER_SOURCE_DIR;
}
std::string golden_dir() {
    return source_dir() + "/tests/golden";
}
std::string failure_dir() {
    return std::string(LANCER_BINARY_DIR) + "/golden_failures";
}

bool regenerating() {
    const char* value = std::getenv("LANCER_REGENERATE_GOLDENS");
    return value != nullptr && std::string(value) == "1";
}

std::string MatrixEntry::id() const {
    std::string name = scene + "/" + integrator;
    for (const auto& [key, value] : parameters) name += "." + key + "-" + value;
    return name;
}

std::string MatrixEntry::golden_path() const {
    return golden_dir() + "/" + id() + ".exr";
}

std::vector<MatrixEntry> load_matrix() {
    const std::string path = golden_dir() + "/matrix.txt";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::vector<MatrixEntry> entries;
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
        ++line;
        if (const auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
        std::istringstream words(text);
        MatrixEntry entry;
        entry.line = line;
        if (!(words >> entry.scene)) continue;  // blank or comment
        auto fail = [&](const std::string& why) {
            throw std::runtime_error(path + ":" + std::to_string(line) + ": " + why);
        };
        if (!(words >> entry.integrator)) fail("expected: scene integrator [key=value ...] [:option=value ...]");
        std::string word;
        while (words >> word) {
            const auto equals = word.find('=');
            if (equals == std::string::npos || equals == 0) fail("expected key=value, got '" + word + "'");
            const std::string key = word.substr(0, equals), value = word.substr(equals + 1);
            if (key[0] != ':') {
                entry.parameters[key] = value;
                continue;
            }
            try {
                if (key == ":test_spp")
                    entry.test_spp = std::stoi(value);
                else if (key == ":golden_spp")
                    entry.golden_spp = std::stoi(value);
                else if (key == ":block")
                    entry.block = std::stoi(value);
                else if (key == ":abs_tol")
                    entry.absolute_tolerance = std::stod(value);
                else
                    fail("unknown option '" + key + "' (:test_spp, :golden_spp, :block, :abs_tol)");
            } catch (const std::logic_error&) {
                fail("bad number in '" + word + "'");
            }
        }
        for (const MatrixEntry& other : entries)
            if (other.id() == entry.id())
                fail("duplicate of line " + std::to_string(other.line) + " (" + entry.id() + ")");
        entries.push_back(std::move(entry));
    }
    return entries;
}

std::vector<std::string> corpus_scenes() {
    std::vector<std::string> scenes;
    const fs::path root = fs::path(source_dir()) / "scenes";
    for (const auto& item : fs::recursive_directory_iterator(root)) {
        if (!item.is_regular_file() || item.path().extension() != ".pov") continue;
        std::string name = fs::relative(item.path(), root).replace_extension().generic_string();
        scenes.push_back(name);
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::vector<std::string> suited_integrators(const std::string& scene) {
    std::ifstream in(source_dir() + "/scenes/" + scene + ".pov");
    std::string line, header;
    // The header: the leading lines that are // comments.
    while (std::getline(in, line)) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line.compare(first, 2, "//") != 0) break;
        header += line.substr(first + 2) + "\n";
    }
    std::vector<std::string> names;
    // "Suits: path (reference), gather, shadow (area_samples)." — the
    // integrator names are the words before each comma/period outside
    // parentheses, up to the end of the sentence.
    const auto suits = header.find("Suits:");
    if (suits == std::string::npos) return names;
    const std::string known[] = {"raycast", "shadow", "whitted", "gather", "path", "normal", "albedo", "depth"};
    std::string sentence;
    int depth = 0;
    for (std::size_t i = suits + 6; i < header.size(); ++i) {
        const char c = header[i];
        if (c == '(')
            ++depth;
        else if (c == ')')
            --depth;
        else if (depth == 0 && c == '.')
            break;
        else if (depth == 0)
            sentence += c;
    }
    // Each word of the sentence that names a known integrator.
    std::string word;
    auto flush = [&] {
        for (const std::string& k : known)
            if (word == k && std::find(names.begin(), names.end(), k) == names.end()) names.push_back(k);
        word.clear();
    };
    for (char c : sentence) {
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
            word += c;
        else
            flush();
    }
    flush();
    return names;
}

RenderResult render_entry(const MatrixEntry& entry, int width, int height, int spp, std::uint64_t seed) {
    ParseOptions options;
    options.image_width = width;
    options.image_height = height;
    options.image_size_from_command_line = true;
    const ParseResult parsed = parse_scene_file(source_dir() + "/scenes/" + entry.scene + ".pov", options);
    if (!parsed.ok()) {
        std::string message = entry.scene + " does not parse:\n";
        for (const Diagnostic& d : parsed.diagnostics) message += format_diagnostic(d) + "\n";
        throw std::runtime_error(message);
    }
    const auto scene = compile_scene(*parsed.scene);
    // Plugin before integrator: the integrator's code must outlive it.
    const Plugin plugin = load_plugin(entry.integrator);
    std::vector<std::string> assignments;
    for (const auto& [key, value] : entry.parameters) assignments.push_back(key + "=" + value);
    const ParameterSet parameters = resolve_parameters(*plugin.descriptor, {}, assignments);
    const std::unique_ptr<Integrator> integrator = plugin.descriptor->create(parameters);
    integrator->prepare(*scene);

    RenderOptions render;
    render.width = width;
    render.height = height;
    render.samples_per_pixel = spp;
    render.seed = seed;
    render.threads = 0;
    render.tile_size = 8;
    render.progress = ProgressMode::Quiet;
    RenderResult result;
    result.deterministic = integrator->is_deterministic();
    result.film = Film(width, height);
    render_image(*scene, *integrator, render, result.film);
    return result;
}

GoldenFile read_golden(const std::string& path) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) throw std::runtime_error("cannot read golden '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    GoldenFile golden;
    auto channel = [&](const std::string& name) {
        for (int c = 0; c < spec.nchannels; ++c)
            if (spec.channelnames[c] == name) return c;
        return -1;
    };
    const int r = channel("R"), g = channel("G"), b = channel("B");
    if (r < 0 || g < 0 || b < 0) throw std::runtime_error("golden '" + path + "' has no R, G, B channels");
    const int vr = channel("var.R"), vg = channel("var.G"), vb = channel("var.B");
    golden.has_variance = vr >= 0 && vg >= 0 && vb >= 0;
    std::vector<float> all(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error("cannot read golden '" + path + "': " + input->geterror());
    test::PixelStatistics& s = golden.statistics;
    s.width = spec.width;
    s.height = spec.height;
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p) {
        const float* px = &all[p * spec.nchannels];
        s.mean.emplace_back(px[r], px[g], px[b]);
        s.variance_of_mean.push_back(golden.has_variance ? glm::dvec3(px[vr], px[vg], px[vb]) : glm::dvec3(0.0));
    }
    for (const auto& attribute : spec.extra_attribs) {
        const std::string name = attribute.name().string();
        if (name.rfind("lancer:", 0) == 0) golden.metadata[name.substr(7)] = attribute.get_string();
    }
    return golden;
}

void write_golden(const std::string& path, const Film& film, bool with_variance,
                  const std::map<std::string, std::string>& metadata) {
    fs::create_directories(fs::path(path).parent_path());
    const int channels = with_variance ? 6 : 3;
    OIIO::ImageSpec spec(film.width(), film.height(), channels, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B"};
    if (with_variance) spec.channelnames.insert(spec.channelnames.end(), {"var.R", "var.G", "var.B"});
    spec.attribute("compression", "zip");
    for (const auto& [key, value] : metadata) spec.attribute("lancer:" + key, value);
    // A fixed date, so regenerating an unchanged golden changes no byte (and
    // git shows only goldens whose pixels changed).
    spec.attribute("DateTime", "2000:01:01 00:00:00");
    std::vector<float> pixels;
    pixels.reserve(std::size_t(film.width()) * film.height() * channels);
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Color m = film.mean(x, y);
            pixels.insert(pixels.end(), {m.r, m.g, m.b});
            if (with_variance) {
                const Color v = film.variance_of_mean(x, y);
                pixels.insert(pixels.end(), {v.r, v.g, v.b});
            }
        }
    // Through a temporary, so an interrupted regeneration leaves the old golden.
    const std::string temporary = path + ".tmp.exr";
    auto output = OIIO::ImageOutput::create(temporary);
    if (!output || !output->open(temporary, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()))
        throw std::runtime_error("cannot write golden '" + path + "'");
    output->close();
    fs::rename(temporary, path);
}

std::string write_failure_image(const std::string& id, const test::PixelStatistics& render,
                                const test::PixelStatistics& golden, float gain) {
    const int w = render.width, h = render.height;
    std::vector<float> pixels(std::size_t(3 * w) * h * 3, 0.0f);
    auto put = [&](int panel, int x, int y, const glm::dvec3& linear) {
        for (int c = 0; c < 3; ++c)
            pixels[(std::size_t(y) * 3 * w + panel * w + x) * 3 + c] =
                linear_to_srgb(std::clamp(float(linear[c]), 0.0f, 1.0f));
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            const glm::dvec3 a = render.mean[i];
            const glm::dvec3 b = i < golden.mean.size() ? golden.mean[i] : glm::dvec3(0.0);
            put(0, x, y, a);
            put(1, x, y, b);
            put(2, x, y, glm::abs(a - b) * double(gain));
        }
    std::string name = id;
    std::replace(name.begin(), name.end(), '/', '_');
    fs::create_directories(failure_dir());
    const std::string path = failure_dir() + "/" + name + ".png";
    OIIO::ImageSpec spec(3 * w, h, 3, OIIO::TypeDesc::UINT8);
    auto output = OIIO::ImageOutput::create(path);
    if (!output || !output->open(path, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()))
        return "(could not write " + path + ")";
    output->close();
    return path;
}

}  // namespace lancer::golden
