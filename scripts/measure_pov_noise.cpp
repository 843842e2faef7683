// Recovers POV-Ray 3.7's noise tables by measuring povray, and writes them
// (render/src/materials/pov_noise_tables.inc) with samples of POV's own
// output for the tests (tests/reference/pov/noise/*.txt). Run through
// scripts/measure-pov-noise.sh; docs/noise.md explains the method.
//
// Every measurement is a scene that writes numbers at parse time: povray
// evaluates f_noise_generator (POV's Noise() with a chosen generator),
// vturbulence (POV's DTurbulence, whose first octave is DNoise) and a marble
// pattern function (whose classic turbulence is POV's scalar Turbulence()).
// Coordinates are always k / 2^20, written as that quotient, so POV and this
// program hold the very same doubles.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

using Vec3 = std::array<double, 3>;

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "measure_pov_noise: %s\n", message.c_str());
    std::exit(1);
}

// --- Talking to povray ---

std::string g_work_dir;
int g_scene_count = 0;

// An exact SDL spelling of a coordinate that is a multiple of 2^-20.
std::string sdl_number(double v) {
    const double scaled = v * 1048576.0;
    if (scaled != std::floor(scaled) || std::fabs(scaled) > 9.0e15) fail("coordinate not a multiple of 2^-20");
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "(%.0f/1048576)", scaled);
    return buffer;
}

std::string sdl_vector(const Vec3& p) {
    return "<" + sdl_number(p[0]) + "," + sdl_number(p[1]) + "," + sdl_number(p[2]) + ">";
}

// Runs one scene made of `declarations` and one #write per query (each query
// writes one or more numbers), and returns every number written, in order.
std::vector<double> run_povray(const std::string& declarations, const std::vector<std::string>& queries) {
    const std::string stem = g_work_dir + "/scene" + std::to_string(g_scene_count++);
    {
        std::ofstream scene(stem + ".pov");
        scene << "#version 3.7;\n#include \"functions.inc\"\n" << declarations << "\n";
        scene << "#fopen Out \"" << stem << ".txt\" write\n";
        for (const std::string& q : queries) scene << q << "\n";
        scene << "#fclose Out\n";
    }
    const std::string command = "povray +I" + stem + ".pov -D +W1 +H1 -GA +O" + stem + ".png >" + stem + ".log 2>&1";
    if (std::system(command.c_str()) != 0) fail("povray failed, see " + stem + ".log");
    std::ifstream in(stem + ".txt");
    std::vector<double> numbers;
    double v;
    while (in >> v) numbers.push_back(v);
    return numbers;
}

std::string write_number(const std::string& expression) {
    return "#write(Out, str(" + expression + ", 0, 17), \"\\n\")";
}

// POV's Noise(p) with a generator (1, 2 or 3).
std::string noise_query(const Vec3& p, int generator) {
    return write_number("f_noise_generator(" + sdl_number(p[0]) + "," + sdl_number(p[1]) + "," + sdl_number(p[2]) +
                        "," + std::to_string(generator) + ")");
}

// POV's DTurbulence(p) (three numbers); with one octave, DNoise(p).
std::string dturbulence_query(const Vec3& p, double lambda, double omega, int octaves) {
    char head[128];
    std::snprintf(head, sizeof head, "#declare V = vturbulence(%.17g, %.17g, %d, ", lambda, omega, octaves);
    return std::string(head) + sdl_vector(p) +
           "); #write(Out, str(V.x, 0, 17), \" \", str(V.y, 0, 17), \" \", str(V.z, 0, 17), \"\\n\")";
}

std::string dnoise_query(const Vec3& p) {
    return dturbulence_query(p, 2.0, 0.5, 1);
}

std::vector<Vec3> triples(const std::vector<double>& numbers) {
    if (numbers.size() % 3 != 0) fail("expected triples");
    std::vector<Vec3> out;
    for (size_t i = 0; i < numbers.size(); i += 3) out.push_back({numbers[i], numbers[i + 1], numbers[i + 2]});
    return out;
}

double s_curve(double t) {
    return t * t * (3.0 - 2.0 * t);
}

double quantize(double v) {
    return std::round(v * 1048576.0) / 1048576.0;
}

// The shortest decimal (up to 15 significant digits) within `tolerance` of v.
double shortest_decimal(double v, double tolerance) {
    for (int digits = 1; digits <= 15; ++digits) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, v);
        const double candidate = std::strtod(buffer, nullptr);
        if (std::fabs(candidate - v) <= tolerance) return candidate;
    }
    return v;
}

