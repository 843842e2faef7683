// POV-Ray's CSG rules through the compiled scene: which surfaces a ray
// meets in intersection, difference, merge, inverse and clipped_by, with
// their normals pointing out of the solid that remains.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/scene_data.h"
#include "host/scene_builder.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"
#include "lancer/render_scene.h"
#include "lancer/scene_error.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;

std::unique_ptr<RenderScene> compile(const std::string& text) {
    ParseResult parsed = parse_scene_string(text, "<csg>");
    if (!parsed.ok()) throw std::runtime_error(format_diagnostic(parsed.diagnostics.front()));
    return compile_scene(*parsed.scene);
}

// The first hit of the ray from `from` along `direction`; t < 0 if none.
Hit first_hit(const RenderScene& scene, const Vec3& from, const Vec3& direction) {
    Hit hit;
    if (!scene.intersect(make_ray(from, direction), hit)) hit.t = -1.0f;
    return hit;
}

TEST(Csg, DifferenceShowsTheCutWithItsNormalOutOfTheSolid) {
    // A unit sphere less its x > 0 half: from +x the ray meets the cut face at x = 0.
    const auto scene = compile("difference { sphere { 0, 1 } box { <0, -2, -2>, <2, 2, 2> } }");
    const Hit hit = first_hit(*scene, {5, 0.1f, 0.2f}, {-1, 0, 0});
    EXPECT_NEAR(hit.t, 5.0f, 1e-5f);
    EXPECT_NEAR(hit.geometric_normal.x, 1.0f, 1e-6f);  // the box's -x face, turned out of the remaining half
    // Beside the sphere nothing is left of the box.
    EXPECT_LT(first_hit(*scene, {5, 1.5f, 0}, {-1, 0, 0}).t, 0.0f);
    // From -x the sphere itself.
    EXPECT_NEAR(first_hit(*scene, {-5, 0, 0}, {1, 0, 0}).t, 4.0f, 1e-5f);
}

