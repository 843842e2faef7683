#include "lancer/light_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lancer {
namespace {

float safe_sqrt(float x) {
    return std::sqrt(std::max(x, 0.0f));
}

// cos(max(0, a - b)) and sin(max(0, a - b)) from the angles' sines and cosines.
float cos_minus_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a > cos_b) return 1.0f;
    return cos_a * cos_b + sin_a * sin_b;
}
float sin_minus_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a > cos_b) return 0.0f;
    return sin_a * cos_b - cos_a * sin_b;
}

// The smallest cone from two (axis, cos half-angle) cones.
void merge_cones(Vec3& axis, float& cos_spread, const Vec3& other_axis, float other_cos) {
    const float theta_a = std::acos(std::clamp(cos_spread, -1.0f, 1.0f));
    const float theta_b = std::acos(std::clamp(other_cos, -1.0f, 1.0f));
    const float theta_d = std::acos(std::clamp(glm::dot(axis, other_axis), -1.0f, 1.0f));
    if (std::min(theta_d + theta_b, kPi) <= theta_a) return;
    if (std::min(theta_d + theta_a, kPi) <= theta_b) {
        axis = other_axis;
        cos_spread = other_cos;
        return;
    }
    const float theta_o = 0.5f * (theta_a + theta_d + theta_b);
    const Vec3 turn = glm::cross(axis, other_axis);
    if (theta_o >= kPi || !(glm::dot(turn, turn) > 0.0f)) {
        cos_spread = -1.0f;
        return;
    }
    // Turn the first axis towards the second by theta_o - theta_a.
    const Vec3 k = glm::normalize(turn);
    const float angle = theta_o - theta_a;
    axis = glm::normalize(axis * std::cos(angle) + glm::cross(k, axis) * std::sin(angle) +
                          k * glm::dot(k, axis) * (1.0f - std::cos(angle)));
    cos_spread = std::cos(theta_o);
}

LightTree::Bounds merged(const LightTree::Bounds& a, const LightTree::Bounds& b) {
    if (!(a.power > 0.0f)) return b;
    if (!(b.power > 0.0f)) return a;
    LightTree::Bounds out = a;
    out.lower = glm::min(a.lower, b.lower);
    out.upper = glm::max(a.upper, b.upper);
    out.power = a.power + b.power;
    merge_cones(out.axis, out.cos_spread, b.axis, b.cos_spread);
    out.cos_emission = std::min(a.cos_emission, b.cos_emission);
    out.two_sided = a.two_sided || b.two_sided;
    return out;
}

bool falls_off(const PointLightParameters& point, LightTree::Falloff falloff) {
    const bool fades = point.falloff == PointFalloff::InverseSquare || point.fade_power > 0.0f;
    return fades == (falloff == LightTree::Falloff::InverseSquare);
}

// A light's bounds with its power left at 0 (the tree weighs it), if a
// tree of `falloff` can hold it.
bool bounds_of(const Light& light, LightTree::Falloff falloff, LightTree::Bounds& bounds) {
    const bool inverse_square = falloff == LightTree::Falloff::InverseSquare;
    auto around = [&](const Vec3& centre, float radius) {
        bounds.lower = centre - Vec3(radius);
        bounds.upper = centre + Vec3(radius);
    };
    // A point emitting every way, or within a spotlight's cone.
    auto point = [&](const PointLightParameters& p) {
        if (p.spot_axis != Vec3(0.0f)) {
            bounds.axis = glm::normalize(p.spot_axis);
            bounds.cos_spread = 1.0f;
            bounds.cos_emission = std::clamp(p.spot_cos_falloff, -1.0f, 1.0f);
        } else if (p.pattern_axis != Vec3(0.0f)) {
            bounds.axis = glm::normalize(p.pattern_axis);
            bounds.cos_spread = 1.0f;
            bounds.two_sided = !p.one_sided;
        }
    };
    switch (light.kind()) {
    case Light::Kind::Point: {
        const auto* p = light.parameters<PointLightParameters>();
        if (p == nullptr || !falls_off(*p, falloff)) return false;
        around(p->position, 0.0f);
        point(*p);
        return true;
    }
    case Light::Kind::PovArea: {
        const auto* p = light.parameters<PovAreaLightParameters>();
        if (p == nullptr || !falls_off(p->center, falloff)) return false;
        // `orient` may turn the axes: the sphere they sweep holds the grid.
        around(p->center.position, 0.5f * (glm::length(p->axis1) + glm::length(p->axis2)));
        point(p->center);
        return true;
    }
    case Light::Kind::Rectangle: {
        const auto* p = light.parameters<RectangleLightParameters>();
        if (p == nullptr || !inverse_square) return false;
        const Vec3 half = 0.5f * (glm::abs(p->axis1) + glm::abs(p->axis2));
        bounds.lower = p->center - half;
        bounds.upper = p->center + half;
        const Vec3 normal = glm::cross(p->axis1, p->axis2);
        if (!(glm::dot(normal, normal) > 0.0f)) return false;
        bounds.axis = glm::normalize(normal);
        bounds.cos_spread = 1.0f;
        return true;
    }
    case Light::Kind::Sphere: {
        const auto* p = light.parameters<SphereLightParameters>();
        if (p == nullptr || !inverse_square) return false;
        around(p->center, p->radius);
        return true;
    }
    case Light::Kind::EmissiveShape: {
        const auto* p = light.parameters<EmissiveShapeParameters>();
        if (p == nullptr || !inverse_square) return false;
        bounds.lower = p->lower;
        bounds.upper = p->upper;
        if (p->flat && p->normal != Vec3(0.0f)) {
            bounds.axis = p->normal;
            bounds.cos_spread = 1.0f;
            bounds.two_sided = true;
        }
        return true;
    }
    case Light::Kind::Directional:
    case Light::Kind::Environment: break;
    }
    return false;
}

