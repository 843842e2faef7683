// CSG objects and their modifiers: intersection, difference, merge,
// clipped_by, bounded_by. What they mean is the renderer's (csg.h); here
// they are built as POV-Ray's parser builds them (Parse_CSG,
// Parse_Object_Mods).
#include <glm/glm.hpp>

#include <algorithm>

#include "evaluator.h"

namespace lancer::parse {

namespace {

// Objects written in the space `object` sits in, moved into its own space,
// so they follow its later transforms (as POV-Ray transforms clips along
// with their object).
std::vector<sg::Object> in_object_space(const std::vector<ShapePtr>& shapes, const sg::Object& object) {
    const sg::Mat4 object_from_parent = glm::inverse(object.parent_from_object);
    std::vector<sg::Object> moved;
    for (const ShapePtr& shape : shapes) {
        sg::Object clip = shape->object;
        clip.parent_from_object = object_from_parent * clip.parent_from_object;
        moved.push_back(std::move(clip));
    }
    return moved;
}

}  // namespace

ShapePtr Evaluator::make_csg(sg::Object::Kind kind, const sg::SourceLocation& at) {
    ShapePtr shape = make_union(at);
    shape->object.kind = kind;
    return shape;
}

namespace {

// POV-Ray's patch objects (a triangle, a mesh without inside_vector, a
// polygon, a bicubic patch, or a group holding one) have no inside
// (lancer's CSG, as POV's, keeps or drops pieces of their surface).
bool is_patch_object(const sg::Object& object) {
    if (const auto* mesh = std::get_if<sg::MeshRef>(&object.shape)) return *mesh && !(*mesh)->inside_vector;
    if (const auto* group = std::get_if<sg::Group>(&object.shape))
        return std::any_of(group->children.begin(), group->children.end(), is_patch_object);
    return std::holds_alternative<sg::Polygon>(object.shape) || std::holds_alternative<sg::BicubicPatch>(object.shape);
}

constexpr const char* kPatchObject = "a triangle, polygon, bicubic_patch or mesh without inside_vector";

}  // namespace

void Evaluator::finish_csg(ShapeValue& shape) {
    const auto& children = std::get<sg::Group>(shape.object.shape).children;
    if (children.size() < 2 && shape.object.kind != sg::Object::Kind::Merge)
        warning(shape.object.location, "should have at least 2 objects in CSG (POV-Ray's warning)");
    if (shape.object.kind == sg::Object::Kind::Intersection || shape.object.kind == sg::Object::Kind::Difference)
        for (const sg::Object& child : children)
            if (is_patch_object(child))
                warning(child.location,
                        "a triangle or a mesh without inside_vector has no inside: in an "
                        "intersection or difference only pieces of its surface are kept "
                        "(POV-Ray's \"patch objects not allowed in intersection\")");
}

std::function<void(ShapeValue&)> Evaluator::clip_edit(const std::vector<ShapePtr>& clips,
                                                      const sg::SourceLocation& at) {
    if (clips.empty()) warning(at, "clipped_by holds no object; it has no effect");
    for (const ShapePtr& clip : clips)
        if (is_patch_object(clip->object))
            error(clip->object.location,
                  "a triangle or a mesh without inside_vector cannot clip: it has no inside "
                  "(POV-Ray's \"illegal patch in clip\")");
    return [clips](ShapeValue& s) {
        for (sg::Object& clip : in_object_space(clips, s.object)) s.object.clipped_by.push_back(std::move(clip));
    };
}

std::function<void(ShapeValue&)> Evaluator::clip_by_bounds_edit(const sg::SourceLocation& at) {
    return [this, at](ShapeValue& s) {
        if (s.bounded_by.empty()) {
            error(at, "clipped_by { bounded_by } needs a bounded_by before it");
            return;
        }
        for (const sg::Object& bound : s.bounded_by) s.object.clipped_by.push_back(bound);
    };
}

std::function<void(ShapeValue&)> Evaluator::bound_edit(const std::vector<ShapePtr>& bounds, const sg::SourceLocation&) {
    for (const ShapePtr& bound : bounds)
        if (is_patch_object(bound->object))
            error(bound->object.location,
                  std::string(kPatchObject) + " cannot bound: it has no inside (POV-Ray's \"illegal patch in bound\")");
    // A bound speeds POV-Ray up, and cuts what the rays that miss it would
    // see (the renderer's csg.h).
    return [bounds](ShapeValue& s) {
        for (sg::Object& bound : in_object_space(bounds, s.object)) {
            s.object.bounded_by.push_back(bound);
            s.bounded_by.push_back(std::move(bound));
        }
    };
}

}  // namespace lancer::parse