// Least squares by Householder QR (columns x unknowns), for the cell fits.
std::vector<double> least_squares(std::vector<std::vector<double>> rows, std::vector<double> rhs, double* rms) {
    const size_t m = rows.size(), n = rows[0].size();
    std::vector<long double> a(m * n), b(rhs.begin(), rhs.end());
    for (size_t i = 0; i < m; ++i)
        for (size_t j = 0; j < n; ++j) a[i * n + j] = rows[i][j];
    for (size_t k = 0; k < n; ++k) {
        long double norm = 0;
        for (size_t i = k; i < m; ++i) norm += a[i * n + k] * a[i * n + k];
        norm = std::sqrt(norm);
        if (norm == 0) fail("singular least squares");
        const long double alpha = a[k * n + k] > 0 ? -norm : norm;
        std::vector<long double> v(m, 0);
        for (size_t i = k; i < m; ++i) v[i] = a[i * n + k];
        v[k] -= alpha;
        long double vv = 0;
        for (size_t i = k; i < m; ++i) vv += v[i] * v[i];
        for (size_t j = k; j < n; ++j) {
            long double dot = 0;
            for (size_t i = k; i < m; ++i) dot += v[i] * a[i * n + j];
            for (size_t i = k; i < m; ++i) a[i * n + j] -= 2 * dot / vv * v[i];
        }
        long double dot = 0;
        for (size_t i = k; i < m; ++i) dot += v[i] * b[i];
        for (size_t i = k; i < m; ++i) b[i] -= 2 * dot / vv * v[i];
    }
    std::vector<double> x(n);
    for (size_t k = n; k-- > 0;) {
        long double s = b[k];
        for (size_t j = k + 1; j < n; ++j) s -= a[k * n + j] * x[j];
        x[k] = static_cast<double>(s / a[k * n + k]);
    }
    if (rms) {
        long double r = 0;
        for (size_t i = n; i < m; ++i) r += b[i] * b[i];
        *rms = static_cast<double>(std::sqrt(r / m));
    }
    return x;
}

// ===================== Generators 1 and 2, and DNoise =====================
//
// A lattice corner contributes value/2 + gradient . offset for each of the
// three components of DNoise (x: the scalar noise's sum), read from one table
// of values R at 12 consecutive positions starting at the corner's index k:
// x component (R[k]/2, R[k+1], R[k+2], R[k+3]), y (R[k+4]/2, ...),
// z (R[k+8]/2, ...). k is a hash of the corner's integer coordinates.

struct Lattice {
    int origin = 0;                    // hash index of a coordinate n: (n + origin) & 0xFFF
    std::array<double, 267> values{};  // R
    std::array<int, 4096> hash_x{}, hash_y{}, hash_z{};
};