// POV-Ray bounds a quadric between planes (a chess piece's waist): here
// Shape::narrow_box does. The same solid with the quadric wrapped in an
// intersection of its own stays unbounded (tested on every ray): both must
// give the same hits (up to the float the BVH keeps t in), and the bounded
// one must count in the scene's bounds where POV-Ray bounds it too.
TEST(Csg, AQuadricBetweenPlanesIsBoundedAndFoundAlike) {
    const std::string waist = "quadric { <1, -1, 1>, 0, 0, -1 translate 5*y scale <0.5, 1, 0.5> rotate 20*y }";
    const std::string tower = "quadric { <1, 0, 1>, 0, 0, -1 scale <2, 1, 2> }";
    const std::string hollow = "quadric { <1, 0, 1>, 0, 0, -1 scale <1.2, 1, 1.2> inverse }";
    const struct {
        std::string bounded, unbounded;
        bool pov_bounds = true;  // POV-Ray bounds it too (min_extent)
    } pieces[] = {
        {"intersection { plane { y, 5.5 } " + waist + " plane { -y, -2.5 } }",
         "intersection { plane { y, 5.5 } intersection { " + waist + " } plane { -y, -2.5 } }"},
        // A rook's top: a tube between two planes, moved.
        {"intersection { plane { y, 10 } " + tower + " " + hollow + " plane { -y, -8 } translate <1, 0, -2> }",
         "intersection { plane { y, 10 } intersection { " + tower + " } " + hollow +
             " plane { -y, -8 } translate <1, 0, -2> }"},
        // Turned off the axes, whole: bounded in the pieces' common space.
        {"intersection { plane { y, 5.5 } " + waist + " plane { -y, -2.5 } rotate <-30, 0, 25> translate 2*y }",
         "intersection { plane { y, 5.5 } intersection { " + waist + " } plane { -y, -2.5 } rotate <-30, 0, 25> " +
             "translate 2*y }"},
        // POV's helix: a quartic clipped by a cylinder and two planes, then
        // turned; the clips bound it, and its roots are sought in their box.
        // POV-Ray gives it no box (its min_extent is -1e10): nor does the
        // scene's, but its rays are culled by it.
        {"quartic { <0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,-0.1666,0,1,0, 0,0,0,0,0,0,0,0.5,0,-1, 0,0,0,0,0> "
         "clipped_by { quadric { <1, 1, 0>, 0, 0, -1 scale 2 } plane { z, 1.4142 } plane { -z, 0 } } "
         "translate -1.4*z rotate 160*z rotate -90*x scale 2 translate 6*y }",
         "quartic { <0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,-0.1666,0,1,0, 0,0,0,0,0,0,0,0.5,0,-1, 0,0,0,0,0> "
         "clipped_by { intersection { intersection { quadric { <1, 1, 0>, 0, 0, -1 scale 2 } } plane { z, 1.4142 } "
         "plane { -z, 0 } } } translate -1.4*z rotate 160*z rotate -90*x scale 2 translate 6*y }",
         false},
    };
    std::mt19937 random(3);
    std::uniform_real_distribution<float> coordinate(-6.0f, 6.0f);
    for (const auto& piece : pieces) {
        const auto bounded = compile("#version 3.7;\n" + piece.bounded);
        const auto unbounded = compile("#version 3.7;\n" + piece.unbounded);
        Bounds box = bounded->bounds();
        if (!piece.pov_bounds) {
            EXPECT_TRUE(box.empty()) << piece.bounded;
            ParseResult parsed = parse_scene_string("#version 3.7;\n" + piece.bounded, "<csg>");
            ASSERT_TRUE(parsed.ok());
            const std::unique_ptr<SceneData> data = build_scene_data(*parsed.scene);
            for (const Instance& instance : data->instances)
                if (instance.kind == ShapeKind::Csg) {
                    EXPECT_TRUE(instance.bounded && instance.pov_unbounded) << piece.bounded;
                    box = Bounds{instance.bounds_lower, instance.bounds_upper};
                }
        }
        ASSERT_FALSE(box.empty()) << piece.bounded;
        EXPECT_LT(box.upper.y, 12.0f) << piece.bounded;
        EXPECT_GT(box.lower.y, -2.0f) << piece.bounded;
        EXPECT_TRUE(unbounded->bounds().empty()) << piece.unbounded;
        int hits = 0;
        for (int k = 0; k < 3000; ++k) {
            const Vec3 from(coordinate(random), coordinate(random) + 6.0f, coordinate(random));
            const Vec3 to(coordinate(random) * 0.4f, coordinate(random) * 0.5f + 6.0f, coordinate(random) * 0.4f);
            const Hit a = first_hit(*bounded, from, to - from), b = first_hit(*unbounded, from, to - from);
            ASSERT_EQ(a.t < 0.0f, b.t < 0.0f) << piece.bounded << " ray " << k;
            if (a.t < 0.0f) continue;
            ++hits;
            EXPECT_NEAR(a.t, b.t, 1e-5f * b.t) << piece.bounded << " ray " << k;
            EXPECT_NEAR(glm::dot(a.geometric_normal, b.geometric_normal), 1.0f, 1e-4f) << piece.bounded;
        }
        EXPECT_GT(hits, 300) << piece.bounded;
    }
}

// A node whose box holds its solid has its shapes searched only within
// that box, but a part whose box does not (a disc's flat one) still culls
// by the whole ray, as POV-Ray's: here the ray crosses the disc's slab only
// outside the clipping sphere's box, and still meets the tube under it.
TEST(Csg, APartWithAFlatBoxIsCulledByTheWholeRay) {
    const auto scene = compile(
        "union { quadric { <1, 0, 1>, 0, 0, -0.25 clipped_by { disc { 0, y, 3 } } } plane { -y, -10 }\n"
        "  clipped_by { sphere { 0, 1 } } }");
    const Hit hit = first_hit(*scene, {2.5f, 0.0f, 0.2f}, {-1.0f, -0.25f, 0.0f});
    const float x = std::sqrt(0.25f - 0.04f);                    // the tube's side at z = 0.2
    EXPECT_NEAR(hit.t, (2.5f - x) * std::sqrt(1.0625f), 1e-4f);  // t along the unit direction
}

