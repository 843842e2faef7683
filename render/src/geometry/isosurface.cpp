// POV-Ray's isosurface, searched as POV-Ray 3.7 searches it (its
// isosurf.cpp, read for the method): along the ray's chord through the
// container, f = function - threshold is sampled at the ends of an
// interval; while f(a) + f(b) < max_gradient * |d| * (b - a) the function,
// if no steeper than max_gradient, may dip below zero inside, so the
// interval is halved, the near half first, down to `accuracy`, and the
// far end of the first small interval where f < 0 is the crossing. The
// solid is where f < 0. A closed isosurface's container walls are part of
// its surface where they cut the solid.
#include "geometry/isosurface.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

namespace lancer {

namespace {

// Faces a crossing reports: the function's surface, then the container's
// walls (box sides in POV's order -x +x -y +y -z +z, or the sphere).
constexpr int kFunctionFace = 0;
constexpr int kFirstBoxSide = 1;
constexpr int kSphereWall = 7;

// A ray's search gives up after this many function evaluations (POV-Ray
// has no limit): a container millions of accuracy steps long with a huge
// max_gradient would otherwise take minutes per ray. Halving down to the
// accuracy everywhere costs about 2 x chord / accuracy evaluations, so a
// chord of 100 000 accuracy steps (100 units at POV's default 0.001) is
// still searched in full.
constexpr long kMostEvaluationsPerSearch = 1L << 18;

// How far the ray's origin lies from 0, in steps of d, on the axis where
// that is least among those the ray really moves along (a component of d
// a quarter of its largest or more: rounding noise in a turned direction
// must not count): the coordinate whose doubles t moves across soonest.
double origin_reach(const DVec3& o, const DVec3& d) {
    const double largest = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    double reach = HUGE_VAL;
    for (int axis = 0; axis < 3; ++axis)
        if (std::fabs(d[axis]) >= 0.25 * largest) reach = std::min(reach, std::fabs(o[axis] / d[axis]));
    return reach;
}

// Where a line crosses the container: entry and exit parameters and walls.
struct Chord {
    double enter = 0.0, exit = 0.0;
    int enter_face = kSphereWall, exit_face = kSphereWall;
};

class IsosurfaceShape final : public Shape {
  public:
    IsosurfaceShape(const IsosurfaceParameters& p, std::shared_ptr<IsosurfaceGradientRecord> gradients)
        : m_p(p), m_gradients(std::move(gradients)) {}

    bool finds_crossings_past_t_min() const override { return false; }
    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        Chord chord;
        if (!container_chord(o, d, chord)) return;
        Search search{*this, o, d, glm::length(d), origin_reach(o, d)};
        if (!(search.length > 0.0) || !std::isfinite(search.length)) return;
        // Steps off a surface the ray starts on are no shorter than the
        // doubles can tell apart there (an `accuracy` of 1e-20 would step
        // nowhere and find the start again).
        const double accuracy = std::max(m_p.accuracy, search.resolution(0.0));
        const double near_surface = m_p.max_gradient * accuracy * 4.0;

        ShapeCrossings found;
        double start = std::max(chord.enter, 0.0);
        const double end = chord.exit;
        int traces = 0;
        // Closed: a ray entering the container where the function is
        // already below zero meets the wall first; a ray starting inside the
        // container (and near or inside the solid) steps off its start, and
        // leaves through the wall where the solid reaches it.
        if (!m_p.open) {
            const double at_start = search.value(start);
            if (start > accuracy) {
                if (at_start < 0.0) {
                    found.add(start, chord.enter_face);
                    ++traces;
                    search.sign = -1.0;
                }
            } else {
                if (at_start < near_surface) {
                    start = accuracy * 5.0;
                    if (search.value(start) < 0.0) search.sign = -1.0;
                }
                if (search.value(end) < 0.0) found.add(end, chord.exit_face);
            }
        }
        if (end - start < accuracy) return;
        if (start < accuracy && search.sign > 0.0 && std::fabs(search.value(start)) < near_surface) {
            // Starting on the surface (a shadow or reflected ray): look past
            // it, for the way out if the ray heads into the solid.
            start = accuracy * 5.0;
            if (search.value(start) < 0.0) search.sign = -1.0;
        }
        for (; traces < m_p.max_trace; ++traces) {
            double root = 0.0;
            if (!search.first_root(start, end, root)) break;
            found.add(root, kFunctionFace);
            start = root + accuracy * 5.0;
            if (end - start < accuracy) break;
            search.sign = -search.sign;
        }
        if (m_gradients && search.steepest > 0.0) m_gradients->record(search.steepest);
        for (int i = 0; i < found.count; ++i)
            if (found.items[i].t > t_min && found.items[i].t < t_max) out.add(found.items[i].t, found.items[i].face);
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        SurfaceGeometry g;
        g.point = p;
        g.uv = Vec2(0.0f);
        if (face >= kFirstBoxSide && face < kFirstBoxSide + 6) {
            const int side = face - kFirstBoxSide;
            g.normal = DVec3(0.0);
            g.normal[side / 2] = side % 2 == 0 ? -1.0 : 1.0;
            return g;
        }
        if (face == kSphereWall) {
            g.normal = (p - m_p.container.sphere_center) / m_p.container.sphere_radius;
            return g;
        }
        // POV's normal: forward differences one accuracy step long.
        const double h = m_p.accuracy;
        const double here = function_at(p);
        DVec3 n(function_at(p + DVec3(h, 0.0, 0.0)) - here, function_at(p + DVec3(0.0, h, 0.0)) - here,
                function_at(p + DVec3(0.0, 0.0, h)) - here);
        const double length = glm::length(n);
        g.normal = length > 0.0 && std::isfinite(length) ? n / length : DVec3(1.0, 0.0, 0.0);
        return g;
    }

