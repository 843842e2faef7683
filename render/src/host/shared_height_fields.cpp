#include "host/shared_height_fields.h"

#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace lancer {
namespace {

// What a height field's shape is made from, besides its smoothing and
// water level: a function (its identity and size, the noise generator) or
// a file (its path, size and time).
struct Source {
    std::weak_ptr<const sg::Function> function;  // expired: its address may be another function's
    const sg::Function* address = nullptr;
    int width = 0, height = 0, noise_generator = 0;
    std::string path;
    std::uintmax_t file_size = 0;
    std::filesystem::file_time_type file_time{};
    double gamma = 0.0;

    bool same(const Source& other) const {
        if (address != other.address) return false;
        if (address != nullptr)
            return !function.expired() && width == other.width && height == other.height &&
                   noise_generator == other.noise_generator;
        return path == other.path && file_size == other.file_size && file_time == other.file_time &&
               gamma == other.gamma;
    }
};

struct SharedField {
    Source source;
    bool smooth = false;
    double water_level = 0.0;
    std::weak_ptr<const Shape> shape;
};

std::mutex g_mutex;
std::vector<SharedField> g_fields;

std::shared_ptr<const Shape> shared(const Source& source, const sg::HeightField& field, const MakeShape& make) {
    {
        const std::lock_guard<std::mutex> lock(g_mutex);
        std::erase_if(g_fields, [](const SharedField& f) {
            return f.shape.expired() || (f.source.address != nullptr && f.source.function.expired());
        });
        for (const SharedField& f : g_fields)
            if (f.source.same(source) && f.smooth == field.smooth && f.water_level == field.water_level)
                if (auto shape = f.shape.lock()) return shape;
    }
    // Made outside the lock: two threads asking at once each make one.
    std::shared_ptr<const Shape> shape = make();
    const std::lock_guard<std::mutex> lock(g_mutex);
    g_fields.push_back(SharedField{source, field.smooth, field.water_level, shape});
    return shape;
}

}  // namespace

std::shared_ptr<const Shape> shared_function_height_field(const sg::HeightField& field, const MakeShape& make) {
    Source source;
    source.function = field.function;
    source.address = field.function.get();
    source.width = field.function_width;
    source.height = field.function_height;
    source.noise_generator = field.function_noise_generator;
    return shared(source, field, make);
}

std::shared_ptr<const Shape> shared_image_height_field(const sg::HeightField& field, const MakeShape& make) {
    Source source;
    source.path = field.path;
    source.gamma = field.gamma;
    std::error_code error;
    source.file_size = std::filesystem::file_size(field.path, error);
    if (!error) source.file_time = std::filesystem::last_write_time(field.path, error);
    // A file whose size or time cannot be read is read afresh each time.
    if (error) return make();
    return shared(source, field, make);
}

}  // namespace lancer
