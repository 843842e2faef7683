// The render core's answers to a scene's trace(), inside(), min_extent()
// and max_extent() while it is parsed: each object asked about is built
// once, alone, as a render scene (shapes only: its textures are left out,
// so no image is read for a question about shape), and kept while the
// object lives (a scene that grows a union in a loop, asking about each
// new one, holds one built scene at a time, not all).
#include <map>

#include "geometry/embree_scene.h"
#include "host/scene_builder.h"
#include "lancer/host/scene_compiler.h"

namespace lancer {

namespace {

// The object without its textures, which a shape question never needs.
sg::Object shape_only(const sg::Object& object) {
    sg::Object copy = object;
    copy.material = nullptr;
    copy.inherits_material = false;
    if (auto* group = std::get_if<sg::Group>(&copy.shape))
        for (sg::Object& child : group->children) child = shape_only(child);
    for (sg::Object& clip : copy.clipped_by) clip = shape_only(clip);
    return copy;
}

class ParseTimeGeometry final : public sg::GeometryQueries {
  public:
    Crossing trace(const std::shared_ptr<const sg::Object>& object, const sg::GlobalSettings& settings,
                   const glm::dvec3& origin, const glm::dvec3& direction) const override {
        const Built& b = built(object, settings);
        Ray ray;
        ray.origin = Vec3(origin);
        ray.direction = Vec3(glm::normalize(direction));
        Hit hit;
        Crossing crossing;
        if (!b.scene->intersect(ray, hit)) return crossing;
        crossing.found = true;
        crossing.point = glm::dvec3(hit.position);
        crossing.normal = glm::dvec3(hit.shading_normal);
        return crossing;
    }

    bool inside(const std::shared_ptr<const sg::Object>& object, const sg::GlobalSettings& settings,
                const glm::dvec3& point) const override {
        return built(object, settings).inside(point);
    }

    bool bounds(const std::shared_ptr<const sg::Object>& object, const sg::GlobalSettings& settings, glm::dvec3& lower,
                glm::dvec3& upper) const override {
        const Built& b = built(object, settings);
        for (const Instance& instance : b.data->instances)
            if (!instance.csg_leaf && !instance.bounded) return false;
        if (b.data->bounds.empty()) return false;
        lower = glm::dvec3(b.data->bounds.lower);
        upper = glm::dvec3(b.data->bounds.upper);
        return true;
    }

  private:
    struct Built {
        std::weak_ptr<const sg::Object> object;  // expired: the address may be another object's
        int noise_generator = 0;                 // the one global setting a shape can depend on
        const SceneData* data = nullptr;
        std::unique_ptr<RenderScene> scene;
        InsideTest inside;
    };

    const Built& built(const std::shared_ptr<const sg::Object>& object, const sg::GlobalSettings& settings) const {
        for (auto i = m_built.begin(); i != m_built.end();) i = i->second.object.expired() ? m_built.erase(i) : ++i;
        auto found = m_built.find(object.get());
        // A noise_generator set between two questions: built again, as
        // POV-Ray would answer the second with the new one.
        if (found != m_built.end() && found->second.noise_generator == settings.noise_generator) return found->second;
        if (found != m_built.end()) m_built.erase(found);
        Built b;
        b.object = object;
        b.noise_generator = settings.noise_generator;
        auto data = build_object_scene_data(shape_only(*object), settings, b.inside);
        b.data = data.get();
        b.scene = make_embree_scene(std::move(data));
        return m_built.emplace(object.get(), std::move(b)).first->second;
    }

    mutable std::map<const sg::Object*, Built> m_built;
};

}  // namespace

std::unique_ptr<sg::GeometryQueries> make_parse_time_geometry_queries() {
    return std::make_unique<ParseTimeGeometry>();
}

}  // namespace lancer