    bool inside(const DVec3& p) const override {
        if (m_p.container.sphere) {
            const DVec3 r = p - m_p.container.sphere_center;
            if (glm::dot(r, r) > m_p.container.sphere_radius * m_p.container.sphere_radius) return false;
        } else {
            for (int axis = 0; axis < 3; ++axis)
                if (p[axis] < m_p.container.box_lower[axis] || p[axis] > m_p.container.box_upper[axis]) return false;
        }
        return !(function_at(p) - m_p.threshold > 0.0);
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        m_p.container.bounds(lower, upper);
        return true;
    }

  private:
    double function_at(const DVec3& p) const {
        const double arguments[3] = {p.x, p.y, p.z};
        return sg::evaluate_function(*m_p.function, arguments, 3, m_p.natives.get());
    }

    bool container_chord(const DVec3& o, const DVec3& d, Chord& chord) const {
        if (m_p.container.sphere) {
            // |o + t d - c|^2 = r^2, solved from the point nearest the centre
            // so far origins keep their digits.
            const double dd = glm::dot(d, d);
            if (!(dd > 0.0)) return false;
            const DVec3 oc = o - m_p.container.sphere_center;
            const double along = -glm::dot(oc, d) / dd;
            const DVec3 closest = oc + along * d;
            const double half2 =
                (m_p.container.sphere_radius * m_p.container.sphere_radius - glm::dot(closest, closest)) / dd;
            if (!(half2 > 0.0)) return false;
            const double half = std::sqrt(half2);
            chord.enter = along - half;
            chord.exit = along + half;
            chord.enter_face = chord.exit_face = kSphereWall;
            return chord.exit > 0.0;
        }
        double enter = -HUGE_VAL, exit = HUGE_VAL;
        for (int axis = 0; axis < 3; ++axis) {
            const double lower = m_p.container.box_lower[axis], upper = m_p.container.box_upper[axis];
            if (d[axis] == 0.0) {
                if (o[axis] < lower || o[axis] > upper) return false;
                continue;
            }
            const double t_lower = (lower - o[axis]) / d[axis], t_upper = (upper - o[axis]) / d[axis];
            const bool lower_first = t_lower < t_upper;
            const double near = lower_first ? t_lower : t_upper, far = lower_first ? t_upper : t_lower;
            if (near > enter) {
                enter = near;
                chord.enter_face = kFirstBoxSide + 2 * axis + (lower_first ? 0 : 1);
            }
            if (far < exit) {
                exit = far;
                chord.exit_face = kFirstBoxSide + 2 * axis + (lower_first ? 1 : 0);
            }
        }
        if (!(enter <= exit) || !(exit > 0.0)) return false;
        chord.enter = enter;
        chord.exit = exit;
        return true;
    }

    // One ray's search: f along the ray, signed so that the side being
    // looked for is negative (sign -1 looks for the way out of the solid).
    struct Search {
        const IsosurfaceShape& shape;
        DVec3 origin, direction;
        double length;  // |direction|: slopes per unit of object space
        double reach;   // origin_reach(origin, direction)
        double sign = 1.0;
        double steepest = 0.0;
        double max_gradient = shape.m_p.max_gradient;
        long evaluations = 0;

