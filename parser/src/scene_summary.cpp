// Scene summary for `lancer check` and tests.
#include "lancer/scene_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

namespace lancer {

const char* object_kind_name(sg::Object::Kind kind) {
    switch (kind) {
    case sg::Object::Kind::Sphere: return "sphere";
    case sg::Object::Kind::Plane: return "plane";
    case sg::Object::Kind::Box: return "box";
    case sg::Object::Kind::Triangle: return "triangle";
    case sg::Object::Kind::SmoothTriangle: return "smooth_triangle";
    case sg::Object::Kind::Mesh: return "mesh";
    case sg::Object::Kind::Mesh2: return "mesh2";
    case sg::Object::Kind::ObjMesh: return "obj_mesh";
    case sg::Object::Kind::Union: return "union";
    case sg::Object::Kind::Cylinder: return "cylinder";
    case sg::Object::Kind::Cone: return "cone";
    case sg::Object::Kind::Torus: return "torus";
    case sg::Object::Kind::Disc: return "disc";
    case sg::Object::Kind::Quadric: return "quadric";
    case sg::Object::Kind::Polygon: return "polygon";
    case sg::Object::Kind::Poly: return "poly";
    case sg::Object::Kind::Cubic: return "cubic";
    case sg::Object::Kind::Quartic: return "quartic";
    case sg::Object::Kind::Superellipsoid: return "superellipsoid";
    case sg::Object::Kind::Blob: return "blob";
    case sg::Object::Kind::Prism: return "prism";
    case sg::Object::Kind::Lathe: return "lathe";
    case sg::Object::Kind::Text: return "text";
    case sg::Object::Kind::Sor: return "sor";
    case sg::Object::Kind::Merge: return "merge";
    case sg::Object::Kind::Intersection: return "intersection";
    case sg::Object::Kind::Difference: return "difference";
    case sg::Object::Kind::Ovus: return "ovus";
    case sg::Object::Kind::SphereSweep: return "sphere_sweep";
    case sg::Object::Kind::BicubicPatch: return "bicubic_patch";
    case sg::Object::Kind::JuliaFractal: return "julia_fractal";
    case sg::Object::Kind::HeightField: return "height_field";
    case sg::Object::Kind::Isosurface: return "isosurface";
    case sg::Object::Kind::Parametric: return "parametric";
    }
    return "object";
}

const char* light_kind_name(sg::Light::Kind kind) {
    switch (kind) {
    case sg::Light::Kind::Point: return "point";
    case sg::Light::Kind::Directional: return "directional";
    case sg::Light::Kind::AreaRectangle: return "area_rectangle";
    case sg::Light::Kind::AreaSphere: return "area_sphere";
    }
    return "light";
}

namespace {

struct Walker {
    SceneSummary& summary;
    std::set<const void*> materials;

    void grow(const sg::Mat4& world_from_object, const sg::Vec3& p) {
        sg::Vec3 w(world_from_object * glm::dvec4(p, 1.0));
        if (!summary.bounds) summary.bounds = std::make_pair(w, w);
        summary.bounds->first = glm::min(summary.bounds->first, w);
        summary.bounds->second = glm::max(summary.bounds->second, w);
    }

    void grow_box(const sg::Mat4& m, const sg::Vec3& lo, const sg::Vec3& hi) {
        for (int corner = 0; corner < 8; ++corner) {
            grow(m, {corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z});
        }
    }