Lattice measure_lattice() {
    // 1. The DNoise triple at the lattice points (0, 0, z): (R[k]/2, R[k+4]/2,
    //    R[k+8]/2) of that corner, exactly (only one corner has weight there).
    std::vector<std::string> queries;
    for (int z = 0; z < 4096; ++z) queries.push_back(dnoise_query({0, 0, double(z)}));
    const std::vector<Vec3> column = triples(run_povray("", queries));
    std::map<Vec3, int> label_of;  // a corner's triple names its index k (to be found)
    std::vector<Vec3> label_triple;
    std::vector<int> column_label(4096);
    for (int z = 0; z < 4096; ++z) {
        auto [it, inserted] = label_of.emplace(column[z], int(label_triple.size()));
        if (inserted) label_triple.push_back(column[z]);
        column_label[z] = it->second;
    }
    std::printf("lattice: %zu distinct corner triples along a column of 4096 corners\n", label_triple.size());
    if (label_triple.size() != 256) fail("expected 256 distinct corners");

    // 2. Each label's 12 table entries: its values (exact) and its gradients,
    //    from two points on each edge leaving a corner that carries it.
    std::vector<int> label_z(256, -1);
    for (int z = 0; z < 4096; ++z)
        if (label_z[column_label[z]] < 0) label_z[column_label[z]] = z;
    const double t1 = 0.25, t2 = 0.75;
    queries.clear();
    for (int label = 0; label < 256; ++label) {
        const Vec3 corner{0, 0, double(label_z[label])};
        for (int axis = 0; axis < 3; ++axis) {
            Vec3 next = corner, p1 = corner, p2 = corner;
            next[axis] += 1;
            p1[axis] += t1;
            p2[axis] += t2;
            queries.push_back(dnoise_query(next));
            queries.push_back(dnoise_query(p1));
            queries.push_back(dnoise_query(p2));
        }
    }
    const std::vector<Vec3> edges = triples(run_povray("", queries));
    std::vector<std::array<double, 12>> entries(256);
    std::vector<std::array<bool, 12>> exact(256);
    for (int label = 0; label < 256; ++label) {
        const Vec3& a = label_triple[label];
        for (int c = 0; c < 3; ++c) {
            entries[label][4 * c] = 2.0 * a[c];
            exact[label][4 * c] = true;
        }
        for (int axis = 0; axis < 3; ++axis) {
            const Vec3& b = edges[label * 9 + axis * 3];
            const Vec3& v1 = edges[label * 9 + axis * 3 + 1];
            const Vec3& v2 = edges[label * 9 + axis * 3 + 2];
            const double s1 = s_curve(t1), s2 = s_curve(t2);
            for (int c = 0; c < 3; ++c) {
                // v = (1-s)(A + gA t) + s(B + gB (t-1)): solve for gA, gB.
                const double r1 = v1[c] - (1 - s1) * a[c] - s1 * b[c];
                const double r2 = v2[c] - (1 - s2) * a[c] - s2 * b[c];
                const double m11 = (1 - s1) * t1, m12 = s1 * (t1 - 1), m21 = (1 - s2) * t2, m22 = s2 * (t2 - 1);
                const double det = m11 * m22 - m12 * m21;
                entries[label][4 * c + 1 + axis] = (r1 * m22 - m12 * r2) / det;
                exact[label][4 * c + 1 + axis] = false;
            }
        }
    }
    // 3. Order the labels: label M follows label L when M's first entry is
    //    L's second one (the 12-entry windows overlap).
    std::vector<int> next(256, -1), previous(256, -1);
    for (int l = 0; l < 256; ++l)
        for (int m = 0; m < 256; ++m)
            if (std::fabs(entries[m][0] - entries[l][1]) < 1e-9) {
                if (next[l] >= 0) fail("ambiguous successor");
                next[l] = m;
                previous[m] = l;
            }
    int first = -1;
    for (int l = 0; l < 256; ++l)
        if (previous[l] < 0) {
            if (first >= 0) fail("two chain starts");
            first = l;
        }
    std::vector<int> index_of_label(256, -1);
    int label = first;
    for (int k = 0; k < 256; ++k) {
        if (label < 0) fail("chain broken");
        index_of_label[label] = k;
        label = next[label];
    }
    // 4. The value table: every estimate of R[m], exact ones preferred.
    Lattice lattice;
    std::vector<double> best(267, NAN);
    std::vector<bool> best_exact(267, false);
    double worst_disagreement = 0;
    for (int l = 0; l < 256; ++l)
        for (int j = 0; j < 12; ++j) {
            const int m = index_of_label[l] + j;
            if (!std::isnan(best[m]))
                worst_disagreement = std::max(worst_disagreement, std::fabs(best[m] - entries[l][j]));
            if (std::isnan(best[m]) || (exact[l][j] && !best_exact[m])) {
                best[m] = entries[l][j];
                best_exact[m] = exact[l][j];
            }
        }
    std::printf("lattice: overlapping estimates of the value table agree within %.3g\n", worst_disagreement);
    if (worst_disagreement > 1e-9) fail("inconsistent value table");
    // The exactly measured entries are all 6-significant-digit decimals; the
    // few known only from slopes (to ~1e-15) are rounded the same way.
    int snapped = 0, inexact = 0;
    for (int m = 0; m < 267; ++m) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.5e", best[m]);
        const double decimal = std::strtod(buffer, nullptr);
        if (best_exact[m]) {
            if (0.5 + decimal * 0.5 != 0.5 + best[m] * 0.5) fail("an exact entry is not a 6-digit decimal");
        } else {
            ++inexact;
            if (std::fabs(decimal - best[m]) > 1e-12) fail("a slope entry is not near a 6-digit decimal");
        }
        lattice.values[m] = decimal;
        ++snapped;
    }
    std::printf("lattice: value table of %d entries (%d measured only as slopes)\n", snapped, inexact);

    // 5. The hash. k(x, y, z) = H(H(H(x) ^ y) ^ z) with a permutation H of
    //    12-bit indices (n + origin) & 0xFFF. Measured: the labels of the
    //    corners (x, 0, z), (x, 1, z) and (0, y, z) for z = 0..3, and
    //    random lattice points to check the result.
    queries.clear();
    const int kFingerprint = 4;
    for (int sweep = 0; sweep < 3; ++sweep)
        for (int i = 0; i < 4096; ++i)
            for (int z = 0; z < kFingerprint; ++z) {
                const Vec3 p = sweep == 0   ? Vec3{double(i), 0, double(z)}
                               : sweep == 1 ? Vec3{double(i), 1, double(z)}
                                            : Vec3{0, double(i), double(z)};
                queries.push_back(dnoise_query(p));
            }
    std::mt19937_64 random(20240607);
    std::uniform_int_distribution<int> coordinate(-30000, 30000);
    std::vector<std::array<int, 3>> checks;
    for (int i = 0; i < 3000; ++i) {
        checks.push_back({coordinate(random), coordinate(random), coordinate(random)});
        queries.push_back(dnoise_query({double(checks.back()[0]), double(checks.back()[1]), double(checks.back()[2])}));
    }
    const std::vector<Vec3> measured = triples(run_povray("", queries));
    auto label_at = [&](size_t i) {
        auto it = label_of.find(measured[i]);
        if (it == label_of.end()) fail("a corner with an unknown triple");
        return it->second;
    };
    std::vector<int> sweep_labels(3 * 4096 * kFingerprint), check_labels(checks.size());
    for (size_t i = 0; i < sweep_labels.size(); ++i) sweep_labels[i] = label_at(i);
    for (size_t i = 0; i < checks.size(); ++i) check_labels[i] = label_at(sweep_labels.size() + i);

    // Every origin is tried; the right one makes the XOR structure hold.
    std::vector<int> passing;
    for (int origin = 0; origin < 4096; ++origin) {
        auto index = [&](int n) { return (n + origin) & 0xFFF; };
        // column[w]: the label at (0, 0) for z index w. With d(x, y) =
        // H(H(x) ^ y) ^ H(H(x0) ^ y0), label(x, y, z) = column[d ^ z].
        std::array<int, 4096> column_at{};
        for (int z = 0; z < 4096; ++z) column_at[index(z)] = column_label[z];
        std::unordered_map<std::uint32_t, int> d_of_fingerprint;
        bool unique = true;
        for (int d = 0; d < 4096 && unique; ++d) {
            std::uint32_t key = 0;
            for (int z = 0; z < kFingerprint; ++z) key = key * 256 + column_at[d ^ index(z)];
            unique = d_of_fingerprint.emplace(key, d).second;
        }
        if (!unique) continue;
        auto d_of = [&](int sweep, int i) {
            std::uint32_t key = 0;
            for (int z = 0; z < kFingerprint; ++z)
                key = key * 256 + sweep_labels[(sweep * 4096 + i) * kFingerprint + z];
            auto it = d_of_fingerprint.find(key);
            return it == d_of_fingerprint.end() ? -1 : it->second;
        };
        // hash_y[y] = d(x0, y); hash_x[x] such that hash_y[hash_x[x] ^ y] = d(x, y).
        std::array<int, 4096> hash_y{}, inverse_y{}, hash_x{};
        inverse_y.fill(-1);
        bool ok = true;
        for (int y = 0; y < 4096 && ok; ++y) {
            const int d = d_of(2, y);
            if (d < 0 || inverse_y[d] >= 0)
                ok = false;
            else {
                hash_y[index(y)] = d;
                inverse_y[d] = index(y);
            }
        }
        for (int x = 0; x < 4096 && ok; ++x) {
            const int d0 = d_of(0, x), d1 = d_of(1, x);
            if (d0 < 0 || d1 < 0)
                ok = false;
            else {
                hash_x[index(x)] = inverse_y[d0] ^ index(0);
                if (hash_y[hash_x[index(x)] ^ index(1)] != d1) ok = false;
            }
        }
        for (size_t i = 0; i < checks.size() && ok; ++i) {
            const int d = hash_y[hash_x[index(checks[i][0])] ^ index(checks[i][1])];
            if (column_at[d ^ index(checks[i][2])] != check_labels[i]) ok = false;
        }
        if (!ok) continue;
        passing.push_back(origin);
        if (passing.size() == 1) {
            lattice.origin = origin;
            for (int i = 0; i < 4096; ++i) {
                lattice.hash_x[i] = hash_x[i];
                lattice.hash_y[i] = hash_y[i];
                lattice.hash_z[i] = index_of_label[column_at[i]];
            }
        }
    }
    std::printf("lattice: hash origins consistent with all %zu measured corners:", checks.size());
    for (int o : passing) std::printf(" %d", o);
    std::printf("\n");
    if (passing.empty()) fail("no hash origin fits");
    return lattice;
}

