// POV-Ray's splines, `spline { [S] [linear_spline | quadratic_spline |
// cubic_spline | natural_spline] t1, v1, t2, v2, … }` called as S(t) or
// S(t, kind), evaluated as POV-Ray 3.7 evaluates them (its splines.cpp,
// read for the method): outside its times a spline holds its end values;
// quadratic fits a parabola through three neighbours; cubic_spline is
// Catmull-Rom (averaged slopes), defined from the second point to the
// next-to-last; natural_spline is the natural cubic (zero curvature at the
// ends).
#include <algorithm>
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

namespace {

using Entry = SplineData::Entry;

// The natural cubic's second derivatives at every entry, for component k.
std::vector<double> natural_curvatures(const std::vector<Entry>& e, int k) {
    const std::size_t n = e.size();
    std::vector<double> curvature(n, 0.0);
    if (n < 3) return curvature;
    std::vector<double> h(n - 1), slope(n - 1), diagonal(n - 1), rhs(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        h[i] = e[i + 1].t - e[i].t;
        slope[i] = (e[i + 1].v[k] - e[i].v[k]) / h[i];
    }
    // Tridiagonal elimination for the inner points, ends held at zero.
    diagonal[1] = 2.0 * (h[0] + h[1]);
    rhs[1] = 6.0 * (slope[1] - slope[0]);
    for (std::size_t i = 2; i + 1 < n; ++i) {
        diagonal[i] = 2.0 * (h[i] + h[i - 1]) - h[i - 1] * h[i - 1] / diagonal[i - 1];
        rhs[i] = 6.0 * (slope[i] - slope[i - 1]) - h[i - 1] * rhs[i - 1] / diagonal[i - 1];
    }
    for (std::size_t i = n - 2; i > 0; --i) curvature[i] = (rhs[i] - h[i] * curvature[i + 1]) / diagonal[i];
    return curvature;
}

double linear(const std::vector<Entry>& e, std::size_t i, int k, double t) {
    return e[i].v[k] + (t - e[i].t) * (e[i + 1].v[k] - e[i].v[k]) / (e[i + 1].t - e[i].t);
}

// The parabola through entries i-1, i, i+1 (Lagrange form).
double quadratic(const std::vector<Entry>& e, std::size_t i, int k, double t) {
    const double t0 = e[i - 1].t, t1 = e[i].t, t2 = e[i + 1].t;
    return e[i - 1].v[k] * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)) +
           e[i].v[k] * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)) +
           e[i + 1].v[k] * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
}

double catmull_rom(const std::vector<Entry>& e, std::size_t i, int k, double t) {
    const double span = e[i + 1].t - e[i].t;
    const double u = (t - e[i].t) / span;
    const auto slope = [&](std::size_t a) { return (e[a + 1].v[k] - e[a].v[k]) / (e[a + 1].t - e[a].t); };
    const double tangent0 = 0.5 * (slope(i - 1) + slope(i)) * span;
    const double tangent1 = 0.5 * (slope(i + 1) + slope(i)) * span;
    const double u2 = u * u, u3 = u2 * u;
    return e[i].v[k] * (2 * u3 - 3 * u2 + 1) + e[i + 1].v[k] * (3 * u2 - 2 * u3) + tangent0 * (u3 - 2 * u2 + u) +
           tangent1 * (u3 - u2);
}

double natural(const std::vector<Entry>& e, const std::vector<double>& c, std::size_t i, double t, int k) {
    const double h = e[i + 1].t - e[i].t, d = t - e[i].t;
    const double slope = (e[i + 1].v[k] - e[i].v[k]) / h - h * (c[i + 1] + 2.0 * c[i]) / 6.0;
    return e[i].v[k] + d * (slope + d * (c[i] / 2.0 + d * (c[i + 1] - c[i]) / (6.0 * h)));
}

}  // namespace

