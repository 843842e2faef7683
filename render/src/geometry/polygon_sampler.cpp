// Triangles of emissive meshes, sampled by world area.
#include "geometry/polygon_sampler.h"

namespace lancer {

std::unique_ptr<SurfaceSampler> make_triangle_sampler(std::vector<WorldTriangle> triangles) {
    std::vector<PolygonSampler::Polygon> polygons;
    polygons.reserve(triangles.size());
    for (const WorldTriangle& t : triangles) {
        PolygonSampler::Polygon p;
        p.origin = t.p[0];
        p.edge1 = t.p[1] - t.p[0];
        p.edge2 = t.p[2] - t.p[0];
        p.uv0 = t.uv[0];
        p.uv1 = t.uv[1];
        p.uv2 = t.uv[2];
        p.material = t.material;
        polygons.push_back(p);
    }
    return std::make_unique<PolygonSampler>(std::move(polygons), false);
}

}  // namespace lancer
