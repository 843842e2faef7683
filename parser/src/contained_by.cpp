// contained_by { box { <a>, <b> } | sphere { <c>, r } }: what an isosurface
// or a parametric is drawn inside, as POV-Ray reads it (the box's corners
// ordered per axis).
#include "evaluator.h"

namespace lancer::parse {

std::function<void(sg::FunctionContainer&)> Evaluator::container_box(const Value& a, const SourceRange& wa,
                                                                     const Value& b, const SourceRange& wb) {
    const sg::Vec3 p = to_vec3(a, wa), q = to_vec3(b, wb);
    const double corners[6] = {p.x, p.y, p.z, q.x, q.y, q.z};
    if (!check_renderable(corners, 3, wa, "the container's corner") ||
        !check_renderable(corners + 3, 3, wb, "the container's corner"))
        return [](sg::FunctionContainer&) {};
    return [p, q](sg::FunctionContainer& iso) {
        iso.container = sg::FunctionContainer::Container::Box;
        iso.box_corner1 = glm::min(p, q);
        iso.box_corner2 = glm::max(p, q);
    };
}

std::function<void(sg::FunctionContainer&)> Evaluator::container_sphere(const Value& center, const SourceRange& wc,
                                                                        const Value& radius, const SourceRange& wr) {
    const sg::Vec3 c = to_vec3(center, wc);
    const double r = to_float(radius, wr, "a float radius");
    const double values[4] = {c.x, c.y, c.z, r};
    if (!check_renderable(values, 3, wc, "the container's centre") ||
        !check_renderable(values + 3, 1, wr, "the container's radius"))
        return [](sg::FunctionContainer&) {};
    if (!(r > 0.0)) {
        error(wr.begin, "contained_by: the container sphere's radius must be positive");
        return [](sg::FunctionContainer&) {};
    }
    return [c, r](sg::FunctionContainer& iso) {
        iso.container = sg::FunctionContainer::Container::Sphere;
        iso.sphere_center = c;
        iso.sphere_radius = r;
    };
}

}  // namespace lancer::parse
