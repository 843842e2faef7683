// The front end's public face: scene text in, scene graph or located
// diagnostics out. Never throws for bad input and never exits.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "lancer/geometry_queries.h"
#include "lancer/scene_graph.h"

namespace lancer {

struct Diagnostic {
    enum class Severity { Error, Warning, Note };
    Severity severity = Severity::Error;
    sg::SourceLocation location;
    std::string message;
    // Where the file holding `location` was included from, innermost first.
    std::vector<sg::SourceLocation> include_chain;
    // The text of location.line (without its newline), for the caret display;
    // empty when unknown (format_diagnostic then reads the file).
    std::string source_line;
};

// POV-Ray's animation constants for the frame being parsed (its +KFI, +KFF,
// +KI, +KF): clock runs from initial_clock at initial_frame to final_clock
// at final_frame. All 0 (and clock_on false) outside an animation, as in
// POV-Ray, which also treats a single frame as no animation.
struct AnimationFrame {
    bool clock_on = false;
    int frame_number = 0;
    int initial_frame = 0, final_frame = 0;
    double clock = 0.0, clock_delta = 0.0;
    double initial_clock = 0.0, final_clock = 0.0;
};

// The frame `frame` of an animation from initial_frame to final_frame over
// clocks initial_clock to final_clock, as POV-Ray numbers it.
AnimationFrame animation_frame(int frame, int initial_frame, int final_frame, double initial_clock, double final_clock);

// A command-line declaration (POV-Ray's Declare=Name=value, lancer's
// -D Name=value): a global identifier set before the scene is read.
struct CommandLineDeclaration {
    std::string name;
    std::variant<double, std::string> value;
};

struct ParseOptions {
    // Searched after the including file's folder: LANCER_INCLUDE_PATH's
    // folders are appended by default_include_path(), then lancer's include/,
    // then POV-Ray's.
    std::vector<std::string> include_path;
    // Values of POV's image_width / image_height until a render_settings
    // block sets them (the command line's size when given).
    int image_width = 640;
    int image_height = 480;
    bool image_size_from_command_line = false;
    // Safe mode (`--safe`) for scenes from untrusted sources: every file the
    // scene names (#include, obj_mesh and the MTL files and textures its OBJ
    // names, image_map) must lie, after following symlinks and "..", inside
    // safe_root or a folder of include_path (lancer's include/ and
    // LANCER_INCLUDE_PATH are appended to it). Anything else is a located
    // error that names the path the scene wrote and never reads the file, so
    // no diagnostic can echo its content.
    bool safe = false;
    // The folder safe mode allows; empty: the scene file's folder
    // (parse_scene_file) or the current folder (parse_scene_string).
    std::string safe_root;
    // Resource limits: exceeding one is a located error, never a hang.
    // One #while/#for loop may run this many times (an iteration costs a few
    // microseconds, so a runaway loop is reported within seconds).
    long max_loop_iterations = 1'000'000;
    int max_include_depth = 64;
    int max_macro_depth = 200;
    int max_nesting_depth = 256;
    // A #declare'd value that is a plain expression (numbers, variables,
    // built-in calls, operators) is read straight from its tokens, not by
    // the grammar: loops run several times faster, with the same values and
    // messages. false: the grammar reads every value (the tests compare).
    bool plain_values = true;
    // Triangles in the whole scene (mesh, mesh2, obj_mesh): ~100 bytes each
    // once the renderer holds them, so the default stops at ~5 GiB.
    long max_triangles = 50'000'000;
    // What a function called while parsing may need of the renderer (noise,
    // patterns, pigments); null: such a call is a located error.
    const sg::FunctionNatives* function_natives = nullptr;
    // What trace(), inside(), min_extent() and max_extent() ask of the
    // objects declared so far; null: such a call is a located error.
    const sg::GeometryQueries* geometry_queries = nullptr;
    AnimationFrame animation;
    // POV-Ray's Version= (+MV): the language version before the scene's
    // first #version. Unset: POV's rule, under which a scene with no
    // #version at all is read as 3.62 (legacy gamma without assumed_gamma,
    // pre-3.7 sky_sphere filter) while `version` still reads 3.7.
    std::optional<double> language_version;
    // Declared before the scene's first line (a name that is not an
    // identifier, or is a reserved word, is an error).
    std::vector<CommandLineDeclaration> declarations;
    // Top-level objects: loops nest, and each nested #while has its own
    // iteration cap, so only this bounds what nested loops can create.
    long max_objects = 2'000'000;
    // Size of one scene, include or OBJ/MTL file; checked before reading.
    long long max_file_bytes = 1LL << 30;
    // Bytes all of the scene's concat() calls may produce, together: a
    // string doubled in a loop reached 7 GB before this bound.
    long long max_string_bytes = 64LL << 20;
    // Memory the parse may add to the process (its resident size beyond
    // what it was when the parse began): arrays, objects and their copies,
    // macro frames, strings. Read at every loop iteration and macro call (at
    // most once a millisecond) and before an array is made; crossing it is a
    // located error. `--max-memory` on render, check and trade.
    long long max_memory_bytes = 4LL << 30;
};

struct ParseResult {
    std::optional<sg::SceneGraph> scene;  // set iff there is no error
    std::vector<Diagnostic> diagnostics;  // errors, warnings and notes in order
    bool ok() const { return scene.has_value(); }
};

// The scene's folder is searched first, then options.include_path.
ParseResult parse_scene_file(const std::string& path, const ParseOptions& options = {});
// `name` stands for the file name in diagnostics; includes resolve against
// the current directory, then options.include_path.
ParseResult parse_scene_string(std::string_view text, const std::string& name = "<string>",
                               const ParseOptions& options = {});

// LANCER_INCLUDE_PATH's folders, then lancer's own include/ folder, then POV-Ray's
// installed include folder when there is one.
std::vector<std::string> default_include_path();

// "file:line:col: error: message", then the source line and a caret under
// the column, then "note: included from file:line" for each include.
std::string format_diagnostic(const Diagnostic& diagnostic);
// `text` with control characters and invalid UTF-8 shown as escapes
// (\x1b, \t): what every echo of the user's input to a terminal goes through.
std::string escape_for_terminal(std::string_view text);

}  // namespace lancer