std::array<double, 5> spline_at(const SplineData& s, SplineData::Kind kind, double t) {
    const std::vector<Entry>& e = s.entries;
    const std::size_t last = e.size() - 1;
    if (last == 0) return e[0].v;
    // `end`: the first entry whose time is at or past t (last + 1 beyond).
    std::size_t end = std::size_t(
        std::lower_bound(e.begin(), e.end(), t, [](const Entry& a, double x) { return a.t < x; }) - e.begin());
    if (t >= e[last].t) end = last + 1;
    std::array<double, 5> v{};
    for (int k = 0; k < 5; ++k) {
        if (kind == SplineData::Kind::Cubic) {
            if (last == 1)
                v[k] = 0.5 * (e[0].v[k] + e[1].v[k]);
            else if (end < 2)
                v[k] = e[1].v[k];
            else if (end >= last)
                v[k] = e[last - 1].v[k];
            else
                v[k] = catmull_rom(e, end - 1, k, t);
            continue;
        }
        if (end == 0) {
            v[k] = e[0].v[k];
        } else if (end > last) {
            v[k] = e[last].v[k];
        } else if (kind == SplineData::Kind::Linear || (kind == SplineData::Kind::Quadratic && last == 1)) {
            v[k] = linear(e, end - 1, k, t);
        } else if (kind == SplineData::Kind::Quadratic) {
            v[k] = quadratic(e, end > 1 ? end - 1 : end, k, t);
        } else {
            v[k] = natural(e, natural_curvatures(e, k), end - 1, t, k);
        }
    }
    return v;
}

Value Evaluator::make_spline(const Value& base, const std::vector<int>& kinds, const std::vector<Value>& entries,
                             const sg::SourceLocation& at) {
    auto spline = base.spline() ? std::make_shared<SplineData>(*base.spline()) : std::make_shared<SplineData>();
    if (!kinds.empty()) spline->kind = SplineData::Kind(kinds.back());
    if (entries.size() % 2 != 0) {
        error(entries.back().location.file ? entries.back().location : at,
              "spline: each entry is a time and a value (t, <v>): the last time has no value");
    }
    for (std::size_t i = 0; i + 1 < entries.size(); i += 2) {
        const Value& time = entries[i];
        const Value& value = entries[i + 1];
        const sg::SourceLocation& where = time.location.file ? time.location : at;
        if (time.kind != Value::Kind::Float) {
            error(where, "spline: expected a float time, found " + describe(time));
            continue;
        }
        Entry entry;
        entry.t = time.v[0];
        int terms = 2;
        if (value.kind == Value::Kind::Float) {
            entry.v.fill(value.v[0]);
        } else if (value.kind == Value::Kind::Vector || value.kind == Value::Kind::Color) {
            terms = value.kind == Value::Kind::Color ? 5 : std::max(2, value.size);
            entry.v = value.v;
        } else {
            error(value.location.file ? value.location : where,
                  "spline: expected a float or vector value, found " + describe(value));
            continue;
        }
        double numbers[6] = {entry.t, entry.v[0], entry.v[1], entry.v[2], entry.v[3], entry.v[4]};
        if (!check_renderable(numbers, 6, SourceRange{where, where}, "a spline entry")) continue;
        spline->terms = std::max(spline->terms, terms);
        // POV: an entry at a time already there replaces it.
        auto place = std::lower_bound(spline->entries.begin(), spline->entries.end(), entry.t,
                                      [](const Entry& a, double x) { return a.t < x; });
        if (place != spline->entries.end() && place->t == entry.t)
            *place = entry;
        else
            spline->entries.insert(place, entry);
    }
    if (spline->entries.empty()) error(at, "spline: it needs at least one entry (t, <v>)");
    Value result;
    result.kind = Value::Kind::Spline;
    result.payload = std::move(spline);
    result.location = at;
    return result;
}

Value Evaluator::call_spline(const Value& spline, const Value& time, const SourceRange& where, int kind) {
    const double t = to_float(time, where, "a float time");
    if (!spline.spline() || spline.spline()->entries.empty()) return Value::number(0.0);
    const SplineData& s = *spline.spline();
    const std::array<double, 5> v = spline_at(s, kind >= 0 ? SplineData::Kind(kind) : s.kind, t);
    Value result;
    result.kind = Value::Kind::Vector;
    result.size = s.terms;
    result.v = v;
    return result;
}

}  // namespace lancer::parse