TEST(Csg, IntersectionKeepsOnlyTheCommonPart) {
    const auto scene = compile("intersection { sphere { 0, 1 } box { -0.8, 0.8 } }");
    // Through a face centre: the box face (inside the sphere).
    EXPECT_NEAR(first_hit(*scene, {-5, 0, 0}, {1, 0, 0}).t, 4.2f, 1e-5f);
    // Towards a box corner: the sphere (the corner is outside it).
    const Vec3 d = glm::normalize(Vec3(1, 1, 1));
    const Hit corner = first_hit(*scene, -5.0f * d, d);
    EXPECT_NEAR(corner.t, 4.0f, 1e-5f);
}

// A disc's inside is POV's half-space behind it, beyond its flat box: the
// intersection of a ball and a disc facing down is the dome above the
// disc. As in POV-Ray the object is bounded by the overlap of the parts'
// boxes, the disc's 0.001 thick: a ray that crosses that slab finds the
// dome, one that never does (the ray along the top) misses it, and a ray
// leaving the disc upwards starts in the slab and finds the dome inside.
TEST(Csg, ADiscBoundsAnIntersectionByItsHalfSpaceAndItsSlab) {
    const auto scene = compile("intersection { sphere { <0, -5, 0>, 10 } disc { 0, -y, 10.1 } }");
    EXPECT_NEAR(first_hit(*scene, {0, 20, 0.5f}, {0, -1, 0}).t, 20.0f - std::sqrt(100.0f - 0.25f) + 5.0f, 1e-4f);
    EXPECT_LT(first_hit(*scene, {-20, 4, 0}, {1, 0, 0}).t, 0.0f);
    const Hit bottom = first_hit(*scene, {0, -1, 0}, {0, 1, 0});
    ASSERT_NEAR(bottom.t, 1.0f, 1e-5f);
    Hit dome;
    ASSERT_TRUE(scene->intersect(bottom.spawn_ray({0, 1, 0}), dome));
    EXPECT_NEAR(dome.position.y, 5.0f, 1e-4f);
}

// POV-Ray's bounded_by: an object's box becomes its bound's where that is
// smaller, and rays that miss the box miss the object; for an object costly
// to intersect (here a quadric) a ray must also meet the bound itself, while
// a cheap one's bound is dropped (POV's "unnecessary bounding object").
TEST(Csg, BoundedByCutsAsPovRayDoes) {
    const auto boxed = compile("sphere { 0, 2 bounded_by { box { -1, 1 } } }");
    EXPECT_NEAR(first_hit(*boxed, {0.5f, 0, -10}, {0, 0, 1}).t, 10.0f - std::sqrt(3.75f), 1e-4f);
    EXPECT_LT(first_hit(*boxed, {1.5f, 0, -10}, {0, 0, 1}).t, 0.0f);
    const auto costly =
        compile("quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -4 bounded_by { sphere { <0, 0, 3>, 1 } } }");
    EXPECT_NEAR(first_hit(*costly, {0.5f, 0, -10}, {0, 0, 1}).t, 10.0f - std::sqrt(3.75f), 1e-4f);
    EXPECT_LT(first_hit(*costly, {0.9f, 0.9f, -10}, {0, 0, 1}).t, 0.0f);
    const auto cheap = compile("sphere { 0, 2 bounded_by { sphere { <0, 0, 3>, 1 } } }");
    EXPECT_NEAR(first_hit(*cheap, {0.9f, 0.9f, -10}, {0, 0, 1}).t, 10.0f - std::sqrt(4.0f - 1.62f), 1e-4f);
}

