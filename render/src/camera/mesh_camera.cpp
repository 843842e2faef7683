// POV-Ray 3.7's mesh_camera (mesh_camera.h); the pixel-to-face rules are
// POV's CreateCameraRay, kept with their quirks, since scenes were made
// against them.
#include "camera/mesh_camera.h"

#include <algorithm>
#include <cmath>

namespace lancer {
namespace {

using DVec3 = glm::dvec3;

// POV's face normal: (P3 - P1) x (P2 - P1), unit; zero for a face whose
// corners are collinear (mesh2 keeps such faces).
DVec3 face_normal(const MeshCameraFace& face) {
    const DVec3 n = glm::cross(face.corners[2] - face.corners[0], face.corners[1] - face.corners[0]);
    const double length = glm::length(n);
    return length > 0.0 ? n / length : DVec3(0.0);
}

glm::dmat3 normals_transform(const glm::dmat4& world_from_mesh) {
    return glm::transpose(glm::inverse(glm::dmat3(world_from_mesh)));
}

}  // namespace

void MeshCameraRays::place(const DVec3& point, const DVec3& normal, const glm::dmat4& world_from_mesh,
                           const glm::dmat3& world_from_mesh_normals, DVec3& origin, DVec3& direction) const {
    // POV moves the start along the normal as it is (the smoothed normal
    // is not unit), then turns the direction, then applies the mesh's
    // transforms: the offset is in the mesh's units.
    const DVec3 start = point + m_settings.start_offset * normal;
    origin = DVec3(world_from_mesh * glm::dvec4(start, 1.0));
    direction = world_from_mesh_normals * (m_settings.reversed ? -normal : normal);
}

void MeshCameraRays::add_mesh(const std::vector<MeshCameraFace>& faces, const glm::dmat4& world_from_mesh) {
    const glm::dmat3 normals = normals_transform(world_from_mesh);
    if (m_settings.distribution == Distribution::UvMapped) {
        // Type 3 reads the first mesh only (POV warns about the others).
        if (m_meshes.empty()) {
            m_uv_faces = faces;
            m_uv_world_from_mesh = world_from_mesh;
            m_uv_world_from_mesh_normals = normals;
            index_uv_faces();
        }
        m_meshes.emplace_back();
        m_face_ends.push_back((m_face_ends.empty() ? 0 : m_face_ends.back()) + std::uint32_t(faces.size()));
        return;
    }
    // Types 0 to 2 always start at a face's centroid: one ray per face.
    Mesh mesh;
    mesh.rays.reserve(faces.size());
    for (const MeshCameraFace& face : faces) {
        const DVec3 normal = face_normal(face);
        FaceRay ray{glm::vec3(0.0f), glm::vec3(0.0f)};
        if (normal != DVec3(0.0)) {
            const DVec3 centroid = (face.corners[0] + face.corners[1] + face.corners[2]) / 3.0;
            DVec3 origin, direction;
            place(centroid, normal, world_from_mesh, normals, origin, direction);
            ray = FaceRay{glm::vec3(origin), glm::vec3(glm::normalize(direction))};
        }
        mesh.rays.push_back(ray);
    }
    m_meshes.push_back(std::move(mesh));
    m_face_ends.push_back((m_face_ends.empty() ? 0 : m_face_ends.back()) + std::uint32_t(faces.size()));
}

void MeshCameraRays::index_uv_faces() {
    // A face's cells: those its uv bounds meet, clamped to the square (the
    // query points lie in it, and clamping keeps every face that holds one).
    const auto n = m_uv_faces.size();
    struct Span {
        int u0, u1, v0, v1;
    };
    std::vector<Span> spans(n);
    auto cell = [this](double t) { return std::clamp(int(std::floor(t * m_grid)), 0, m_grid - 1); };
    auto count_entries = [&] {
        std::size_t entries = 0;
        for (std::size_t f = 0; f < n; ++f) {
            const glm::dvec2* uv = m_uv_faces[f].uv;
            const double lo_u = std::min({uv[0].x, uv[1].x, uv[2].x}), hi_u = std::max({uv[0].x, uv[1].x, uv[2].x});
            const double lo_v = std::min({uv[0].y, uv[1].y, uv[2].y}), hi_v = std::max({uv[0].y, uv[1].y, uv[2].y});
            if (!(std::isfinite(lo_u) && std::isfinite(hi_u) && std::isfinite(lo_v) && std::isfinite(hi_v))) {
                spans[f] = Span{0, -1, 0, -1};  // never found
                continue;
            }
            spans[f] = Span{cell(lo_u), cell(hi_u), cell(lo_v), cell(hi_v)};
            entries += std::size_t(spans[f].u1 - spans[f].u0 + 1) * std::size_t(spans[f].v1 - spans[f].v0 + 1);
        }
        return entries;
    };
    // About one face per cell; coarser while big faces would fill the grid.
    m_grid = std::clamp(int(std::sqrt(double(n))), 1, 1024);
    while (count_entries() > 16 * n + std::size_t(m_grid) * m_grid && m_grid > 1) m_grid /= 2;

    m_cell_starts.assign(std::size_t(m_grid) * m_grid + 1, 0);
    for (const Span& s : spans)
        for (int v = s.v0; v <= s.v1; ++v)
            for (int u = s.u0; u <= s.u1; ++u) ++m_cell_starts[std::size_t(v) * m_grid + u + 1];
    for (std::size_t c = 1; c < m_cell_starts.size(); ++c) m_cell_starts[c] += m_cell_starts[c - 1];
    m_cell_faces.assign(m_cell_starts.back(), 0);
    std::vector<std::uint32_t> filled(m_cell_starts.begin(), m_cell_starts.end() - 1);
    // Faces in order, so each cell's list is in face order.
    for (std::size_t f = 0; f < n; ++f)
        for (int v = spans[f].v0; v <= spans[f].v1; ++v)
            for (int u = spans[f].u0; u <= spans[f].u1; ++u)
                m_cell_faces[filled[std::size_t(v) * m_grid + u]++] = std::uint32_t(f);
}

bool MeshCameraRays::face_ray(const Mesh& mesh, std::uint32_t face, DVec3& origin, DVec3& direction) const {
    if (face >= mesh.rays.size()) return false;
    const FaceRay& ray = mesh.rays[face];
    if (ray.direction == glm::vec3(0.0f)) return false;
    origin = DVec3(ray.origin);
    direction = DVec3(ray.direction);
    return true;
}

bool MeshCameraRays::uv_mapped_ray(double u, double v, DVec3& origin, DVec3& direction) const {
    const int cu = std::clamp(int(std::floor(u * m_grid)), 0, m_grid - 1);
    const int cv = std::clamp(int(std::floor(v * m_grid)), 0, m_grid - 1);
    const std::size_t c = std::size_t(cv) * m_grid + cu;
    // The first face (in POV's order) whose uv triangle holds (u, v).
    for (std::uint32_t i = m_cell_starts[c]; i < m_cell_starts[c + 1]; ++i) {
        const MeshCameraFace& face = m_uv_faces[m_cell_faces[i]];
        const glm::dvec2 &p1 = face.uv[0], &p2 = face.uv[1], &p3 = face.uv[2];
        // POV's barycentric coordinates of (u, v) in the uv triangle.
        const double scale = (p2.x - p1.x) * (p3.y - p1.y) - (p3.x - p1.x) * (p2.y - p1.y);
        // A uv triangle without area holds no point (POV would divide by
        // zero and trace a ray of NaNs).
        if (scale == 0.0) continue;
        const double b1 = ((p2.x - u) * (p3.y - v) - (p3.x - u) * (p2.y - v)) / scale;
        const double b2 = ((p3.x - u) * (p1.y - v) - (p1.x - u) * (p3.y - v)) / scale;
        const double b3 = ((p1.x - u) * (p2.y - v) - (p2.x - u) * (p1.y - v)) / scale;
        if (b1 < 0.0 || b2 < 0.0 || b3 < 0.0) continue;
        const DVec3 point = b1 * face.corners[0] + b2 * face.corners[1] + b3 * face.corners[2];
        // One normal for the whole face, unless smooth (POV interpolates
        // the vertex normals; a face without them keeps its own normal).
        const DVec3 normal =
            m_settings.smooth && face.smooth
                ? b1 * face.vertex_normals[0] + b2 * face.vertex_normals[1] + b3 * face.vertex_normals[2]
                : face_normal(face);
        if (normal == DVec3(0.0)) return false;
        place(point, normal, m_uv_world_from_mesh, m_uv_world_from_mesh_normals, origin, direction);
        return true;
    }
    return false;
}

bool MeshCameraRays::generate(double x, double y, int width, int height, int ray_number, DVec3& origin,
                              DVec3& direction) const {
    if (m_meshes.empty()) return false;
    // POV's pixel point: x at the pixel's centre, y half a pixel above its
    // top edge (POV's y -= 0.5), both clamped to the image. So the top two
    // rows both read row 0 of the faces, and each row below reads the row
    // above it: POV's picture, kept.
    const double px = std::clamp(x, 0.0, double(width) - 1.0);
    const double py = std::clamp(y - 1.0, 0.0, double(height) - 1.0);
    const auto column = std::uint32_t(px), row = std::uint32_t(py);
    const auto pixel = row * std::uint32_t(width) + column;
    switch (m_settings.distribution) {
    case Distribution::FacePerPixel:
        // The r-th ray of a pixel leaves the r-th mesh.
        if (ray_number < 0 || std::size_t(ray_number) >= m_meshes.size()) return false;
        return face_ray(m_meshes[std::size_t(ray_number)], pixel, origin, direction);
    case Distribution::MeshesInARow: {
        // POV adds ray_number times the number of faces, so only a pixel's
        // first ray ever finds a face.
        const std::uint32_t total = m_face_ends.back();
        const std::uint64_t face = std::uint64_t(pixel) + std::uint64_t(ray_number) * total;
        if (face >= total) return false;
        const auto mesh =
            std::size_t(std::upper_bound(m_face_ends.begin(), m_face_ends.end(), face) - m_face_ends.begin());
        const std::uint32_t first = mesh == 0 ? 0 : m_face_ends[mesh - 1];
        return face_ray(m_meshes[mesh], std::uint32_t(face) - first, origin, direction);
    }
    case Distribution::SideBySide: {
        // One strip per mesh, left to right. POV numbers the faces with the
        // image's column, not the strip's: a strip right of the first one
        // reads its faces a strip-width further on (POV's picture, kept).
        const std::size_t meshes = m_meshes.size();
        const auto mesh = std::size_t(px / (double(width) / double(meshes)));
        const auto strip_width = std::uint32_t(std::uint32_t(width) / meshes);
        if (mesh >= meshes) return false;
        return face_ray(m_meshes[mesh], row * strip_width + column, origin, direction);
    }
    case Distribution::UvMapped: {
        // POV's pixel point as (u, v), u from 0 at the image's left edge
        // and v from 1 at its top: at a pixel's centre, the u of its left
        // edge and the v of its top edge (row 0: of its middle).
        const double u = (px - 0.5) / double(width);
        const double v = 1.0 - (py + 0.5) / double(height);
        return uv_mapped_ray(u, v, origin, direction);
    }
    }
    return false;
}

}  // namespace lancer
