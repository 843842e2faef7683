#include "animation.h"

#include <charconv>
#include <cmath>
#include <filesystem>

namespace lancer::app {

namespace {

// "X..Y" split at "..": false when there is no "..".
bool split_range(const std::string& text, std::string& first, std::string& last) {
    const std::size_t dots = text.find("..");
    if (dots == std::string::npos) return false;
    first = text.substr(0, dots);
    last = text.substr(dots + 2);
    return true;
}

bool whole_int(const std::string& text, int& value) {
    const char* end = text.data() + text.size();
    const auto [stop, failure] = std::from_chars(text.data(), end, value);
    return failure == std::errc() && stop == end && !text.empty();
}

bool whole_double(const std::string& text, double& value) {
    const char* end = text.data() + text.size();
    const auto [stop, failure] = std::from_chars(text.data(), end, value);
    return failure == std::errc() && stop == end && !text.empty() && std::isfinite(value);
}

// Frames beyond this would be a typo, not an animation (and names stay short).
constexpr int kMostFrame = 9'999'999;

}  // namespace

std::optional<AnimationRange> parse_frame_range(const std::string& text, std::string& error) {
    AnimationRange range;
    std::string first, last;
    const bool is_range = split_range(text, first, last);
    if (!is_range) first = last = text;
    if (!whole_int(first, range.initial_frame) || !whole_int(last, range.final_frame)) {
        error = "--frames expects A..B (frame numbers, e.g. 1..60) or one frame number, got '" + text + "'";
        return std::nullopt;
    }
    if (range.initial_frame < 0 || range.final_frame < range.initial_frame || range.final_frame > kMostFrame) {
        error = "--frames needs 0 <= A <= B <= " + std::to_string(kMostFrame) + ", got '" + text + "'";
        return std::nullopt;
    }
    return range;
}

bool parse_clock_range(const std::string& text, AnimationRange& range, std::string& error) {
    std::string first, last;
    if (!split_range(text, first, last) || !whole_double(first, range.initial_clock) ||
        !whole_double(last, range.final_clock)) {
        error = "--clock expects C0..C1 (two finite numbers, e.g. 0..1), got '" + text + "'";
        return false;
    }
    return true;
}

std::string frame_file_name(const std::string& path, int frame, int final_frame) {
    const std::filesystem::path p(path);
    const std::size_t digits = std::to_string(final_frame).size();
    std::string number = std::to_string(frame);
    if (number.size() < digits) number.insert(0, digits - number.size(), '0');
    return (p.parent_path() / (p.stem().string() + number + p.extension().string())).string();
}

}  // namespace lancer::app
