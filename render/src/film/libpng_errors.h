// libpng reports errors through a longjmp: its error callback records the
// reason here and jumps back to the setjmp of the one function that called
// libpng, which turns it into an exception once no libpng frame is left
// (internal to liblancer).
#pragma once

#include <png.h>

#include <string>

namespace lancer {

struct LibpngError {
    std::string message;
};

// For png_create_*_struct(..., &error, on_libpng_error, on_libpng_warning).
[[noreturn]] inline void on_libpng_error(png_structp png, png_const_charp message) {
    static_cast<LibpngError*>(png_get_error_ptr(png))->message = message ? message : "libpng error";
    png_longjmp(png, 1);
}

inline void on_libpng_warning(png_structp, png_const_charp) {}

}  // namespace lancer