// The lattice sum at p (POV's Noise before the shift), from the recovered
// tables: used to fit generator 2's constants.
double lattice_sum(const Lattice& t, const Vec3& p) {
    int cell[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
        const double x = p[a];
        const std::int64_t n = x >= 0 ? std::int64_t(x) : std::int64_t(x - (1 - 1e-10));
        cell[a] = int((n + t.origin) & 0xFFF);
        f[a] = x - double(n);
    }
    double sum = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const int cx = corner & 1, cy = (corner >> 1) & 1, cz = corner >> 2;
        const int k = t.hash_z[(t.hash_y[(t.hash_x[(cell[0] + cx) & 0xFFF] ^ ((cell[1] + cy) & 0xFFF))] ^
                                ((cell[2] + cz) & 0xFFF))];
        double w = 1, term = t.values[k] * 0.5;
        const int c[3] = {cx, cy, cz};
        for (int a = 0; a < 3; ++a) {
            const double s = s_curve(f[a]);
            w *= c[a] ? s : 1 - s;
            term += t.values[k + 1 + a] * (f[a] - c[a]);
        }
        sum += w * term;
    }
    return sum;
}

struct RangeCorrection {
    double shift = 0, scale = 0;
};

RangeCorrection measure_range_correction(const Lattice& lattice) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-50, 50);
    std::vector<Vec3> points;
    std::vector<std::string> queries;
    for (int i = 0; i < 400; ++i) {
        points.push_back({quantize(coordinate(random)), quantize(coordinate(random)), quantize(coordinate(random))});
        queries.push_back(noise_query(points.back(), 2));
    }
    const std::vector<double> values = run_povray("", queries);
    // value = (sum + shift) * scale: a straight line in the sum.
    std::vector<std::vector<double>> rows;
    std::vector<double> rhs;
    for (size_t i = 0; i < points.size(); ++i) {
        if (values[i] <= 0 || values[i] >= 1) continue;
        rows.push_back({lattice_sum(lattice, points[i]), 1.0});
        rhs.push_back(values[i]);
    }
    double rms = 0;
    const std::vector<double> line = least_squares(rows, rhs, &rms);
    RangeCorrection r;
    r.scale = shortest_decimal(line[0], 1e-12);
    r.shift = shortest_decimal(line[1] / line[0], 1e-12);
    std::printf("generator 2: value = (sum + %.17g) * %.17g (fit %.17g, %.17g; rms %.3g)\n", r.shift, r.scale,
                line[1] / line[0], line[0], rms);
    return r;
}

