#include "lancer/shading/environment_light.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "lancer/render_scene.h"

namespace lancer {
namespace {

// The cosine of the polar angle (from +y) at fraction `t` of row `row`.
double row_cosine(int row, double t, int rows) {
    return std::cos(M_PI * (double(row) + t) / double(rows));
}

Vec3 direction_from(double cos_theta, double phi) {
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return Vec3(float(sin_theta * std::cos(phi)), float(cos_theta), float(sin_theta * std::sin(phi)));
}

// How much a cell is worth drawing: the mean magnitude of its channels (a
// negative sky, valid POV, lights as much as it darkens).
double brightness(const Color& c) {
    const double value = (std::fabs(double(c.r)) + std::fabs(double(c.g)) + std::fabs(double(c.b))) / 3.0;
    return std::isfinite(value) ? value : 0.0;
}

// Cumulative sums of `weights`, scaled to end at exactly 1.
std::vector<float> normalised_cdf(const double* weights, int count, double total) {
    std::vector<float> cdf(std::size_t(count) + 1, 0.0f);
    double running = 0.0;
    for (int i = 0; i < count; ++i) {
        running += weights[i];
        cdf[std::size_t(i) + 1] = float(running / total);
    }
    cdf.back() = 1.0f;
    return cdf;
}

// The bin of `cdf` (count + 1 entries) holding u, and u's place inside it.
int pick(const float* cdf, int count, float u, float& remapped) {
    const int bin = std::clamp(int(std::upper_bound(cdf + 1, cdf + count + 1, u) - (cdf + 1)), 0, count - 1);
    const float width = cdf[bin + 1] - cdf[bin];
    remapped = width > 0.0f ? std::clamp((u - cdf[bin]) / width, 0.0f, 1.0f) : 0.5f;
    return bin;
}

}  // namespace

EnvironmentLight::EnvironmentLight(const RenderScene& scene, int columns, int rows)
    : m_scene(scene), m_columns(std::max(1, columns)), m_rows(std::max(1, rows)) {
    const std::size_t cells = std::size_t(m_columns) * std::size_t(m_rows);
    std::vector<double> brightest(cells, 0.0);  // the brightest of the cell's probes
    tbb::parallel_for(0, m_rows, [&](int row) {
        // Probes stratified in cos(theta) and phi: equal solid angles.
        const double z0 = row_cosine(row, 0.0, m_rows), z1 = row_cosine(row, 1.0, m_rows);
        for (int column = 0; column < m_columns; ++column) {
            double most = 0.0;
            for (int a = 0; a < 2; ++a) {
                for (int b = 0; b < 2; ++b) {
                    const double z = z0 + (z1 - z0) * (a + 0.5) / 2.0;
                    const double phi = 2.0 * M_PI * (column + (b + 0.5) / 2.0) / m_columns;
                    Ray ray;
                    ray.direction = direction_from(z, phi);
                    const Color radiance = scene.background(ray);
                    most = std::max(most, brightness(radiance));
                }
            }
            brightest[std::size_t(row) * m_columns + column] = most;
        }
    });

    // A cell is worth its brightest neighbour (3x3, round the sphere in
    // longitude): the probes miss the edge of a bright patch that only
    // grazes a cell, and such a cell left at the floor would be reached
    // rarely and with a huge weight.
    std::vector<double> value(cells, 0.0);
    for (int row = 0; row < m_rows; ++row) {
        for (int column = 0; column < m_columns; ++column) {
            double most = 0.0;
            for (int r = std::max(0, row - 1); r <= std::min(m_rows - 1, row + 1); ++r)
                for (int dc = -1; dc <= 1; ++dc) {
                    const int c = (column + dc + m_columns) % m_columns;
                    most = std::max(most, brightest[std::size_t(r) * m_columns + c]);
                }
            value[std::size_t(row) * m_columns + column] = most;
        }
    }

    // Solid angle of a cell in each row, and the sky's mean over the sphere.
    std::vector<double> solid_angle(std::size_t(m_rows), 0.0);
    double sphere_mean = 0.0;
    for (int row = 0; row < m_rows; ++row) {
        solid_angle[row] = 2.0 * M_PI / m_columns * (row_cosine(row, 0.0, m_rows) - row_cosine(row, 1.0, m_rows));
        for (int column = 0; column < m_columns; ++column)
            sphere_mean += value[std::size_t(row) * m_columns + column] * solid_angle[row];
    }
    sphere_mean /= 4.0 * M_PI;
    m_power = Color(float(4.0 * M_PI * sphere_mean));

    // Every cell keeps a floor of 1% of the mean brightness, so detail the
    // 2x2 probes missed (a sun smaller than a cell) can still be drawn.
    const double floor = sphere_mean > 0.0 ? 0.01 * sphere_mean : 1.0;
    std::vector<double> weight(cells);
    std::vector<double> row_weight(std::size_t(m_rows), 0.0);
    for (int row = 0; row < m_rows; ++row) {
        for (int column = 0; column < m_columns; ++column) {
            const std::size_t cell = std::size_t(row) * m_columns + column;
            weight[cell] = (value[cell] + floor) * solid_angle[row];
            row_weight[row] += weight[cell];
        }
    }
    double total = 0.0;
    for (double w : row_weight) total += w;
    m_row_cdf = normalised_cdf(row_weight.data(), m_rows, total);
    m_column_cdf.resize(std::size_t(m_rows) * (m_columns + 1));
    m_cell_pdf.resize(cells);
    for (int row = 0; row < m_rows; ++row) {
        const std::vector<float> cdf =
            normalised_cdf(weight.data() + std::size_t(row) * m_columns, m_columns, row_weight[row]);
        std::copy(cdf.begin(), cdf.end(), m_column_cdf.begin() + std::size_t(row) * (m_columns + 1));
        for (int column = 0; column < m_columns; ++column) {
            const std::size_t cell = std::size_t(row) * m_columns + column;
            m_cell_pdf[cell] = float(weight[cell] / total / solid_angle[row]);
        }
    }
}

LightSample EnvironmentLight::sample(const Vec3& p, const Vec2& u) const {
    float v_in_row = 0.0f, u_in_cell = 0.0f;
    const int row = pick(m_row_cdf.data(), m_rows, u.y, v_in_row);
    const int column = pick(m_column_cdf.data() + std::size_t(row) * (m_columns + 1), m_columns, u.x, u_in_cell);
    // Uniform in cos(theta) inside the cell: a constant density over it.
    const double z0 = row_cosine(row, 0.0, m_rows), z1 = row_cosine(row, 1.0, m_rows);
    const double z = z0 + (z1 - z0) * double(v_in_row);
    const double phi = 2.0 * M_PI * (column + double(u_in_cell)) / m_columns;
    LightSample s;
    s.wi = direction_from(z, phi);
    s.pdf = pdf(s.wi);
    s.distance = kDistance;
    s.point = p + s.wi * kDistance;
    Ray ray;
    ray.origin = p;
    ray.direction = s.wi;
    s.radiance = m_scene.background(ray);
    return s;
}

int EnvironmentLight::cell_of(int row, float phi) const {
    const int column = std::clamp(int(phi / (2.0f * kPi) * float(m_columns)), 0, m_columns - 1);
    return row * m_columns + column;
}

float EnvironmentLight::pdf(const Vec3& wi) const {
    const float length = glm::length(wi);
    if (!(length > 0.0f) || !std::isfinite(length)) return 0.0f;
    const float z = std::clamp(wi.y / length, -1.0f, 1.0f);
    const int row = std::clamp(int(std::acos(z) / kPi * float(m_rows)), 0, m_rows - 1);
    float phi = std::atan2(wi.z, wi.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    return m_cell_pdf[std::size_t(cell_of(row, phi))];
}

}  // namespace lancer