bool finite_box(const LightTree::Bounds& b) {
    return std::isfinite(b.lower.x) && std::isfinite(b.lower.y) && std::isfinite(b.lower.z) &&
           std::isfinite(b.upper.x) && std::isfinite(b.upper.y) && std::isfinite(b.upper.z);
}

}  // namespace

bool LightTree::can_bound(const Light& light, Falloff falloff) {
    Bounds bounds;
    return bounds_of(light, falloff, bounds) && finite_box(bounds);
}

float LightTree::importance(const Bounds& b, const Vec3& p, const Vec3& n, Falloff falloff) {
    if (!(b.power > 0.0f)) return 0.0f;
    const Vec3 centre = 0.5f * (b.lower + b.upper);
    const Vec3 offset = p - centre;
    const float distance2 = glm::dot(offset, offset);
    const float radius = 0.5f * glm::length(b.upper - b.lower);
    // A point close to the box is weighed as if at its edge: the bound
    // below would otherwise grow without limit near a small light. (pbrt-v4
    // takes the larger of the squared distance and half the diagonal, which
    // changes with the scene's unit; both squared here, so a scene scaled
    // by any factor chooses the same lights.)
    const float weighed2 =
        falloff == Falloff::None ? 1.0f : std::max({distance2, radius * radius, std::numeric_limits<float>::min()});
    const Vec3 wi = distance2 > 0.0f ? offset / std::sqrt(distance2) : Vec3(0.0f, 0.0f, 1.0f);
    // The angle the box subtends from p (every way from inside it).
    float cos_box = -1.0f;
    if (distance2 > radius * radius) cos_box = safe_sqrt(1.0f - radius * radius / distance2);
    const float sin_box = safe_sqrt(1.0f - cos_box * cos_box);
    // The smallest angle between an emitted normal and the way to p.
    float cos_w = glm::dot(b.axis, wi);
    if (b.two_sided) cos_w = std::abs(cos_w);
    const float sin_w = safe_sqrt(1.0f - cos_w * cos_w);
    const float sin_spread = safe_sqrt(1.0f - b.cos_spread * b.cos_spread);
    const float cos_x = cos_minus_clamped(sin_w, cos_w, sin_spread, b.cos_spread);
    const float sin_x = sin_minus_clamped(sin_w, cos_w, sin_spread, b.cos_spread);
    const float cos_closest = cos_minus_clamped(sin_x, cos_x, sin_box, cos_box);
    if (cos_closest <= b.cos_emission) return 0.0f;
    float value = b.power * cos_closest / weighed2;
    if (n != Vec3(0.0f)) {
        // The receiving side's cosine, at its best over the box.
        const float cos_i = std::abs(glm::dot(wi, n));
        const float sin_i = safe_sqrt(1.0f - cos_i * cos_i);
        value *= cos_minus_clamped(sin_i, cos_i, sin_box, cos_box);
    }
    return std::isfinite(value) ? std::max(value, 0.0f) : 0.0f;
}

