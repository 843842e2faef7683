// The public entry points (lancer/parser.h).
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "evaluator.h"
#include "parse_stack.h"

namespace lancer {

namespace fs = std::filesystem;

namespace parse {

namespace {

bool is_identifier(const std::string& name) {
    if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
    for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

}  // namespace

ParseResult Evaluator::run(std::string text, const std::string& label, const std::string& path,
                           const std::string& folder) {
    return run_with(
        [&](std::string& read) {
            read = std::move(text);
            return true;
        },
        label, path, folder);
}

ParseResult Evaluator::run_file(std::ifstream& file, const std::string& path, const std::string& folder) {
    const sg::SourceLocation where{std::make_shared<const std::string>(path), 0, 0};
    return run_with(
        [&](std::string& read) {
            return within_file_limit(path, where, "scene file") &&
                   read_open_file(file, path, where, "scene file", read);
        },
        path, path, folder);
}

ParseResult Evaluator::run_with(const std::function<bool(std::string&)>& read_text, const std::string& label,
                                const std::string& path, const std::string& folder) {
    m_scene.main_file = path.empty() ? label : path;
    init_safe_roots(folder);
    if (m_options.image_size_from_command_line) {
        m_scene.render.width = m_options.image_width;
        m_scene.render.height = m_options.image_height;
    }
    for (const CommandLineDeclaration& declaration : m_options.declarations) {
        if (!is_identifier(declaration.name) || is_reserved_word(declaration.name)) {
            static const auto command_line = std::make_shared<const std::string>("command line");
            error(sg::SourceLocation{command_line, 0, 0},
                  "-D " + declaration.name + ": not a name a scene can declare" +
                      (is_identifier(declaration.name) ? " (a reserved word)" : ""));
            continue;
        }
        const auto* number = std::get_if<double>(&declaration.value);
        store(declaration.name,
              number ? Value::number(*number) : Value::string(std::get<std::string>(declaration.value)), false, {});
    }
    std::string text;
    if (read_text(text) && push_file(std::move(text), label, path, folder, {})) {
        m_pending.push_back(Pending{
            nullptr, std::make_shared<const Symbol>(Parser::token::TOK_START_SCENE, SourceRange{}), nullptr, 0, false});
        Parser parser(*this);
        parser.parse();
        while (!m_frames.empty() && !m_aborted) pop_frame();
        if (!m_aborted) settle_version_defaults();
    }
    if (m_options.image_size_from_command_line) {
        m_scene.render.width = m_options.image_width;
        m_scene.render.height = m_options.image_height;
    }
    ParseResult result;
    result.diagnostics = std::move(m_diagnostics);
    if (m_error_count == 0 && !m_aborted) result.scene = std::move(m_scene);
    if (m_error_count == 0 && m_aborted) {
        // Every abort reports an error first; guard the contract anyway.
        Diagnostic diagnostic;
        diagnostic.location.file = std::make_shared<const std::string>(label);
        diagnostic.message = "parsing stopped";
        result.diagnostics.push_back(diagnostic);
    }
    return result;
}

}  // namespace parse

AnimationFrame animation_frame(int frame, int initial_frame, int final_frame, double initial_clock,
                               double final_clock) {
    AnimationFrame a;
    if (final_frame <= initial_frame) return a;  // one frame: POV-Ray's "no animation"
    a.clock_on = true;
    a.frame_number = frame;
    a.initial_frame = initial_frame;
    a.final_frame = final_frame;
    a.initial_clock = initial_clock;
    a.final_clock = final_clock;
    const double frames = double(final_frame) - double(initial_frame);
    a.clock_delta = (final_clock - initial_clock) / frames;
    // As a fraction of the span, so the last frame's clock is final_clock exactly.
    a.clock = initial_clock + (final_clock - initial_clock) * ((double(frame) - double(initial_frame)) / frames);
    return a;
}

ParseResult parse_scene_file(const std::string& path, const ParseOptions& options) {
    std::error_code ec;
    std::ifstream in(path, std::ios::binary);
    if (!in || fs::is_directory(path, ec)) {
        ParseResult result;
        Diagnostic diagnostic;
        diagnostic.location.file = std::make_shared<const std::string>(path);
        diagnostic.message = fs::exists(path, ec) ? "cannot read the scene file" : "scene file not found";
        result.diagnostics.push_back(diagnostic);
        return result;
    }
    ParseResult result;
    parse::run_on_parse_stack([&] {
        parse::Evaluator evaluator(options);
        result = evaluator.run_file(in, path, fs::path(path).parent_path().string());
    });
    return result;
}

ParseResult parse_scene_string(std::string_view text, const std::string& name, const ParseOptions& options) {
    ParseResult result;
    parse::run_on_parse_stack([&] {
        parse::Evaluator evaluator(options);
        result = evaluator.run(std::string(text), name, "", "");
    });
    return result;
}

std::vector<std::string> default_include_path() {
    std::vector<std::string> path;
    if (const char* env = std::getenv("LANCER_INCLUDE_PATH")) {
        std::string list = env;
        size_t start = 0;
        while (start <= list.size()) {
            size_t end = list.find(':', start);
            if (end == std::string::npos) end = list.size();
            if (end > start) path.push_back(list.substr(start, end - start));
            start = end + 1;
        }
    }
    // lancer's own include/: beside the running binary in an installed tree
    // (which may have been moved since it was configured), else the source
    // tree when running from a build, else the configured install prefix.
    std::error_code ec;
    const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
    std::vector<fs::path> candidates;
    if (!ec) candidates.push_back(executable.parent_path().parent_path() / "share" / "lancer" / "include");
    candidates.emplace_back(LANCER_SOURCE_INCLUDE_DIR);
    candidates.emplace_back(LANCER_INSTALL_INCLUDE_DIR);
    bool found_own = false;
    for (const fs::path& folder : candidates) {
        if (fs::is_regular_file(folder / "colors.inc", ec)) {
            path.push_back(folder.string());
            found_own = true;
            break;
        }
    }
    if (!found_own) path.push_back(LANCER_INSTALL_INCLUDE_DIR);
    // Then POV-Ray's own include folder, as POV-Ray's Library_Path finds it
    // (Debian's povray-includes, or a build installed under /usr/local):
    // scenes written for POV-Ray include shapes.inc, textures.inc ...
    for (const char* folder : {"/usr/local/share/povray-3.7/include", "/usr/share/povray-3.7/include"}) {
        if (fs::is_directory(folder, ec)) path.emplace_back(folder);
    }
    return path;
}

}  // namespace lancer