// ===================== Generator 3 =====================
//
// A gradient lattice: corner c contributes g_c . (p - c), interpolated by the
// s-curve (zero at the corners, where the value is a constant midpoint).
// Cells are floor(coordinate + offset) for a large non-integer offset; the
// gradient of corner (x, y, z) is G[(HY[(HX[x] + y) & 2047] + z) & 2047].

struct Solid {
    double offset = 0, midpoint = 0;
    std::array<int, 2048> hash_x{}, hash_y{};
    std::vector<Vec3> gradients = std::vector<Vec3>(2048);
};

struct CellSamples {
    Vec3 origin;  // world coordinates of the cell's lower corner (integers)
    std::vector<Vec3> points;
    std::vector<double> values;
};

struct CellFit {
    std::array<Vec3, 8> gradients;  // corner (cx, cy, cz) at index cx + 2 cy + 4 cz
    double midpoint = 0, rms = 0;
    std::array<int, 3> cell{};  // index of the lower corner: floor(coordinate + offset) & 2047
};

CellFit fit_cell(const CellSamples& samples, double offset) {
    std::vector<std::vector<double>> rows;
    std::vector<double> rhs;
    CellFit fit;
    for (size_t i = 0; i < samples.points.size(); ++i) {
        if (samples.values[i] <= 0 || samples.values[i] >= 1) continue;
        double r[3], s[3];
        for (int a = 0; a < 3; ++a) {
            const double t = samples.points[i][a] + offset;
            const double floor_t = std::floor(t);
            r[a] = t - floor_t;
            s[a] = s_curve(r[a]);
            fit.cell[a] = int(std::int64_t(floor_t) & 2047);
        }
        std::vector<double> row(25);
        for (int corner = 0; corner < 8; ++corner) {
            const int c[3] = {corner & 1, (corner >> 1) & 1, corner >> 2};
            double w = 1;
            for (int a = 0; a < 3; ++a) w *= c[a] ? s[a] : 1 - s[a];
            for (int a = 0; a < 3; ++a) row[corner * 3 + a] = w * (r[a] - c[a]);
        }
        row[24] = 1;
        rows.push_back(row);
        rhs.push_back(samples.values[i]);
    }
    const std::vector<double> x = least_squares(rows, rhs, &fit.rms);
    for (int corner = 0; corner < 8; ++corner)
        fit.gradients[corner] = {x[3 * corner], x[3 * corner + 1], x[3 * corner + 2]};
    fit.midpoint = x[24];
    return fit;
}

std::vector<CellSamples> measure_cells(const std::vector<Vec3>& origins, int per_cell, std::mt19937_64& random) {
    std::uniform_real_distribution<double> fraction(0.05, 0.95);
    std::vector<CellSamples> cells;
    std::vector<std::string> queries;
    for (const Vec3& o : origins) {
        CellSamples cell;
        cell.origin = o;
        for (int i = 0; i < per_cell; ++i) {
            cell.points.push_back({o[0] + quantize(fraction(random)), o[1] + quantize(fraction(random)),
                                   o[2] + quantize(fraction(random))});
            queries.push_back(noise_query(cell.points.back(), 3));
        }
        cells.push_back(std::move(cell));
    }
    const std::vector<double> values = run_povray("", queries);
    size_t next = 0;
    for (CellSamples& cell : cells)
        for (size_t i = 0; i < cell.points.size(); ++i) cell.values.push_back(values[next++]);
    return cells;
}