    void visit(const sg::Object& object, const sg::Mat4& world_from_parent) {
        sg::Mat4 world_from_object = world_from_parent * object.parent_from_object;
        ++summary.objects_by_kind[object_kind_name(object.kind)];
        ++summary.object_count;
        if (object.material) materials.insert(object.material.get());
        if (const auto* sphere = std::get_if<sg::Sphere>(&object.shape)) {
            grow_box(world_from_object, sphere->center - sg::Vec3(sphere->radius),
                     sphere->center + sg::Vec3(sphere->radius));
        } else if (const auto* box = std::get_if<sg::Box>(&object.shape)) {
            grow_box(world_from_object, box->corner1, box->corner2);
        } else if (const auto* cone = std::get_if<sg::Cone>(&object.shape)) {
            const double r = std::max(cone->base_radius, cone->cap_radius);
            grow_box(world_from_object, glm::min(cone->base, cone->cap) - sg::Vec3(r),
                     glm::max(cone->base, cone->cap) + sg::Vec3(r));
        } else if (const auto* torus = std::get_if<sg::Torus>(&object.shape)) {
            const double outer = torus->major_radius + torus->minor_radius;
            grow_box(world_from_object, sg::Vec3(-outer, -torus->minor_radius, -outer),
                     sg::Vec3(outer, torus->minor_radius, outer));
        } else if (const auto* disc = std::get_if<sg::Disc>(&object.shape)) {
            grow_box(world_from_object, disc->center - sg::Vec3(disc->radius), disc->center + sg::Vec3(disc->radius));
        } else if (std::holds_alternative<sg::Plane>(object.shape) ||
                   std::holds_alternative<sg::Quadric>(object.shape)) {
            ++summary.unbounded_objects;
        } else if (const auto* mesh = std::get_if<sg::MeshRef>(&object.shape)) {
            if (*mesh) {
                summary.triangles += static_cast<long long>((*mesh)->faces.size());
                for (const auto& p : (*mesh)->positions) grow(world_from_object, p);
                for (const auto& m : (*mesh)->materials) materials.insert(m.get());
            }
        } else if (const auto* group = std::get_if<sg::Group>(&object.shape)) {
            for (const auto& child : group->children) visit(child, world_from_object);
        }
    }
};

std::string vec_text(const sg::Vec3& v) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "<%g, %g, %g>", v.x, v.y, v.z);
    return buffer;
}

}  // namespace

SceneSummary summarize_scene(const sg::SceneGraph& scene) {
    SceneSummary summary;
    Walker walker{summary, {}};
    for (const auto& object : scene.objects) walker.visit(object, sg::Mat4(1.0));
    summary.materials = static_cast<int>(walker.materials.size());
    for (const auto& light : scene.lights) {
        ++summary.lights_by_kind[light.area_light ? "area_light" : light_kind_name(light.kind)];
        ++summary.light_count;
    }
    return summary;
}

std::string format_scene_summary(const SceneSummary& summary, const sg::SceneGraph& scene, int warnings,
                                 const std::string& default_integrator) {
    std::ostringstream out;
    out << scene.main_file << ": ok\n";
    out << "  objects:   " << summary.object_count;
    if (!summary.objects_by_kind.empty()) {
        out << " (";
        bool first = true;
        for (const auto& [kind, count] : summary.objects_by_kind) {
            out << (first ? "" : ", ") << count << " " << kind;
            first = false;
        }
        out << ")";
    }
    out << "\n  triangles: " << summary.triangles << "\n";
    out << "  lights:    " << summary.light_count;
    if (!summary.lights_by_kind.empty()) {
        out << " (";
        bool first = true;
        for (const auto& [kind, count] : summary.lights_by_kind) {
            out << (first ? "" : ", ") << count << " " << kind;
            first = false;
        }
        out << ")";
    }
    out << "\n  materials: " << summary.materials << "\n";
    out << "  bounds:    ";
    if (summary.bounds)
        out << vec_text(summary.bounds->first) << " to " << vec_text(summary.bounds->second);
    else
        out << "(no finite objects)";
    if (summary.unbounded_objects) out << " (" << summary.unbounded_objects << " infinite plane(s) excluded)";
    out << "\n  camera:    " << (scene.camera ? "from the scene" : "POV-Ray default") << "\n";
    if (scene.render.integrator)
        out << "  integrator: " << *scene.render.integrator << "\n";
    else if (!default_integrator.empty())
        out << "  integrator: " << default_integrator << " (the default: the scene names none)\n";
    out << "  warnings:  " << warnings << "\n";
    return out.str();
}

}  // namespace lancer
