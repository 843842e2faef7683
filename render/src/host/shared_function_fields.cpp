#include "host/shared_function_fields.h"

#include <mutex>
#include <vector>

namespace lancer {
namespace {

struct SharedField {
    std::weak_ptr<const sg::Function> function;  // expired: its address may be another function's
    const sg::Function* address = nullptr;
    int width = 0, height = 0;
    bool smooth = false;
    double water_level = 0.0;
    int noise_generator = 0;
    std::weak_ptr<const Shape> shape;

    bool same(const sg::HeightField& field, int generator) const {
        return address == field.function.get() && !function.expired() && width == field.function_width &&
               height == field.function_height && smooth == field.smooth && water_level == field.water_level &&
               noise_generator == generator;
    }
};

std::mutex g_mutex;
std::vector<SharedField> g_fields;

}  // namespace

std::shared_ptr<const Shape> shared_function_height_field(const sg::HeightField& field, int noise_generator,
                                                          const std::function<std::shared_ptr<const Shape>()>& make) {
    {
        const std::lock_guard<std::mutex> lock(g_mutex);
        std::erase_if(g_fields, [](const SharedField& f) { return f.function.expired() || f.shape.expired(); });
        for (const SharedField& f : g_fields)
            if (f.same(field, noise_generator))
                if (auto shape = f.shape.lock()) return shape;
    }
    // Made outside the lock: two threads asking at once each make one.
    std::shared_ptr<const Shape> shape = make();
    const std::lock_guard<std::mutex> lock(g_mutex);
    g_fields.push_back(SharedField{field.function, field.function.get(), field.function_width, field.function_height,
                                   field.smooth, field.water_level, noise_generator, shape});
    return shape;
}

}  // namespace lancer