Solid measure_solid() {
    Solid solid;
    std::mt19937_64 random(3);
    // 1. The offset: the one that makes a few densely sampled cells fit the
    //    gradient-lattice form best (coarse scan, then golden section, then
    //    the neighbouring doubles). Samples lie at fractions 0.05..0.95 of the
    //    integer cells, so offsets in [0, 0.05) keep them in one cell.
    const std::vector<CellSamples> probes = measure_cells({{0, 0, 0}, {5, -3, 2}, {-7, 11, -4}}, 120, random);
    auto misfit = [&](double offset) {
        double total = 0;
        for (const CellSamples& cell : probes) total += fit_cell(cell, offset).rms;
        return total;
    };
    constexpr double kMagnitude = 1.0e7;  // sets the rounding of coordinate + offset (see docs/noise.md)
    double best = 0, best_misfit = INFINITY;
    for (int i = 0; i < 500; ++i) {
        const double f = 0.0001 * i;
        const double m = misfit(kMagnitude + f);
        if (m < best_misfit) best_misfit = m, best = f;
    }
    double lo = best - 0.0001, hi = best + 0.0001;
    for (int i = 0; i < 80; ++i) {
        const double a = lo + (hi - lo) * 0.382, b = lo + (hi - lo) * 0.618;
        if (misfit(kMagnitude + a) < misfit(kMagnitude + b))
            hi = b;
        else
            lo = a;
    }
    double offset = kMagnitude + 0.5 * (lo + hi);
    double offset_misfit = misfit(offset);
    for (double candidate = std::nextafter(offset - 64 * 1.862645149230957e-09, 0.0), end = offset + 64 * 1.9e-9;
         candidate < end; candidate = std::nextafter(candidate, INFINITY)) {
        const double m = misfit(candidate);
        if (m < offset_misfit) offset_misfit = m, offset = candidate;
    }
    solid.offset = offset;
    std::printf("generator 3: lattice offset %.17g (misfit %.3g)\n", offset, offset_misfit);

    // 2. Gradients along a column of cells (gives G up to a rotation), and the
    //    corners of rows of cells along x and y (the two hash levels).
    std::vector<Vec3> origins;
    for (int i = 0; i < 2048; i += 2) origins.push_back({0, 0, double(i)});
    for (int i = 0; i < 2048; i += 2) origins.push_back({double(i), 0, 0});
    for (int i = 0; i < 2048; i += 2) origins.push_back({0, double(i), 0});
    const std::vector<CellSamples> cells = measure_cells(origins, 40, random);
    std::vector<CellFit> fits;
    double worst_rms = 0, midpoint_sum = 0;
    for (const CellSamples& cell : cells) {
        fits.push_back(fit_cell(cell, offset));
        worst_rms = std::max(worst_rms, fits.back().rms);
        midpoint_sum += fits.back().midpoint;
    }
    solid.midpoint = shortest_decimal(midpoint_sum / fits.size(), 1e-10);
    std::printf("generator 3: %zu cells fitted, worst rms %.3g, midpoint %.17g (mean fit %.17g)\n", fits.size(),
                worst_rms, solid.midpoint, midpoint_sum / fits.size());

    const int x0 = fits[0].cell[0], y0 = fits[0].cell[1];
    std::vector<bool> seen(2048, false);
    for (size_t i = 0; i < 1024; ++i)
        for (int cz = 0; cz < 2; ++cz) {
            const int w = (fits[i].cell[2] + cz) & 2047;
            solid.gradients[w] = fits[i].gradients[4 * cz];
            seen[w] = true;
        }
    if (std::count(seen.begin(), seen.end(), true) != 2048) fail("gradient column incomplete");
    auto distance = [](const Vec3& a, const Vec3& b) {
        return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])});
    };
    double worst_match = 0, nearest_other = INFINITY;
    auto match = [&](const Vec3& g) {
        int best_index = -1;
        double best_distance = INFINITY, second = INFINITY;
        for (int w = 0; w < 2048; ++w) {
            const double d = distance(g, solid.gradients[w]);
            if (d < best_distance)
                second = best_distance, best_distance = d, best_index = w;
            else
                second = std::min(second, d);
        }
        worst_match = std::max(worst_match, best_distance);
        nearest_other = std::min(nearest_other, second);
        if (best_distance > 1e-6) fail("a gradient matches no column gradient");
        return best_index;
    };
    // d(x, y): G(x, y, z) = column[(d + z) & 2047]; both z corners must agree.
    std::map<std::pair<int, int>, int> d;
    for (const CellFit& fit : fits)
        for (int corner = 0; corner < 8; ++corner) {
            const int cx = corner & 1, cy = (corner >> 1) & 1, cz = corner >> 2;
            const int x = (fit.cell[0] + cx) & 2047, y = (fit.cell[1] + cy) & 2047, z = (fit.cell[2] + cz) & 2047;
            const int value = (match(fit.gradients[corner]) - z) & 2047;
            auto [it, inserted] = d.emplace(std::make_pair(x, y), value);
            if (!inserted && it->second != value) fail("inconsistent generator-3 hash");
        }
    std::printf("generator 3: corners match column gradients within %.3g (others at least %.3g away)\n", worst_match,
                nearest_other);
    // hash_y[y] = d(x0, y); hash_x[x] such that hash_y[(hash_x[x] + y) & 2047] = d(x, y).
    for (int y = 0; y < 2048; ++y) {
        auto it = d.find({x0, y});
        if (it == d.end()) fail("generator-3 y row incomplete");
        solid.hash_y[y] = it->second;
    }
    int ambiguous = 0;
    for (int x = 0; x < 2048; ++x) {
        auto d0 = d.find({x, y0}), d1 = d.find({x, (y0 + 1) & 2047});
        if (d0 == d.end() || d1 == d.end()) fail("generator-3 x row incomplete");
        std::vector<int> candidates;
        for (int w = 0; w < 2048; ++w)
            if (solid.hash_y[(w + y0) & 2047] == d0->second && solid.hash_y[(w + y0 + 1) & 2047] == d1->second)
                candidates.push_back(w);
        if (candidates.empty()) fail("generator-3 x hash has no solution");
        ambiguous += candidates.size() > 1;
        solid.hash_x[x] = candidates[0];
    }
    std::printf("generator 3: hash recovered (%d x entries ambiguous)\n", ambiguous);
    return solid;
}

