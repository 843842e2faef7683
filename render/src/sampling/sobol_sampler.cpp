// Owen-scrambled Sobol sampler (sampler.h: make_sobol_sampler).
//
// Each pixel runs through the same Sobol sequence, sample index i giving
// point i; every (seed, pixel, dimension) gets its own nested uniform
// (Owen) scramble, so pixels are decorrelated while each pixel keeps the
// sequence's stratification: for 2^k samples every 1D projection is
// stratified in 2^k intervals and the first two dimensions form a (0,k,2)
// net. Owen scrambling also makes every point uniformly distributed, so
// estimates stay unbiased, and it speeds convergence on smooth integrands.
//
// Dimensions past the direction-number table fall back to independent
// uniform values hashed from (seed, pixel, index, dimension).
#include <array>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string_view>
#include <vector>

#include "lancer/sampler.h"
#include "sampling/bit_reversal.h"

namespace lancer {

namespace {

// Joe & Kuo's "new-joe-kuo-6.21201" direction numbers (S. Joe, F. Y. Kuo,
// SIAM J. Sci. Comput. 30, 2008), dimensions 2 to 53, one row per dimension
// as "s a m_1 ... m_s": s the degree of the primitive polynomial, a its
// interior coefficients as bits, m_k the initial odd direction integers.
// Dimension 1 is van der Corput and needs no row.
constexpr std::string_view kJoeKuo =
    "1 0 1|2 1 1 3|3 1 1 3 1|3 2 1 1 1|4 1 1 1 3 3|4 4 1 3 5 13|5 2 1 1 5 5 17|"
    "5 4 1 1 5 5 5|5 7 1 1 7 11 19|5 11 1 1 5 1 1|5 13 1 1 1 3 11|5 14 1 3 5 5 31|"
    "6 1 1 3 3 9 7 49|6 13 1 1 1 15 21 21|6 16 1 3 1 13 27 49|6 19 1 1 1 15 7 5|"
    "6 22 1 3 1 15 13 25|6 25 1 1 5 5 19 61|7 1 1 3 7 11 23 15 103|"
    "7 4 1 3 7 13 13 15 69|7 7 1 1 3 13 7 35 63|7 8 1 3 5 9 1 25 53|"
    "7 14 1 3 1 13 9 35 107|7 19 1 3 1 5 27 61 31|7 21 1 1 5 11 19 41 61|"
    "7 28 1 3 5 3 3 13 69|7 31 1 1 7 13 1 19 1|7 32 1 3 7 5 13 19 59|"
    "7 37 1 1 3 9 25 29 41|7 41 1 3 5 13 23 1 55|7 42 1 3 7 3 13 59 17|"
    "7 50 1 3 1 3 5 53 69|7 55 1 1 5 5 23 33 13|7 56 1 1 7 7 1 61 123|"
    "7 59 1 1 7 9 13 61 49|7 62 1 3 3 5 3 55 33|8 14 1 3 1 15 31 13 49 245|"
    "8 21 1 3 5 15 31 59 63 97|8 22 1 3 1 11 11 11 77 249|8 38 1 3 1 11 27 43 71 9|"
    "8 47 1 1 7 15 21 11 81 45|8 49 1 3 7 3 25 31 65 79|8 50 1 3 1 1 19 11 3 205|"
    "8 52 1 1 5 9 19 21 29 157|8 56 1 3 7 11 1 33 89 185|8 67 1 3 3 3 15 9 79 71|"
    "8 70 1 3 7 11 15 39 119 27|8 84 1 1 3 1 11 31 97 225|8 97 1 1 1 3 23 43 57 177|"
    "8 103 1 3 7 7 17 17 37 71|8 115 1 3 1 5 27 63 123 213|8 122 1 1 3 5 11 43 53 133";

constexpr int kBits = 32;
using DirectionNumbers = std::vector<std::array<std::uint32_t, kBits>>;

// Expands the table into 32 direction numbers per dimension (V_k as 0.32
// fixed point), Bratley & Fox's recurrence.
DirectionNumbers build_direction_numbers() {
    DirectionNumbers table;
    std::array<std::uint32_t, kBits> v{};
    for (int k = 0; k < kBits; ++k) v[k] = 1u << (kBits - 1 - k);
    table.push_back(v);

    std::size_t start = 0;
    while (start < kJoeKuo.size()) {
        std::size_t end = kJoeKuo.find('|', start);
        if (end == std::string_view::npos) end = kJoeKuo.size();
        std::istringstream row{std::string(kJoeKuo.substr(start, end - start))};
        start = end + 1;
        unsigned s = 0, a = 0;
        row >> s >> a;
        for (unsigned k = 0; k < s; ++k) {
            std::uint32_t m = 0;
            row >> m;
            v[k] = m << (kBits - 1 - k);
        }
        for (unsigned k = s; k < unsigned(kBits); ++k) {
            std::uint32_t x = v[k - s] ^ (v[k - s] >> s);
            for (unsigned j = 1; j < s; ++j)
                if ((a >> (s - 1 - j)) & 1u) x ^= v[k - j];
            v[k] = x;
        }
        table.push_back(v);
    }
    return table;
}

// The direction numbers with their bits reversed (see owen_scramble_reversed).
const DirectionNumbers& reversed_direction_numbers() {
    static const DirectionNumbers table = [] {
        DirectionNumbers reversed = build_direction_numbers();
        for (auto& dimension : reversed)
            for (std::uint32_t& v : dimension) v = reverse_bits(v);
        return reversed;
    }();
    return table;
}

// Point `index` of the dimension with reversed direction numbers v,
// reversed: the XOR of the direction numbers of the index's set bits.
std::uint32_t reversed_point(const std::array<std::uint32_t, kBits>& v, std::uint32_t index) {
    std::uint32_t x = 0;
    for (std::uint32_t i = index; i != 0; i &= i - 1) x ^= v[std::size_t(__builtin_ctz(i))];
    return x;
}

// The first kTabulatedPoints points of every dimension as reversed_point
// gives them, point i of dimension d at [i * dimensions + d] so that one
// sample's dimensions share cache lines. Renders of up to 256 samples a
// pixel (nearly all) take every point from here: building a point at each
// value cost about a quarter of the sampler's instructions.
constexpr std::uint32_t kTabulatedPoints = 256;

const std::vector<std::uint32_t>& tabulated_points() {
    static const std::vector<std::uint32_t> table = [] {
        const DirectionNumbers& v = reversed_direction_numbers();
        std::vector<std::uint32_t> points(kTabulatedPoints * v.size());
        for (std::uint32_t index = 0; index < kTabulatedPoints; ++index)
            for (std::size_t d = 0; d < v.size(); ++d) points[index * v.size() + d] = reversed_point(v[d], index);
        return points;
    }();
    return table;
}

// 64-bit finaliser (a strong avalanche mixer; constants from Stafford's
// Mix13 variant of the MurmurHash3 finaliser).
std::uint64_t mix64(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

// Nested uniform scramble (Burley, "Practical hash-based Owen scrambling",
// JCGT 2020): on bit-reversed values, a hash in which every bit depends only
// on the bits below it flips each digit as a function of the digits above
// it in the original order, which is Owen's scramble. It takes and returns
// bit-reversed values: the points are built reversed (from reversed
// direction numbers), so only the result is reversed back.
std::uint32_t owen_scramble_reversed(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// [0,1) from the top 24 bits, so the float is exact and never rounds to 1.
float to_unit_float(std::uint32_t x) {
    return float(x >> 8) * 0x1p-24f;
}

class SobolSampler final : public Sampler {
  public:
    explicit SobolSampler(std::uint64_t seed)
        : m_seed(mix64(seed ^ 0x5b1e5c0ffee5eedull)),
          m_table(&reversed_direction_numbers()),
          m_points(tabulated_points().data()) {}

    void start_sample(int pixel_x, int pixel_y, std::uint32_t sample_index) override {
        m_pixel_key = mix64(m_seed ^ mix64((std::uint64_t(std::uint32_t(pixel_x)) << 32) | std::uint32_t(pixel_y)));
        m_index = sample_index;
        m_dimension = 0;
        m_index_points =
            sample_index < kTabulatedPoints ? m_points + std::size_t(sample_index) * m_table->size() : nullptr;
    }

    float next_1d() override { return value(m_dimension++); }

    Vec2 next_2d() override {
        const float a = value(m_dimension);
        const float b = value(m_dimension + 1);
        m_dimension += 2;
        return Vec2(a, b);
    }

    std::unique_ptr<Sampler> clone() const override { return std::make_unique<SobolSampler>(*this); }

  private:
    float value(std::uint32_t dimension) const {
        const std::uint64_t dim_key = mix64(m_pixel_key + 0x9e3779b97f4a7c15ull * (dimension + 1));
        if (dimension >= m_table->size())
            return to_unit_float(std::uint32_t(mix64(dim_key ^ (std::uint64_t(m_index) << 17)) >> 32));
        const std::uint32_t x =
            m_index_points != nullptr ? m_index_points[dimension] : reversed_point((*m_table)[dimension], m_index);
        return to_unit_float(reverse_bits(owen_scramble_reversed(x, std::uint32_t(dim_key >> 32))));
    }

    std::uint64_t m_seed;
    const DirectionNumbers* m_table;
    const std::uint32_t* m_points;                  // tabulated_points()
    const std::uint32_t* m_index_points = nullptr;  // this sample's row of them, if tabulated
    std::uint64_t m_pixel_key = 0;
    std::uint32_t m_index = 0;
    std::uint32_t m_dimension = 0;
};

}  // namespace

std::unique_ptr<Sampler> make_sobol_sampler(std::uint64_t seed) {
    return std::make_unique<SobolSampler>(seed);
}

}  // namespace lancer
