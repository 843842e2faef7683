// POV-Ray's density_file pattern: a df3 voxel grid over the unit cube
// [0, 1)^3 (0 outside it), read as POV's density_pattern reads it, with
// interpolate 0 (the voxel the point is in), 1 (trilinear between voxel
// corners, wrapping at the far faces) or anything else (tricubic, in
// single precision as POV computes it).
#include <cmath>
#include <cstdint>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

// POV's intp3(): the Catmull-Rom cubic through fa..fd at t between fb and
// fc, in single precision (its coefficients in double, then rounded).
float catmull_rom(float t, float fa, float fb, float fc, float fd) {
    const float b = float(double(fc - fa) * 0.5);
    const float d = float(double(fd - fb) * 0.5);
    const float e = float(2.0 * double(fb - fc) + double(b) + double(d));
    const float f = float(-3.0 * double(fb - fc) - 2.0 * double(b) - double(d));
    return ((e * t + f) * t + b) * t + fb;
}

// POV's index wrap for tricubic: its indices are unsigned, so one below 0
// is the largest size_t taken modulo the size (the last voxel only when
// the size is a power of two), as POV evaluates it.
std::size_t wrap_unsigned(std::uint64_t index, std::uint64_t size) {
    return std::size_t(index % size);
}

}  // namespace

double density_file_pattern(const PatternSetup& s, const glm::dvec3& p) {
    if (!s.density_voxels) return 0.0;
    const std::vector<double>& v = *s.density_voxels;
    const std::uint64_t sx = std::uint64_t(s.density_size.x), sy = std::uint64_t(s.density_size.y),
                        sz = std::uint64_t(s.density_size.z);
    if (sx == 0 || sy == 0 || sz == 0 || v.size() != sx * sy * sz) return 0.0;
    if (!(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0 && p.z >= 0.0 && p.z < 1.0)) return 0.0;
    auto at = [&](std::uint64_t x, std::uint64_t y, std::uint64_t z) { return v[std::size_t((z * sy + y) * sx + x)]; };

    double density = 0.0;
    switch (s.density_interpolation % 10) {
    case 0: {
        const std::uint64_t x = std::uint64_t(p.x * double(sx)), y = std::uint64_t(p.y * double(sy)),
                            z = std::uint64_t(p.z * double(sz));
        density = (x < sx && y < sy && z < sz) ? at(x, y, z) : 0.0;
        break;
    }
    case 1: {
        double xx = p.x * double(sx), yy = p.y * double(sy), zz = p.z * double(sz);
        const std::uint64_t x1 = std::uint64_t(xx), y1 = std::uint64_t(yy), z1 = std::uint64_t(zz);
        const std::uint64_t x2 = (x1 + 1) % sx, y2 = (y1 + 1) % sy, z2 = (z1 + 1) % sz;
        xx -= std::floor(xx);
        yy -= std::floor(yy);
        zz -= std::floor(zz);
        const double xi = 1.0 - xx, yi = 1.0 - yy;
        density =
            ((at(x1, y1, z1) * xi + at(x2, y1, z1) * xx) * yi + (at(x1, y2, z1) * xi + at(x2, y2, z1) * xx) * yy) *
                (1.0 - zz) +
            ((at(x1, y1, z2) * xi + at(x2, y1, z2) * xx) * yi + (at(x1, y2, z2) * xi + at(x2, y2, z2) * xx) * yy) * zz;
        break;
    }
    default: {
        double xx = p.x * double(sx), yy = p.y * double(sy), zz = p.z * double(sz);
        const std::uint64_t x1 = std::uint64_t(xx), y1 = std::uint64_t(yy), z1 = std::uint64_t(zz);
        xx -= std::floor(xx);
        yy -= std::floor(yy);
        zz -= std::floor(zz);
        std::uint64_t k[4];
        for (std::uint64_t i = 0; i < 4; ++i) k[i] = wrap_unsigned(z1 + i - 1, sz);
        // Along z at each of the 4x4 (x, y) neighbours, then along y, then x.
        float along_y[4];
        for (std::uint64_t i = 0; i < 4; ++i) {
            const std::uint64_t ii = wrap_unsigned(i + x1 - 1, sx);
            float along_z[4];
            for (std::uint64_t j = 0; j < 4; ++j) {
                const std::uint64_t jj = wrap_unsigned(j + y1 - 1, sy);
                along_z[j] = catmull_rom(float(zz), float(at(ii, jj, k[0])), float(at(ii, jj, k[1])),
                                         float(at(ii, jj, k[2])), float(at(ii, jj, k[3])));
            }
            along_y[i] = catmull_rom(float(yy), along_z[0], along_z[1], along_z[2], along_z[3]);
        }
        density = catmull_rom(float(xx), along_y[0], along_y[1], along_y[2], along_y[3]);
        break;
    }
    }
    return density < 0.0 ? 0.0 : density;
}

}  // namespace lancer::pattern_detail