// ===================== Output =====================

template <typename T, size_t N>
void write_table(std::ostream& out, const char* declaration, const std::array<T, N>& values, const char* format,
                 size_t per_line) {
    out << declaration << " = {\n";
    for (size_t i = 0; i < N; ++i) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, format, values[i]);
        out << (i % per_line == 0 ? "    " : " ") << buffer << ",";
        if (i % per_line == per_line - 1 || i + 1 == N) out << "\n";
    }
    out << "};\n";
}

void write_tables(const std::string& path, const Lattice& lattice, const RangeCorrection& range, const Solid& solid) {
    std::ofstream out(path);
    out << "// Generated by scripts/measure-pov-noise.sh (scripts/measure_pov_noise.cpp) from\n"
           "// measurements of POV-Ray 3.7.0.10's output; do not edit. See docs/noise.md.\n"
           "// Included by noise.cpp inside an anonymous namespace.\n\n";
    out << "// Generators 1 and 2, and DNoise. A coordinate n's hash index: (n + origin) & 0xFFF.\n";
    out << "constexpr std::int64_t kLatticeHashOrigin = " << lattice.origin << ";\n";
    out << "// R: a corner with index k reads R[k..k+11] (see noise.cpp).\n";
    write_table(out, "constexpr double kLatticeValues[267]", lattice.values, "%.6g", 8);
    out << "// Corner index k of hash indices (x, y, z): kLatticeHashZ[kLatticeHashY[kLatticeHashX[x] ^ y] ^ z].\n";
    std::array<int, 4096> z_table = lattice.hash_z;
    write_table(out, "constexpr std::uint16_t kLatticeHashX[4096]", lattice.hash_x, "%d", 16);
    write_table(out, "constexpr std::uint16_t kLatticeHashY[4096]", lattice.hash_y, "%d", 16);
    write_table(out, "constexpr std::uint8_t kLatticeHashZ[4096]", z_table, "%d", 16);
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "constexpr double kRangeCorrectedShift = %.17g;\n", range.shift);
    out << "// Generator 2: (sum + shift) * scale.\n" << buffer;
    std::snprintf(buffer, sizeof buffer, "constexpr double kRangeCorrectedScale = %.17g;\n\n", range.scale);
    out << buffer;
    out << "// Generator 3: cell of a coordinate: floor(coordinate + offset) & 2047; value at the corners.\n";
    std::snprintf(buffer, sizeof buffer, "constexpr double kSolidLatticeOffset = %.17g;\n", solid.offset);
    out << buffer;
    std::snprintf(buffer, sizeof buffer, "constexpr double kSolidNoiseMidpoint = %.17g;\n", solid.midpoint);
    out << buffer;
    out << "// Gradient of corner (x, y, z): kSolidGradients[(kSolidHashY[(kSolidHashX[x] + y) & 2047] + z) & 2047]\n"
           "// (already scaled to the noise's [0, 1] range).\n";
    write_table(out, "constexpr std::uint16_t kSolidHashX[2048]", solid.hash_x, "%d", 16);
    write_table(out, "constexpr std::uint16_t kSolidHashY[2048]", solid.hash_y, "%d", 16);
    std::array<double, 2048 * 3> flat{};
    for (int i = 0; i < 2048; ++i)
        for (int a = 0; a < 3; ++a) flat[i * 3 + a] = solid.gradients[i][a];
    write_table(out, "constexpr double kSolidGradients[2048 * 3]", flat, "%.17g", 3);
}

// Sample points: small, medium and large coordinates of either sign, and
// points on and next to lattice corners.
std::vector<Vec3> sample_points(int count, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::vector<Vec3> points;
    const double ranges[] = {4, 200, 1.2e4, 3e4};
    for (int i = 0; i < count; ++i) {
        const int kind = i % 10;
        Vec3 p;
        if (kind < 8) {
            std::uniform_real_distribution<double> c(-ranges[kind % 4], ranges[kind % 4]);
            p = {quantize(c(random)), quantize(c(random)), quantize(c(random))};
        } else {
            std::uniform_int_distribution<int> c(-10050, 10050);
            std::uniform_int_distribution<int> nudge(-3, 3);
            p = {double(c(random)), double(c(random)), double(c(random))};
            if (kind == 9)
                for (double& v : p) v += nudge(random) / 1048576.0;
        }
        points.push_back(p);
    }
    return points;
}

