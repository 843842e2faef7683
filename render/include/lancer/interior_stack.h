// The objects a ray is inside, innermost last, as POV-Ray's ray keeps its
// list of interiors: what decides which media a stretch of the ray crosses
// (lancer/shading/pov_media.h). A camera ray starts with the objects that
// contain the camera (RenderScene::camera_interiors); an integrator pushes
// the object a transmitted ray enters and removes the one it leaves.
#pragma once

#include <array>
#include <cstdint>

#include "lancer/hit.h"
#include "lancer/material.h"

namespace lancer {

// Small and fixed: deeper nesting than kDepth keeps the outermost kDepth
// objects.
struct InteriorStack {
    struct Entry {
        const Material* material = nullptr;
        std::uint32_t object_id = 0;    // the surface's (where its media's patterns are placed)
        std::uint32_t interior_id = 0;  // the object it is the inside of (Hit::interior_id)
    };
    static constexpr int kDepth = 8;
    std::array<Entry, kDepth> entries{};
    int size = 0;

    void push(const Entry& entry) {
        if (size < kDepth) entries[std::size_t(size++)] = entry;
    }

    // After a ray is transmitted through `hit`: POV-Ray's rule (Trace::
    // ComputeRefraction) goes by the list, not by the face. The object
    // leaves the list if it is in it, else it joins it: a ray that passes a
    // polygon, which has no inside, is "in" it from then on, whichever side
    // it came from, and a non-hollow one then hides fog and media beyond.
    InteriorStack crossed(const Hit& hit) const {
        InteriorStack next = *this;
        for (int i = next.size - 1; i >= 0; --i)
            if (next.entries[std::size_t(i)].interior_id == hit.interior_id) {
                for (int j = i; j + 1 < next.size; ++j) next.entries[std::size_t(j)] = next.entries[std::size_t(j + 1)];
                --next.size;
                return next;
            }
        next.push(Entry{hit.material, hit.object_id, hit.interior_id});
        return next;
    }

    // n1/n2 across `hit`, whose object's index is `ior`, for the ray that
    // refracts there (POV-Ray's Trace::ComputeRefraction): by the list, not
    // by the face. Nested objects count as outside their container (leaving
    // the inner one returns to the container's index), and where two
    // overlap the later entered wins, so leaving the earlier bends nothing.
    float refraction_eta(const Hit& hit, float ior) const {
        if (size == 0) return 1.0f / ior;
        const Entry& innermost = entries[std::size_t(size - 1)];
        if (innermost.interior_id == hit.interior_id)
            return size == 1 ? ior : ior / entries[std::size_t(size - 2)].material->parameters().ior;
        if (holds(hit)) return 1.0f;
        return innermost.material->parameters().ior / ior;
    }

    // n2/n1 across `hit` for POV's `reflection { fresnel }` (Trace::
    // ComputeRelativeIOR), which leaving into another object reads as the
    // innermost's index over this one's.
    float fresnel_ior(const Hit& hit, float ior) const {
        if (size == 0) return ior;
        if (!holds(hit)) return ior / entries[std::size_t(size - 1)].material->parameters().ior;
        if (size == 1) return 1.0f / ior;
        return entries[std::size_t(size - 1)].material->parameters().ior / ior;
    }

    bool holds(const Hit& hit) const {
        for (int i = 0; i < size; ++i)
            if (entries[std::size_t(i)].interior_id == hit.interior_id) return true;
        return false;
    }
};

}  // namespace lancer
