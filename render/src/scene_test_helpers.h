// Small builders for scene graphs in tests (no parser involved).
#pragma once

#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "lancer/render_scene.h"
#include "lancer/scene_graph.h"

namespace lancer::testing {

inline sg::MaterialRef solid_material(const glm::dvec3& rgb, double diffuse = 0.6, glm::dvec3 emission = {}) {
    auto m = std::make_shared<sg::Material>();
    m->pigment.color.rgb = rgb;
    m->finish->diffuse = diffuse;
    m->finish->emission = emission;
    return m;
}

inline sg::Object sphere_object(const glm::dvec3& center, double radius, sg::MaterialRef material = nullptr) {
    sg::Object o;
    o.kind = sg::Object::Kind::Sphere;
    o.shape = sg::Sphere{center, radius};
    o.material = std::move(material);
    return o;
}

inline sg::Object box_object(const glm::dvec3& a, const glm::dvec3& b, sg::MaterialRef material = nullptr) {
    sg::Object o;
    o.kind = sg::Object::Kind::Box;
    o.shape = sg::Box{a, b};
    o.material = std::move(material);
    return o;
}

inline sg::Object plane_object(const glm::dvec3& normal, double distance, sg::MaterialRef material = nullptr) {
    sg::Object o;
    o.kind = sg::Object::Kind::Plane;
    o.shape = sg::Plane{normal, distance};
    o.material = std::move(material);
    return o;
}

inline sg::MeshRef triangle_mesh(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    auto mesh = std::make_shared<sg::TriangleMesh>();
    mesh->positions = {a, b, c};
    sg::TriangleMesh::Face face;
    face.position[0] = 0;
    face.position[1] = 1;
    face.position[2] = 2;
    mesh->faces.push_back(face);
    return mesh;
}

inline sg::Object mesh_object(sg::MeshRef mesh, sg::MaterialRef material = nullptr,
                              const glm::dmat4& parent_from_object = glm::dmat4(1.0)) {
    sg::Object o;
    o.kind = sg::Object::Kind::Mesh;
    o.shape = std::move(mesh);
    o.material = std::move(material);
    o.parent_from_object = parent_from_object;
    return o;
}

inline Ray make_ray(const Vec3& origin, const Vec3& direction) {
    Ray r;
    r.origin = origin;
    r.direction = glm::normalize(direction);
    return r;
}

}  // namespace lancer::testing
