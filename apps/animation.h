// Animations as POV-Ray renders them: `--frames A..B` (its +KFI / +KFF) and
// `--clock C0..C1` (+KI / +KF), one image per frame, named as POV-Ray names
// them.
#pragma once

#include <optional>
#include <string>

#include "lancer/parser.h"

namespace lancer::app {

struct AnimationRange {
    int initial_frame = 1, final_frame = 1;
    double initial_clock = 0.0, final_clock = 1.0;  // POV-Ray's defaults
    // The parse options' constants for `frame` (POV's numbering).
    AnimationFrame frame(int frame) const {
        return animation_frame(frame, initial_frame, final_frame, initial_clock, final_clock);
    }
    int frame_count() const { return final_frame - initial_frame + 1; }
};

// "A..B" with 0 <= A <= B (or one frame "A"); nullopt with `error` set.
std::optional<AnimationRange> parse_frame_range(const std::string& text, std::string& error);
// "C0..C1", two finite numbers; false with `error` set.
bool parse_clock_range(const std::string& text, AnimationRange& range, std::string& error);

// POV-Ray's frame file name: the frame number, zero-padded to the digits of
// the final frame, between the stem and the extension (`anim.png`, frame 7
// of 60: `anim07.png`).
std::string frame_file_name(const std::string& path, int frame, int final_frame);

}  // namespace lancer::app
