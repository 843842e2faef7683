#include "lancer/finish_balance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace lancer {
namespace {

double max_channel(const sg::Vec3& v) {
    return std::max({v.x, v.y, v.z});
}

struct MaterialWalker {
    std::set<const sg::Material*> seen;
    std::vector<Diagnostic> warnings;

    void check(const sg::MaterialRef& material) {
        if (!material || !seen.insert(material.get()).second) return;
        const sg::Pigment& pigment = material->pigment;
        const double peak = pigment.kind == sg::Pigment::Kind::Solid ? max_channel(pigment.color.rgb) : 1.0;
        const double transparency = pigment.kind == sg::Pigment::Kind::Solid
                                        ? std::clamp(pigment.color.filter + pigment.color.transmit, 0.0, 1.0)
                                        : 0.0;
        const double bound = finish_reflectance_bound(*material->finish, peak, transparency);
        if (!(bound > 1.0 + 1e-9)) return;
        Diagnostic warning;
        warning.severity = Diagnostic::Severity::Warning;
        warning.location = material->finish->location.file ? material->finish->location : material->location;
        char share[32];
        std::snprintf(share, sizeof share, "%.3g", bound);
        warning.message = std::string("this finish returns up to ") + share +
                          " times the light it receives (POV's values are peaks, not albedos); path gains "
                          "energy at each bounce off it, bounded by max_depth";
        warnings.push_back(warning);
    }

    void visit(const sg::Object& object) {
        check(object.material);
        if (const auto* group = std::get_if<sg::Group>(&object.shape))
            for (const sg::Object& child : group->children) visit(child);
        if (const auto* mesh = std::get_if<sg::MeshRef>(&object.shape))
            if (*mesh)
                for (const sg::MaterialRef& face_material : (*mesh)->materials) check(face_material);
    }
};

}  // namespace

double finish_reflectance_bound(const sg::Finish& finish, double pigment_peak, double transparency) {
    const double opacity = 1.0 - transparency;
    double highlights = 0.0;
    if (finish.phong > 0.0) highlights += finish.phong * 2.0 / (finish.phong_size + 1.0);
    if (finish.specular > 0.0 && finish.roughness > 0.0) {
        const double k = 1.0 / finish.roughness;
        highlights += finish.specular * 8.0 * (1.0 - std::pow(2.0, -(k + 2.0) / 2.0)) / (k + 2.0);
    }
    const double mirror = std::max(max_channel(finish.reflection.min), max_channel(finish.reflection.max));
    const double passed = finish.conserve_energy ? transparency * std::max(0.0, 1.0 - mirror) : transparency;
    return opacity * (finish.diffuse * pigment_peak + highlights) + mirror + passed;
}

std::vector<Diagnostic> energy_gaining_finishes(const sg::SceneGraph& scene) {
    MaterialWalker walker;
    for (const sg::Object& object : scene.objects) walker.visit(object);
    return std::move(walker.warnings);
}

}  // namespace lancer