void write_samples(const std::string& dir) {
    char line[512];
    // Noise for each generator.
    for (int generator = 1; generator <= 3; ++generator) {
        const std::vector<Vec3> points = sample_points(1000, 100 + generator);
        std::vector<std::string> queries;
        for (const Vec3& p : points) queries.push_back(noise_query(p, generator));
        const std::vector<double> values = run_povray("", queries);
        std::ofstream out(dir + "/noise_generator" + std::to_string(generator) + ".txt");
        out << "# POV-Ray 3.7 f_noise_generator(x, y, z, " << generator
            << ") (= Noise()); x y z value. scripts/measure-pov-noise.sh\n";
        for (size_t i = 0; i < points.size(); ++i) {
            std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g\n", points[i][0], points[i][1], points[i][2],
                          values[i]);
            out << line;
        }
    }
    // f_noise3d uses the global noise_generator, 2 unless a scene sets it.
    {
        const std::vector<Vec3> points = sample_points(200, 99);
        std::vector<std::string> queries;
        for (const Vec3& p : points) {
            queries.push_back(
                write_number("f_noise3d(" + sdl_number(p[0]) + "," + sdl_number(p[1]) + "," + sdl_number(p[2]) + ")"));
            queries.push_back(noise_query(p, 2));
        }
        const std::vector<double> values = run_povray("", queries);
        int same = 0;
        for (size_t i = 0; i < values.size(); i += 2) same += values[i] == values[i + 1];
        std::printf("f_noise3d equals generator 2 at %d of %zu points\n", same, points.size());
    }
    // DTurbulence (vturbulence) for a few settings; one octave is DNoise.
    struct Setting {
        int octaves;
        double omega, lambda;
    };
    const Setting settings[] = {{1, 0.5, 2.0}, {6, 0.5, 2.0}, {3, 0.7, 2.5}, {10, 0.35, 1.7}};
    {
        std::ofstream out(dir + "/dturbulence.txt");
        out << "# POV-Ray 3.7 vturbulence(lambda, omega, octaves, <x, y, z>) (= DTurbulence(); octaves 1: DNoise());\n"
               "# octaves omega lambda x y z vx vy vz. scripts/measure-pov-noise.sh\n";
        int seed = 200;
        for (const Setting& s : settings) {
            const std::vector<Vec3> points = sample_points(s.octaves == 1 ? 1000 : 300, seed++);
            std::vector<std::string> queries;
            for (const Vec3& p : points) queries.push_back(dturbulence_query(p, s.lambda, s.omega, s.octaves));
            const std::vector<Vec3> values = triples(run_povray("", queries));
            for (size_t i = 0; i < points.size(); ++i) {
                std::snprintf(line, sizeof line, "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", s.octaves,
                              s.omega, s.lambda, points[i][0], points[i][1], points[i][2], values[i][0], values[i][1],
                              values[i][2]);
                out << line;
            }
        }
    }
    // Scalar Turbulence(), seen through marble: with classic turbulence t the
    // marble value is x + t * Turbulence(p). frequency 0 keeps POV from
    // folding it with fmod(value, 1.00001); POV still wraps negative values
    // into [0, 1), and ramp_wave leaves the rest. t = 0.01 pins Turbulence
    // to ~1e-10 whichever way the value came out.
    {
        std::ofstream out(dir + "/turbulence.txt");
        out << "# POV-Ray 3.7 Turbulence() from function { pattern { marble frequency 0 ramp_wave turbulence 0.01\n"
               "# ... } }: turbulence = (pattern - x) / 0.01, or (pattern - frac(x)) / 0.01 unwrapped to [-50, 50)\n"
               "# where x + 0.01 turbulence < 0; generator octaves omega lambda x y z turbulence.\n"
               "# scripts/measure-pov-noise.sh\n";
        int seed = 300;
        for (int generator = 1; generator <= 3; ++generator)
            for (const Setting& s : settings) {
                char declaration[256];
                std::snprintf(declaration, sizeof declaration,
                              "#declare M = function { pattern { marble frequency 0 ramp_wave turbulence 0.01 octaves "
                              "%d omega %.17g lambda %.17g noise_generator %d } }",
                              s.octaves, s.omega, s.lambda, generator);
                const std::vector<Vec3> points = sample_points(200, seed++);
                std::vector<std::string> queries;
                for (const Vec3& p : points)
                    queries.push_back(
                        write_number("M(" + sdl_number(p[0]) + "," + sdl_number(p[1]) + "," + sdl_number(p[2]) + ")"));
                const std::vector<double> values = run_povray(declaration, queries);
                for (size_t i = 0; i < points.size(); ++i) {
                    double t = (values[i] - points[i][0]) / 0.01;
                    if (std::fabs(t) >= 50) {
                        t = (values[i] - (points[i][0] - std::floor(points[i][0]))) / 0.01;
                        while (t >= 50) t -= 100;
                        while (t < -50) t += 100;
                    }
                    std::snprintf(line, sizeof line, "%d %d %.17g %.17g %.17g %.17g %.17g %.17g\n", generator,
                                  s.octaves, s.omega, s.lambda, points[i][0], points[i][1], points[i][2], t);
                    out << line;
                }
            }
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: measure_pov_noise WORK_DIR TABLES_INC SAMPLES_DIR\n");
        return 2;
    }
    g_work_dir = argv[1];
    const Lattice lattice = measure_lattice();
    const RangeCorrection range = measure_range_correction(lattice);
    const Solid solid = measure_solid();
    write_tables(argv[2], lattice, range, solid);
    write_samples(argv[3]);
    return 0;
}
