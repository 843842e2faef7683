// 8-bit sRGB codes from a table (film/srgb8.h).
//
// The code is a monotonic step function of x with 255 steps. The table
// keeps each step's exact threshold (the least float with that code, found
// by bisection on the float's bits against the defining formula) and, for
// the floats of (0, 1) grouped by their top 17 bits, the code at the start
// of each group; a group is narrower than a step, so at most one threshold
// lies inside it.
#include "film/srgb8.h"

#include <array>
#include <bit>
#include <vector>

#include "lancer/host/image_io.h"

namespace lancer {
namespace {

constexpr std::uint32_t kOneBits = 0x3F800000u;  // 1.0f
constexpr int kGroupShift = 15;

unsigned defining_code(float linear) {
    const float encoded = linear_to_srgb(linear);
    if (!(encoded > 0.0f)) return 0;
    if (encoded >= 1.0f) return 255;
    return unsigned(encoded * 255.0f + 0.5f);
}

struct Srgb8Table {
    std::array<float, 257> threshold{};  // threshold[k]: the least x with code >= k; [256] past every x
    std::vector<std::uint8_t> group_start;

    Srgb8Table() {
        for (unsigned k = 1; k <= 255; ++k) {
            std::uint32_t low = 0, high = kOneBits;  // code(low) < k <= code(high)
            while (high - low > 1) {
                const std::uint32_t middle = low + (high - low) / 2;
                (defining_code(std::bit_cast<float>(middle)) >= k ? high : low) = middle;
            }
            threshold[k] = std::bit_cast<float>(high);
        }
        threshold[256] = 2.0f;
        group_start.resize((kOneBits >> kGroupShift) + 1);
        for (std::size_t g = 0; g < group_start.size(); ++g)
            group_start[g] = std::uint8_t(defining_code(std::bit_cast<float>(std::uint32_t(g) << kGroupShift)));
    }
};

const Srgb8Table& table() {
    static const Srgb8Table built;
    return built;
}

std::uint8_t code_from(const Srgb8Table& t, float linear) {
    if (!(linear > 0.0f)) return 0;  // NaN too
    if (linear >= 1.0f) return 255;
    unsigned code = t.group_start[std::bit_cast<std::uint32_t>(linear) >> kGroupShift];
    if (linear >= t.threshold[code + 1]) ++code;
    return std::uint8_t(code);
}

}  // namespace

std::uint8_t linear_to_srgb8(float linear) {
    return code_from(table(), linear);
}

void linear_to_srgb8(const float* linear, std::uint8_t* codes, std::size_t count) {
    const Srgb8Table& t = table();
    for (std::size_t i = 0; i < count; ++i) codes[i] = code_from(t, linear[i]);
}

}  // namespace lancer