        double value(double t) {
            ++evaluations;
            return shape.function_at(origin + t * direction) - shape.m_p.threshold;
        }
        double signed_value(double t) { return sign * value(t); }

        // The shortest interval near t whose ends are points the doubles
        // tell apart on the axis that tells them apart first: below it the
        // function's values are rounding noise, and halving them all (an
        // `accuracy` of 1e-20 asks for that) costs tens of thousands of
        // evaluations a ray for no digit.
        double resolution(double t) const { return 4.0 * DBL_EPSILON * (reach + std::fabs(t)); }

        bool first_root(double a, double b, double& root) {
            const IsosurfaceParameters& p = shape.m_p;
            double fa = signed_value(a);
            if (p.open && fa < 0.0) {
                // An open isosurface seen from inside its solid: the way out.
                sign = -sign;
                fa = -fa;
            }
            const double fb = signed_value(b);
            if (p.evaluate && max_gradient > p.evaluate_parameters.x) max_gradient *= p.evaluate_parameters.z;
            return halve(a, fa, b, fb, root);
        }

        bool halve(double a, double fa, double b, double fb, double& root) {
            const IsosurfaceParameters& p = shape.m_p;
            const double span = b - a;
            const double slope = std::fabs(fb - fa) / (length * span);
            if (slope > steepest && std::isfinite(slope)) steepest = slope;
            if (p.evaluate && max_gradient < slope * p.evaluate_parameters.y)
                max_gradient = slope * p.evaluate_parameters.y * p.evaluate_parameters.y;
            const double middle = a + 0.5 * span;
            // An interval that doubles cannot split any more (a ray's
            // parameter near 1e30, from an isosurface scaled that much,
            // has steps far above any accuracy) counts as short enough:
            // halving it again would recurse without end.
            if (span < p.accuracy || span < resolution(b) || !(middle > a && middle < b)) {
                if (!(fb < 0.0)) return false;
                root = b;
                return true;
            }
            if (!(fa + fb - max_gradient * length * span < 0.0)) return false;
            if (evaluations >= kMostEvaluationsPerSearch) return false;
            const double fm = signed_value(middle);
            return halve(a, fa, middle, fm, root) || halve(middle, fm, b, fb, root);
        }
    };

    IsosurfaceParameters m_p;
    std::shared_ptr<IsosurfaceGradientRecord> m_gradients;
};

bool finite(const DVec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::shared_ptr<const Shape> make_isosurface_shape(const IsosurfaceParameters& parameters,
                                                   std::shared_ptr<IsosurfaceGradientRecord> gradients) {
    const IsosurfaceParameters& p = parameters;
    if (!p.function) return nullptr;
    if (!p.container.usable() || !std::isfinite(p.threshold) || !(p.accuracy > 0.0) || !std::isfinite(p.accuracy) ||
        !(p.max_gradient > 0.0) || !std::isfinite(p.max_gradient) || !finite(p.evaluate_parameters))
        return nullptr;
    IsosurfaceParameters kept = p;
    kept.max_trace = std::clamp(p.max_trace, 1, 10);
    kept.container = p.container.ordered();
    return std::make_shared<IsosurfaceShape>(kept, std::move(gradients));
}

std::optional<std::string> isosurface_gradient_advice(const IsosurfaceParameters& parameters,
                                                      const IsosurfaceGradientRecord& gradients) {
    if (parameters.evaluate) return std::nullopt;
    const double found = gradients.steepest(), given = parameters.max_gradient;
    constexpr double kNegligible = 1e-10;
    if (!(found > kNegligible) || !(given > kNegligible)) return std::nullopt;
    // POV-Ray's thresholds: it is lenient on purpose.
    const double difference = given - found, ratio = std::fabs(given / found);
    char text[256];
    if ((ratio <= 0.9 && difference <= -0.5) || ((ratio <= 0.95 || difference <= -0.1) && given < 10.0)) {
        std::snprintf(text, sizeof text,
                      "the steepest gradient found was %.3f but max_gradient is %.3f: the isosurface may have holes; "
                      "raise max_gradient",
                      found, given);
        return std::string(text);
    }
    if (difference >= 10.0 || (ratio >= 1.1 && difference >= 0.5)) {
        std::snprintf(text, sizeof text,
                      "the steepest gradient found was %.3f but max_gradient is %.3f: lowering max_gradient would "
                      "render the isosurface faster",
                      found, given);
        return std::string(text);
    }
    return std::nullopt;
}

}  // namespace lancer
