#include "lancer/fog.h"

#include <algorithm>
#include <cmath>

#include "materials/noise.h"

namespace lancer {

SceneFog::SceneFog(std::vector<FogLayer> layers, int noise_generator)
    : m_layers(std::move(layers)), m_noise_generator(noise_generator) {}

namespace {

// The mean density of ground fog between heights start and end (in
// fog_alts above fog_offset): 1 below the offset, 1/(1+h^2) above, whose
// integral is atan(h).
double ground_density(double start, double end) {
    if (start <= 0.0) {
        if (end <= 0.0) return 1.0;
        return (std::atan(end) - start) / (end - start);
    }
    if (end <= 0.0) return (std::atan(start) - end) / (start - end);
    const double delta = start - end;
    if (std::abs(delta) > 1e-10) return (std::atan(start) - std::atan(end)) / delta;
    return 1.0 / (start * start + 1.0);
}

}  // namespace

double SceneFog::layer_transmittance(const FogLayer& fog, const Vec3& origin, const Vec3& direction,
                                     double width) const {
    const glm::dvec3 from(origin);
    const glm::dvec3 along(direction);
    double density = 1.0;
    glm::dvec3 middle = from + along * (width / 2.0);
    if (fog.ground) {
        const glm::dvec3 up(fog.up);
        const double start = (glm::dot(from, up) - fog.offset) / fog.alt;
        const double end = (glm::dot(from + along * width, up) - fog.offset) / fog.alt;
        density = ground_density(start, end);
    }
    if (fog.turbulent) {
        // The further away, the less the turbulence shows.
        const double fade = std::exp(-width / fog.distance);
        const double value = pov_turbulence(middle * glm::dvec3(fog.turbulence), fog.omega, fog.lambda, fog.octaves,
                                            NoiseGenerator(m_noise_generator));
        width *= 1.0 - fade * std::min(1.0, value * fog.turb_depth);
    }
    return std::exp(-width * density / fog.distance);
}

SceneFog::Passage SceneFog::passage(const Vec3& origin, const Vec3& direction, float distance) const {
    Passage result;
    for (const FogLayer& fog : m_layers) {
        if (std::abs(fog.distance) <= 1e-10f) continue;
        const float through = std::max(float(layer_transmittance(fog, origin, direction, distance)), fog.transmit);
        // Filtered fog tints what it lets through by its colour.
        result.attenuation *= through * (Color(1.0f - fog.filter) + fog.filter * fog.color);
        result.added += (1.0f - through) * fog.color;
    }
    return result;
}

Color SceneFog::seen_through(const Vec3& origin, const Vec3& direction, float distance, const Color& behind) const {
    const Passage fogged = passage(origin, direction, distance);
    return fogged.added + fogged.attenuation * behind;
}

Color SceneFog::transmittance(const Vec3& origin, const Vec3& direction, float distance) const {
    return passage(origin, direction, distance).attenuation;
}

}  // namespace lancer
