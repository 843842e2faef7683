// POV-Ray's media block: building sg::Media from the grammar's edits, with
// POV's checks (parstxtr.cpp Parse_Media) as errors at the value's location.
#include <cmath>
#include <limits>

#include "evaluator.h"

namespace lancer::parse {

void set_hollow(sg::Object& object, bool hollow) {
    object.hollow = hollow;
    if (auto* group = std::get_if<sg::Group>(&object.shape))
        for (sg::Object& child : group->children) set_hollow(child, hollow);
}

std::shared_ptr<sg::Media> Evaluator::build_media(const Edits<sg::Media>& edits, const sg::SourceLocation& at) {
    auto media = std::make_shared<sg::Media>();
    for (const auto& edit : edits) edit(*media);
    media->location = at;
    return media;
}

std::function<void(sg::Media&)> Evaluator::media_scattering(const Value& type, const SourceRange& type_at,
                                                            const Value& colour, const SourceRange& colour_at,
                                                            const Edits<sg::Media>& options) {
    int kind = to_int(type, type_at);
    if (kind < 1 || kind > 5) {
        error(type_at.begin,
              "scattering type must be 1 to 5 (isotropic, Mie hazy, Mie murky, Rayleigh, "
              "Henyey-Greenstein), got " +
                  std::to_string(kind));
        kind = 1;
    }
    const sg::Vec3 coefficient = to_color(colour, colour_at).rgb;
    // POV refuses an eccentricity on any type but Henyey-Greenstein's.
    sg::Media probe;
    probe.eccentricity = std::numeric_limits<double>::quiet_NaN();
    for (const auto& option : options) option(probe);
    const bool has_eccentricity = !std::isnan(probe.eccentricity);
    if (has_eccentricity && kind != 5)
        error(type_at.begin, "eccentricity is only for scattering type 5 (Henyey-Greenstein)");
    if (has_eccentricity && !(std::fabs(probe.eccentricity) < 1.0))
        error(type_at.begin, "eccentricity must lie strictly between -1 and 1");
    const auto type_value = static_cast<sg::Media::ScatteringType>(kind);
    return [type_value, coefficient, options](sg::Media& m) {
        m.scattering_type = type_value;
        m.scattering = coefficient;
        m.eccentricity = 0.0;
        m.extinction = 1.0;
        for (const auto& option : options) option(m);
    };
}

std::function<void(sg::Media&)> Evaluator::media_integer(const std::string& name, const Value& v,
                                                         const SourceRange& where, int lowest, int highest) {
    int value = to_int(v, where);
    if (value < lowest || value > highest) {
        error(where.begin, "media " + name + " must lie in [" + std::to_string(lowest) + ", " +
                               std::to_string(highest) + "], got " + std::to_string(value));
        value = lowest;
    }
    if (name == "method") return [value](sg::Media& m) { m.method = value; };
    if (name == "intervals") return [value](sg::Media& m) { m.intervals = value; };
    return [value](sg::Media& m) { m.aa_level = value; };
}

std::function<void(sg::Media&)> Evaluator::media_real(const std::string& name, const Value& v, const SourceRange& where,
                                                      double lowest, double highest) {
    double value = to_float(v, where, "a float for media " + name);
    // POV: confidence in [0, 1), aa_threshold above 0, the others not negative.
    const bool open_top = name == "confidence", open_bottom = name == "aa_threshold";
    const bool fits = std::isfinite(value) && (open_bottom ? value > lowest : value >= lowest) &&
                      (open_top ? value < highest : value <= highest);
    if (!fits) {
        error(where.begin, "media " + name + " out of range: " + std::to_string(value));
        value = open_bottom ? 0.1 : lowest;
    }
    if (name == "confidence") return [value](sg::Media& m) { m.confidence = value; };
    if (name == "variance") return [value](sg::Media& m) { m.variance = value; };
    if (name == "ratio") return [value](sg::Media& m) { m.ratio = value; };
    if (name == "aa_threshold") return [value](sg::Media& m) { m.aa_threshold = value; };
    return [value](sg::Media& m) { m.jitter = value; };
}

std::function<void(sg::Media&)> Evaluator::media_samples(const Value& min, const SourceRange& min_at, const Value& max,
                                                         const SourceRange& max_at) {
    // A bound on the work per interval, far above what any scene asks.
    constexpr int kMostSamples = 1 << 16;
    int lowest = to_int(min, min_at), highest = to_int(max, max_at);
    if (lowest < 1 || lowest > kMostSamples) {
        error(min_at.begin,
              "media samples must lie in [1, " + std::to_string(kMostSamples) + "], got " + std::to_string(lowest));
        lowest = 1;
    }
    if (highest < lowest || highest > kMostSamples) {
        error(max_at.begin, "media's maximum samples must lie in [minimum, " + std::to_string(kMostSamples) +
                                "], got " + std::to_string(highest));
        highest = lowest;
    }
    return [lowest, highest](sg::Media& m) {
        m.samples_min = lowest;
        m.samples_max = highest;
    };
}

}  // namespace lancer::parse