// A union's bounded_by: POV-Ray tests it before any part, so it cuts a part
// that has no bounds of its own (a quadric here, written in the union's
// space while the part is moved) where the rays miss the bound, and so
// does lancer; nested in another union the same.
TEST(Csg, AUnionsBoundedByCutsItsUnboundedParts) {
    const std::string quadric = "quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -4 translate x }";
    const std::string bound = "bounded_by { sphere { <1, 0, -3>, 1 } }";
    for (const std::string& text : {"union { " + quadric + " box { <5, -1, -1>, <6, 1, 1> } " + bound + " }",
                                    "union { union { " + quadric + " } sphere { <5, 0, 0>, 1 } " + bound + " }"}) {
        const auto scene = compile(text);
        // Through the bound: the quadric's near side, at z = -sqrt(3.75).
        EXPECT_NEAR(first_hit(*scene, {1.5f, 0, -10}, {0, 0, 1}).t, 10.0f - std::sqrt(3.75f), 1e-4f) << text;
        // Beside the bound, though through the quadric: nothing.
        EXPECT_LT(first_hit(*scene, {1.9f, 0.9f, -10}, {0, 0, 1}).t, 0.0f) << text;
        // Without the bound the same ray meets it.
        const auto unbounded = compile("union { " + quadric + " }");
        EXPECT_NEAR(first_hit(*unbounded, {1.9f, 0.9f, -10}, {0, 0, 1}).t, 10.0f - std::sqrt(4.0f - 1.62f), 1e-4f);
    }
}

// The same for a glowing plane, which outside a union's bound lancer
// leaves whole (it is no light `path` could sample): in one, it is a disc.
TEST(Csg, AUnionsBoundedByCutsAGlowingPlane) {
    const auto scene = compile(
        "union { plane { y, 0 finish { emission 1 } } sphere { <0, 0.5, 0>, 0.5 }"
        " bounded_by { sphere { <0, 0.5, 0>, 2 } } }");
    EXPECT_NEAR(first_hit(*scene, {1, 5, 0}, {0, -1, 0}).t, 5.0f, 1e-5f);
    EXPECT_LT(first_hit(*scene, {3, 5, 0}, {0, -1, 0}).t, 0.0f);
}

// A smooth triangle whose written normals disagree with its winding, as
// a CSG leaf: the facet's normal is turned to the side of the normal that
// shades, as for a mesh out of CSG, so the two never face apart.
TEST(Csg, ASmoothMeshLeafsNormalsFaceTheSameSide) {
    const auto scene = compile(
        "mesh { smooth_triangle { <-1, -1, 0>, <0, 0, -1>, <1, -1, 0>, <0, 0, -1>, <0, 1, 0>, <0, 0, -1> }\n"
        "  clipped_by { box { -2, 2 } } }");
    for (const float side : {-1.0f, 1.0f}) {
        const Hit hit = first_hit(*scene, {0.1f, -0.2f, 5 * side}, {0, 0, -side});
        ASSERT_GT(hit.t, 0.0f);
        EXPECT_GT(glm::dot(hit.shading_normal, hit.geometric_normal), 0.99f) << "from z = " << 5 * side;
    }
}

TEST(Csg, MergeDropsInnerSurfacesAndUnionKeepsThem) {
    const std::string spheres = "sphere { <-0.5, 0, 0>, 1 } sphere { <0.5, 0, 0>, 1 }";
    const auto merged = compile("merge { " + spheres + " }");
    const auto united = compile("union { " + spheres + " }");
    // From the middle, inside both: a union shows the left sphere's far
    // side at x = 0.5, a merge only the outer surface at x = 1.5.
    EXPECT_NEAR(first_hit(*united, {0, 0, 0}, {1, 0, 0}).t, 0.5f, 1e-5f);
    EXPECT_NEAR(first_hit(*merged, {0, 0, 0}, {1, 0, 0}).t, 1.5f, 1e-5f);
    EXPECT_NEAR(first_hit(*merged, {-5, 0, 0}, {1, 0, 0}).t, 3.5f, 1e-5f);
}