LightTree::LightTree(const std::vector<const Light*>& lights, Falloff falloff) : m_falloff(falloff) {
    std::vector<std::pair<const Light*, Bounds>> items;
    double total = 0.0;
    bool finite = true;
    for (const Light* light : lights) {
        Bounds bounds;
        if (light == nullptr || !bounds_of(*light, falloff, bounds) || !finite_box(bounds)) continue;
        // A negative light (valid POV) darkens as much as a positive one
        // lights: its magnitude weighs it.
        const double power = std::fabs(double(luminance(light->power())));
        finite = finite && std::isfinite(power);
        total += power;
        bounds.power = float(power);
        items.emplace_back(light, bounds);
    }
    if (items.empty()) return;
    const double mean = total / double(items.size());
    for (auto& [light, bounds] : items)
        bounds.power = !finite || !(total > 0.0) ? 1.0f : float(0.9 * double(bounds.power) + 0.1 * mean);
    m_nodes.reserve(2 * items.size());
    build(items, 0, items.size(), 0, 0);
}

std::uint32_t LightTree::build(std::vector<std::pair<const Light*, Bounds>>& lights, std::size_t begin, std::size_t end,
                               std::uint64_t trail, int depth) {
    const std::uint32_t index = std::uint32_t(m_nodes.size());
    m_nodes.emplace_back();
    if (end - begin == 1) {  // halving: depth < 64 for any count that fits in memory
        m_nodes[index].bounds = lights[begin].second;
        m_nodes[index].light = lights[begin].first;
        m_trails[lights[begin].first] = trail;
        return index;
    }
    Bounds all;
    Vec3 lower(std::numeric_limits<float>::infinity()), upper(-std::numeric_limits<float>::infinity());
    for (std::size_t i = begin; i < end; ++i) {
        all = merged(all, lights[i].second);
        const Vec3 centre = 0.5f * (lights[i].second.lower + lights[i].second.upper);
        lower = glm::min(lower, centre);
        upper = glm::max(upper, centre);
    }
    // Halve along the widest spread of the lights' centres.
    const Vec3 extent = upper - lower;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(lights.begin() + std::ptrdiff_t(begin), lights.begin() + std::ptrdiff_t(middle),
                     lights.begin() + std::ptrdiff_t(end), [axis](const auto& a, const auto& b) {
                         return a.second.lower[axis] + a.second.upper[axis] <
                                b.second.lower[axis] + b.second.upper[axis];
                     });
    m_nodes[index].bounds = all;
    const std::uint32_t left = build(lights, begin, middle, trail, depth + 1);
    const std::uint32_t right = build(lights, middle, end, trail | (std::uint64_t(1) << depth), depth + 1);
    m_nodes[index].children[0] = left;
    m_nodes[index].children[1] = right;
    return index;
}

float LightTree::left_share(const Node& node, const Vec3& p, const Vec3& n) const {
    const float left = importance(m_nodes[node.children[0]].bounds, p, n, m_falloff);
    const float right = importance(m_nodes[node.children[1]].bounds, p, n, m_falloff);
    if (!(left + right > 0.0f)) return -1.0f;
    return left / (left + right);
}

LightTree::Choice LightTree::sample(const Vec3& p, const Vec3& n, float u) const {
    Choice choice;
    if (m_nodes.empty()) return choice;
    std::uint32_t index = 0;
    float probability = 1.0f;
    while (m_nodes[index].light == nullptr) {
        const Node& node = m_nodes[index];
        const float p_left = left_share(node, p, n);
        if (p_left < 0.0f) return choice;  // neither side can reach p
        // Reuse u: rescaled into the chosen child's share of [0, 1).
        if (u < p_left) {
            index = node.children[0];
            probability *= p_left;
            u = std::min(u / p_left, 0x1.fffffep-1f);
        } else {
            index = node.children[1];
            probability *= 1.0f - p_left;
            u = std::min((u - p_left) / (1.0f - p_left), 0x1.fffffep-1f);
        }
    }
    if (!(probability > 0.0f)) return choice;
    choice.light = m_nodes[index].light;
    choice.probability = probability;
    return choice;
}

float LightTree::probability(const Vec3& p, const Vec3& n, const Light* light) const {
    const auto found = m_trails.find(light);
    if (found == m_trails.end()) return 0.0f;
    std::uint64_t bits = found->second;
    float probability = 1.0f;
    std::uint32_t index = 0;
    while (m_nodes[index].light == nullptr) {
        const Node& node = m_nodes[index];
        const float p_left = left_share(node, p, n);
        if (p_left < 0.0f) return 0.0f;
        const int side = int(bits & 1u);
        probability *= side == 0 ? p_left : 1.0f - p_left;  // as sample() computes it
        index = node.children[side];
        bits >>= 1;
    }
    return probability;
}

}  // namespace lancer
