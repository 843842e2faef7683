#include "lancer/rainbow.h"

#include <algorithm>
#include <cmath>

#include "lancer/shading/point_hash.h"
#include "materials/pattern.h"
#include "materials/point_pigment.h"

namespace lancer {

SceneRainbows::SceneRainbows(std::vector<RainbowArc> arcs, std::vector<std::unique_ptr<PointPigment>> colour_maps)
    : m_arcs(std::move(arcs)), m_maps(std::move(colour_maps)) {}

SceneRainbows::~SceneRainbows() = default;

Color SceneRainbows::seen_through(const Vec3& direction, float distance, const Color& behind) const {
    constexpr double kEpsilon = 1e-10;  // POV's EPSILON: the map's last value is not reached
    const glm::dvec3 d(direction);
    glm::dvec3 total(0.0);
    int shown = 0;
    for (std::size_t i = 0; i < m_arcs.size(); ++i) {
        const RainbowArc& arc = m_arcs[i];
        if (arc.distance == 0.0 || arc.width == 0.0) continue;
        // How far round the ring from `up` the direction lies.
        const double x = glm::dot(d, glm::dvec3(arc.right));
        double y = glm::dot(d, glm::dvec3(arc.up));
        const double length = std::sqrt(x * x + y * y);
        if (length > 0.0) y /= length;
        const double around = std::abs(std::acos(std::clamp(y, -1.0, 1.0)));
        if (around > arc.arc_angle) continue;
        const double toward = glm::dot(d, glm::dvec3(arc.antisolar));
        if (toward < 0.0) continue;
        double index = (std::acos(std::min(toward, 1.0)) - arc.start_angle) / arc.width;
        if (arc.jitter > 0.0) index += (2.0 * point_hash(direction, 0x7261696eull + i) - 1.0) * arc.jitter;
        if (index < 0.0 || index > 1.0 - kEpsilon) continue;
        const TextureSample ring = m_maps[i]->at(glm::dvec3(index, 0.0, 0.0), PatternContext{});
        const double falloff_width = arc.arc_angle - arc.falloff_angle;
        double fade = 0.0;
        if (falloff_width > 0.0 && around > arc.falloff_angle) {
            fade = (around - arc.falloff_angle) / falloff_width;
            fade = (3.0 - 2.0 * fade) * fade * fade;
        }
        // Its transmit is the least it lets through, more towards its ends.
        double kept = std::exp(-double(distance) / arc.distance);
        kept = std::max(kept, fade * (1.0 - ring.transmit) + ring.transmit);
        const double added = 1.0 - kept;
        const double filter = ring.filter * added;
        const glm::dvec3 tint = glm::dvec3(1.0 - filter) + filter * glm::dvec3(ring.rgb);
        total += kept * glm::dvec3(behind) * tint + added * glm::dvec3(ring.rgb);
        ++shown;
    }
    if (shown == 0) return behind;
    return Color(total / double(shown));
}

}  // namespace lancer