TEST(Csg, InverseHollowsAShell) {
    // A shell: the big sphere intersected with the inverse of the small one.
    const auto scene = compile("intersection { sphere { 0, 2 } sphere { 0, 1 inverse } }");
    const Hit inner = first_hit(*scene, {0, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(inner.t, 1.0f, 1e-5f);
    // The inner wall's normal points into the cavity, out of the shell.
    EXPECT_NEAR(inner.geometric_normal.x, -1.0f, 1e-6f);
}

TEST(Csg, DeMorganInversionOfAGroup) {
    // difference { A union { B C } } removes both B and C from A.
    const auto scene =
        compile("difference { box { -1, 1 } union { sphere { <-1, 0, 0>, 0.5 } sphere { <1, 0, 0>, 0.5 } } }");
    // From -x: the left cavity's wall at x = -0.5, its normal pointing
    // into the cavity (out of what is left).
    const Hit hit = first_hit(*scene, {-5, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(hit.t, 4.5f, 1e-5f);
    EXPECT_NEAR(hit.geometric_normal.x, -1.0f, 1e-6f);
    // Inside the box between the cavities, towards +x: the right cavity at x = 0.5.
    EXPECT_NEAR(first_hit(*scene, {0, 0, 0}, {1, 0, 0}).t, 0.5f, 1e-5f);
}

TEST(Csg, ClippedByKeepsTheSurfaceInsideTheClip) {
    // The lower half of a sphere: from above the ray passes the clipped-away
    // top and meets the inside of the bottom.
    const auto scene = compile("sphere { 0, 1 clipped_by { plane { y, 0 } } }");
    EXPECT_NEAR(first_hit(*scene, {0, 5, 0}, {0, -1, 0}).t, 6.0f, 1e-5f);
    // clipped_by { bounded_by } clips by the bound.
    const auto bound =
        compile("sphere { 0, 1 bounded_by { box { <-2, -2, -2>, <2, 0.5, 2> } } clipped_by { bounded_by } }");
    EXPECT_NEAR(first_hit(*bound, {0, 5, 0}, {0, -1, 0}).t, 6.0f, 1e-5f);
    // Transforms after clipped_by move the clip with the object.
    const auto moved = compile("sphere { 0, 1 clipped_by { plane { y, 0 } } translate <0, 10, 0> }");
    EXPECT_NEAR(first_hit(*moved, {0, 15, 0}, {0, -1, 0}).t, 6.0f, 1e-5f);
}

TEST(Csg, EachChildKeepsItsOwnTexture) {
    const auto scene = compile(
        "difference { box { -1, 1 pigment { rgb <1, 0, 0> } } sphere { <1, 0, 0>, 0.5 pigment { rgb <0, 0, 1> } } }");
    const Hit box = first_hit(*scene, {-5, 0, 0}, {1, 0, 0});
    const Hit cut = first_hit(*scene, {5, 0, 0}, {-1, 0, 0});
    ASSERT_GT(box.t, 0.0f);
    ASSERT_GT(cut.t, 0.0f);
    EXPECT_NEAR(cut.t, 4.5f, 1e-5f);
    EXPECT_NE(box.material, cut.material);
    EXPECT_NE(box.object_id, cut.object_id);
}

TEST(Csg, ShadowRaysSeeOnlyWhatIsKept) {
    // A box with a tunnel along x: a shadow ray through the tunnel is not blocked.
    const auto scene = compile("difference { box { -1, 1 } cylinder { <-2, 0, 0>, <2, 0, 0>, 0.5 } }");
    Ray through = make_ray({-5, 0, 0}, {1, 0, 0});
    through.t_max = 10.0f;
    EXPECT_FALSE(scene->occluded(through));
    Ray blocked = make_ray({-5, 0.8f, 0}, {1, 0, 0});
    blocked.t_max = 10.0f;
    EXPECT_TRUE(scene->occluded(blocked));
}

TEST(Csg, UnboundedTreesAreTraced) {
    // Two half-spaces: a wedge with no finite box.
    const auto scene = compile("intersection { plane { y, 0 } plane { x, 0 } }");
    EXPECT_NEAR(first_hit(*scene, {-3, 5, 0}, {0, -1, 0}).t, 5.0f, 1e-5f);
    EXPECT_LT(first_hit(*scene, {3, 5, 0}, {0, -1, 0}).t, 0.0f);
}

// A mesh2 cube: its 12 triangles, wound outwards, between -1 and 1.
std::string mesh_cube(const std::string& extra) {
    return R"(mesh2 { vertex_vectors { 8, <-1,-1,-1>, <1,-1,-1>, <1,1,-1>, <-1,1,-1>, <-1,-1,1>, <1,-1,1>, <1,1,1>, <-1,1,1> }
      face_indices { 12, <0,2,1>, <0,3,2>, <4,5,6>, <4,6,7>, <0,1,5>, <0,5,4>, <3,7,6>, <3,6,2>,
                         <0,4,7>, <0,7,3>, <1,2,6>, <1,6,5> } )" +
           extra + " }";
}

TEST(Csg, AMeshWithInsideVectorIsASolid) {
    // The cube less a sphere of radius 1.2: only the cube's corners remain,
    // so a ray through a face centre passes, one towards a corner stops at
    // the cube's face; the sphere's surface shows inside the corners.
    const auto scene = compile("difference { " + mesh_cube("inside_vector <0.3, 0.4, 1>") + " sphere { 0, 1.2 } }");
    EXPECT_LT(first_hit(*scene, {-5, 0, 0}, {1, 0, 0}).t, 0.0f);
    const Hit corner = first_hit(*scene, {-5, 0.9f, 0.9f}, {1, 0, 0});
    EXPECT_NEAR(corner.t, 4.0f, 1e-5f);
    // From inside the cut (at the origin) towards a corner: the sphere's
    // surface, its normal turned out of what remains (towards the origin).
    const Vec3 d = glm::normalize(Vec3(1, 1, 1));
    const Hit cut = first_hit(*scene, {0, 0, 0}, d);
    EXPECT_NEAR(cut.t, 1.2f, 1e-5f);
    EXPECT_LT(glm::dot(cut.geometric_normal, d), -0.99f);
    // An intersection with a sphere keeps the cube's faces inside it.
    const auto both = compile("intersection { " + mesh_cube("inside_vector z") + " sphere { 0, 1.2 } }");
    EXPECT_NEAR(first_hit(*both, {-5, 0, 0}, {1, 0, 0}).t, 4.0f, 1e-5f);
    EXPECT_LT(first_hit(*both, {-5, 0.95f, 0.95f}, {1, 0, 0}).t, 0.0f);  // that corner is outside the sphere
}

TEST(Csg, AMeshKeepsItsPerTriangleTexturesInCsg) {
    // Two parallel triangles, the nearer (z = 0) with its own texture, the
    // farther (z = 1) with the mesh's: each hit shows its own.
    const auto scene = compile(R"(difference {
        mesh { triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> texture { pigment { rgb x } } }
               triangle { <-1, -1, 1>, <1, -1, 1>, <0, 1, 1> } pigment { rgb z } }
        sphere { <10, 0, 0>, 1 } })");
    const Hit near = first_hit(*scene, {0, 0, -5}, {0, 0, 1});
    const Hit far = first_hit(*scene, {0, 0, 5}, {0, 0, -1});
    ASSERT_NEAR(near.t, 5.0f, 1e-5f);
    ASSERT_NEAR(far.t, 4.0f, 1e-5f);
    ASSERT_TRUE(near.material && far.material);
    EXPECT_NE(near.material, far.material);
}

TEST(Csg, AMeshWithoutInsideVectorHasNoInsideEvenInverted) {
    // POV-Ray: a patch object is never inside, so subtracting it removes
    // nothing and the sphere in a difference with it stays whole...
    const auto kept = compile("difference { sphere { 0, 1 } " + mesh_cube("") + " }");
    EXPECT_NEAR(first_hit(*kept, {-5, 0, 0}, {1, 0, 0}).t, 4.0f, 1e-5f);
    // ...and a sphere less such a mesh (the mesh inverted) keeps none of
    // the mesh's surface, which is never inside the sphere... while the
    // mesh less the sphere keeps its faces outside the sphere only.
    const auto faces = compile("difference { " + mesh_cube("") + " sphere { 0, 1.2 } }");
    EXPECT_LT(first_hit(*faces, {-5, 0, 0}, {1, 0, 0}).t, 0.0f);
    EXPECT_NEAR(first_hit(*faces, {-5, 0.9f, 0.9f}, {1, 0, 0}).t, 4.0f, 1e-5f);
}

}  // namespace
}  // namespace lancer
