// POV-Ray 3.7's mesh_camera: each pixel's ray leaves a face of a mesh along
// the face's normal. Which face a pixel takes is POV's distribution type
// (CreateCameraRay in POV-Ray 3.7's tracepixel.cpp, read for its rules;
// docs/scene-language.md describes them):
//   0  pixel i takes face i; a pixel's r-th ray (of rays_per_pixel) the
//      r-th mesh's face i;
//   1  pixel i takes face i of all the meshes' faces in a row;
//   2  the image is split into one strip per mesh, side by side;
//   3  the pixel's point of the image, read as (u,v), finds the first face
//      of the first mesh whose uv triangle holds it; the ray leaves that
//      point of the face (with `smooth`, along the interpolated normal).
// A pixel past the faces gets no ray (black in the image, as in POV).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace lancer {

// One face as the mesh camera reads it, in its mesh's own space and in
// POV's face order.
struct MeshCameraFace {
    glm::dvec3 corners[3]{};
    glm::dvec3 vertex_normals[3]{};  // read only when smooth is true
    bool smooth = false;             // the face has vertex normals
    glm::dvec2 uv[3]{};              // read only by distribution type 3
};

class MeshCameraRays {
  public:
    enum class Distribution { FacePerPixel = 0, MeshesInARow = 1, SideBySide = 2, UvMapped = 3 };
    struct Settings {
        Distribution distribution = Distribution::FacePerPixel;
        // POV reads the camera's location.z as how far along the normal a
        // ray starts off its face, and a direction.z below -1e-10 as rays
        // sent against the normal.
        double start_offset = 0.0;
        bool reversed = false;
        bool smooth = false;        // type 3: interpolate the vertex normals
        double max_distance = 0.0;  // how far a ray reaches; 0: no limit
    };

    explicit MeshCameraRays(const Settings& settings) : m_settings(settings) {}

    // The next mesh of the camera (in the order the scene lists them):
    // its faces and its transforms.
    void add_mesh(const std::vector<MeshCameraFace>& faces, const glm::dmat4& world_from_mesh);

    // The ray (world space; direction not normalised) for the film point
    // (x, y) in pixels ((0,0) the top-left corner) of a width x height
    // image, and the pixel's ray_number-th ray; false where the pixel has
    // no face.
    bool generate(double x, double y, int width, int height, int ray_number, glm::dvec3& origin,
                  glm::dvec3& direction) const;

    std::size_t mesh_count() const { return m_meshes.size(); }
    const Settings& settings() const { return m_settings; }

  private:
    // A face's ray in world space, made once (types 0 to 2 always start at
    // the centroid); a zero direction marks a face without a normal.
    struct FaceRay {
        glm::vec3 origin;
        glm::vec3 direction;
    };
    struct Mesh {
        std::vector<FaceRay> rays;
    };
    bool face_ray(const Mesh& mesh, std::uint32_t face, glm::dvec3& origin, glm::dvec3& direction) const;
    bool uv_mapped_ray(double u, double v, glm::dvec3& origin, glm::dvec3& direction) const;
    // The start and direction (world space) of a ray leaving `point` of a
    // face along `normal` (both in the mesh's space), as POV moves it:
    // start_offset along the normal, reversed if asked, then transformed.
    void place(const glm::dvec3& point, const glm::dvec3& normal, const glm::dmat4& world_from_mesh,
               const glm::dmat3& world_from_mesh_normals, glm::dvec3& origin, glm::dvec3& direction) const;
    void index_uv_faces();

    Settings m_settings;
    std::vector<Mesh> m_meshes;
    std::vector<std::uint32_t> m_face_ends;  // faces in meshes 0..i together
    // Type 3 reads the first mesh's faces themselves, found through a grid
    // over the unit uv square: each cell lists the faces whose uv bounds
    // meet it, in face order.
    std::vector<MeshCameraFace> m_uv_faces;
    glm::dmat4 m_uv_world_from_mesh{1.0};
    glm::dmat3 m_uv_world_from_mesh_normals{1.0};
    int m_grid = 1;
    std::vector<std::uint32_t> m_cell_starts, m_cell_faces;
};

}  // namespace lancer
