// Loading the image module (image_codecs.h) once, at the first image.
#include "film/image_codecs.h"

#include <dlfcn.h>

#include <atomic>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "host/library_folder.h"

namespace lancer {
namespace {

constexpr const char* kModuleName = "liblancer_images.so";

std::atomic<ImageCodecs*> g_codecs{nullptr};
std::mutex g_loading;

ImageCodecs* load_module() {
    const std::string folder = folder_of_liblancer();
    const std::string path = (std::filesystem::path(folder) / kModuleName).string();
    dlerror();
    // Never closed: readers and writers it made may outlive any owner, and
    // OpenImageIO keeps threads and caches of its own.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        const char* why = dlerror();
        throw std::runtime_error("lancer's image module cannot be loaded (" + path +
                                 "): " + (why ? why : "no detail from dlerror()") +
                                 "; it belongs beside liblancer.so: rebuild or reinstall lancer");
    }
    using Entry = ImageCodecs* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, "lancer_image_codecs_v1"));
    if (entry == nullptr)
        throw std::runtime_error("'" + path + "' is not lancer's image module of this version: rebuild lancer");
    return entry();
}

}  // namespace

ImageCodecs& image_codecs() {
    if (ImageCodecs* codecs = g_codecs.load(std::memory_order_acquire)) return *codecs;
    std::lock_guard<std::mutex> lock(g_loading);
    if (g_codecs.load(std::memory_order_relaxed) == nullptr) g_codecs.store(load_module(), std::memory_order_release);
    return *g_codecs.load(std::memory_order_relaxed);
}

bool image_codecs_loaded() {
    return g_codecs.load(std::memory_order_acquire) != nullptr;
}

}  // namespace lancer
