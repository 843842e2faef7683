// POV-Ray's ripples and waves: sums of sine waves spreading from
// number_of_waves fixed sources (pattern_random.cpp makes them), as values
// and as normals. The pattern's frequency and phase act inside the sum
// (and, for the values, once more in the pipeline, as in POV).
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

// Distance from a source; POV takes 1 at the source itself.
double source_distance(const glm::dvec3& offset) {
    const double length = std::sqrt(offset.x * offset.x + offset.y * offset.y + offset.z * offset.z);
    return length == 0.0 ? 1.0 : length;
}

}  // namespace

double ripples_pattern(const PatternSetup& s, const glm::dvec3& p) {
    double sum = 0.0;
    for (const glm::dvec3& source : s.wave_sources) {
        sum += cycloidal(source_distance(p - source) * s.frequency + s.phase);
    }
    return 0.5 * (1.0 + sum / double(s.wave_sources.size()));
}

double waves_pattern(const PatternSetup& s, const glm::dvec3& p) {
    double sum = 0.0;
    for (std::size_t i = 0; i < s.wave_sources.size(); ++i) {
        const double length = source_distance(p - s.wave_sources[i]);
        const double f = s.wave_frequencies[i];
        sum += cycloidal(length * s.frequency * f + s.phase) / f;
    }
    return 0.2 * (2.5 + sum / double(s.wave_sources.size()));
}

void ripples_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal) {
    const double count = double(s.wave_sources.size());
    for (const glm::dvec3& source : s.wave_sources) {
        const glm::dvec3 offset = p - source;
        const double length = source_distance(offset);
        const double height = cycloidal(length * s.frequency + s.phase) * amount;
        normal += (height / (length * count)) * offset;
    }
}

void waves_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal) {
    const double count = double(s.wave_sources.size());
    for (std::size_t i = 0; i < s.wave_sources.size(); ++i) {
        const glm::dvec3 offset = p - s.wave_sources[i];
        const double length = source_distance(offset);
        const double f = s.wave_frequencies[i];
        const double height = cycloidal(length * s.frequency * f + s.phase) * amount / f;
        normal += (height / (length * count)) * offset;
    }
}

}  // namespace lancer::pattern_detail
