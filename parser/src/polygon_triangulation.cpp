// Polygon triangulation in O(n log n): a fan for a verified convex polygon,
// otherwise a plane sweep that splits the polygon into y-monotone pieces
// (de Berg, Cheong, van Kreveld, Overmars, Computational Geometry, 3rd ed.,
// ch. 3) and the linear stack algorithm on each piece. Ties in y are broken
// by x, then by index (a symbolic rotation of the plane), so horizontal
// edges and equal heights need no special case. Every result is checked
// (n - 2 triangles whose areas add up to the polygon's); a polygon whose
// boundary crosses itself fails the check and becomes a fan.
#include "polygon_triangulation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

namespace lancer::parse {

namespace {

struct Point2 {
    double x, y;
    bool operator==(const Point2& o) const { return x == o.x && y == o.y; }
};

// Twice the signed area of (o, a, b): positive when it turns left.
double cross(const Point2& o, const Point2& a, const Point2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Triangulates a simple polygon given counterclockwise; fails (returns
// false) instead of looping or reading out of range on any other input.
class MonotoneTriangulator {
  public:
    explicit MonotoneTriangulator(const std::vector<Point2>& p) : m_p(p), m_n(static_cast<int>(p.size())) {}

    // Appends triangles (local indices, counterclockwise) and the sum of
    // their doubled areas.
    bool run(std::vector<std::array<int, 3>>& triangles, double& doubled_area) {
        m_triangles = &triangles;
        m_doubled_area = &doubled_area;
        return !crosses_itself() && sweep() && split_and_triangulate();
    }

  private:
    int next(int i) const { return i + 1 == m_n ? 0 : i + 1; }
    int prev(int i) const { return i == 0 ? m_n - 1 : i - 1; }

    // The sweep's order: higher first, then further left, then lower index.
    bool above(int a, int b) const {
        if (m_p[a].y != m_p[b].y) return m_p[a].y > m_p[b].y;
        if (m_p[a].x != m_p[b].x) return m_p[a].x < m_p[b].x;
        return a < b;
    }

    // x of edge e (between corners e and next(e)) on the sweep line through
    // the current event.
    double x_at(int e) const {
        const bool down = above(e, next(e));
        const Point2& u = m_p[down ? e : next(e)];
        const Point2& l = m_p[down ? next(e) : e];
        const Point2& s = m_p[m_event];
        if (u.y == l.y) return std::clamp(s.x, std::min(u.x, l.x), std::max(u.x, l.x));
        const double t = std::clamp((u.y - s.y) / (u.y - l.y), 0.0, 1.0);
        return u.x + t * (l.x - u.x);
    }

    struct Probe {
        double x;
    };
    // Orders the sweep's edges left to right at the current event.
    struct EdgeLess {
        using is_transparent = void;
        const MonotoneTriangulator* t;
        bool operator()(int a, int b) const {
            if (a == b) return false;
            const double xa = t->x_at(a), xb = t->x_at(b);
            if (xa != xb) return xa < xb;
            // Meeting at the sweep line: the one heading further left is left.
            const bool down_a = t->above(a, t->next(a)), down_b = t->above(b, t->next(b));
            const Point2& pa = t->m_p[down_a ? a : t->next(a)];
            const Point2& pb = t->m_p[down_b ? b : t->next(b)];
            const Point2& la = t->m_p[down_a ? t->next(a) : a];
            const Point2& lb = t->m_p[down_b ? t->next(b) : b];
            const double turn = (la.x - pa.x) * (lb.y - pb.y) - (la.y - pa.y) * (lb.x - pb.x);
            if (turn != 0.0) return turn > 0.0;
            return a < b;
        }
        bool operator()(int a, Probe b) const { return t->x_at(a) < b.x; }
        bool operator()(Probe a, int b) const { return a.x < t->x_at(b); }
    };
    using Status = std::set<int, EdgeLess>;

    bool insert_edge(int e) {
        auto [it, inserted] = m_status.insert(e);
        if (!inserted) return false;
        m_where[e] = it;
        m_in_status[e] = 1;
        m_helper[e] = e;
        return true;
    }
    bool erase_edge(int e) {
        if (!m_in_status[e]) return false;
        m_status.erase(m_where[e]);
        m_in_status[e] = 0;
        return true;
    }
    // The edge directly left of the current event, or -1.
    int left_edge() const {
        auto it = m_status.lower_bound(Probe{m_p[m_event].x});
        if (it == m_status.begin()) return -1;
        return *std::prev(it);
    }
    bool diagonal(int a, int b) {
        if (a == b || a == next(b) || b == next(a)) return false;
        m_diagonals.push_back({a, b});
        return true;
    }
    bool is_merge(int v) const { return m_merge[v] != 0; }

    std::vector<int> sweep_order() const {
        std::vector<int> order(m_n);
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [this](int a, int b) { return above(a, b); });
        return order;
    }

    // Whether edges e and f (not neighbours) cross at a point inside both.
    bool proper_crossing(int e, int f) const {
        if (e == f || next(e) == f || next(f) == e) return false;
        const Point2 &a = m_p[e], &b = m_p[next(e)], &c = m_p[f], &d = m_p[next(f)];
        const double o1 = cross(a, b, c), o2 = cross(a, b, d), o3 = cross(c, d, a), o4 = cross(c, d, b);
        return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
    }

    // Shamos and Hoey's sweep: two edges that cross are neighbours on the
    // sweep line just before the first crossing. (Edges that only touch are
    // left to the triangulation and its area check.)
    bool crosses_itself() {
        Status status{EdgeLess{this}};
        std::vector<Status::iterator> where(m_n, status.end());
        for (int v : sweep_order()) {
            m_event = v;
            const int edges[2] = {prev(v), v};  // the edges ending and starting at v
            for (int e : edges) {
                const int other = e == v ? next(v) : e;
                if (!above(other, v) || where[e] == status.end()) continue;
                auto it = where[e];
                auto after = std::next(it);
                if (it != status.begin() && after != status.end() && proper_crossing(*std::prev(it), *after))
                    return true;
                status.erase(it);
                where[e] = status.end();
            }
            for (int e : edges) {
                const int other = e == v ? next(v) : e;
                if (above(other, v)) continue;
                auto [it, inserted] = status.insert(e);
                if (!inserted) return true;
                where[e] = it;
                if (it != status.begin() && proper_crossing(*std::prev(it), e)) return true;
                if (std::next(it) != status.end() && proper_crossing(e, *std::next(it))) return true;
            }
        }
        return false;
    }

    // Adds the diagonals that split the polygon into y-monotone pieces.
    bool sweep() {
        const std::vector<int> order = sweep_order();
        m_merge.assign(m_n, 0);
        for (int v = 0; v < m_n; ++v)
            m_merge[v] = above(prev(v), v) && above(next(v), v) && cross(m_p[prev(v)], m_p[v], m_p[next(v)]) <= 0.0;
        m_helper.assign(m_n, -1);
        m_in_status.assign(m_n, 0);
        m_where.assign(m_n, m_status.end());
        for (int v : order) {
            m_event = v;
            const int a = prev(v), b = next(v);
            const bool a_below = above(v, a), b_below = above(v, b);
            const bool convex = cross(m_p[a], m_p[v], m_p[b]) > 0.0;
            if (a_below && b_below) {
                if (!convex) {  // split: joins the helper of the edge to its left
                    const int e = left_edge();
                    if (e < 0 || !diagonal(v, m_helper[e])) return false;
                    m_helper[e] = v;
                }
                if (!insert_edge(v)) return false;  // start or split
            } else if (!a_below && !b_below) {
                if (!m_in_status[a]) return false;  // end or merge: the edge from a ends here
                if (is_merge(m_helper[a]) && !diagonal(v, m_helper[a])) return false;
                erase_edge(a);
                if (!convex) {  // merge
                    const int e = left_edge();
                    if (e < 0) return false;
                    if (is_merge(m_helper[e]) && !diagonal(v, m_helper[e])) return false;
                    m_helper[e] = v;
                }
            } else if (!a_below) {  // regular, on a left chain: the interior lies to its right
                if (!m_in_status[a]) return false;
                if (is_merge(m_helper[a]) && !diagonal(v, m_helper[a])) return false;
                erase_edge(a);
                if (!insert_edge(v)) return false;
            } else {  // regular, on a right chain
                const int e = left_edge();
                if (e < 0) return false;
                if (is_merge(m_helper[e]) && !diagonal(v, m_helper[e])) return false;
                m_helper[e] = v;
            }
        }
        return true;
    }

    // Walks the pieces the diagonals cut (half-edges sorted by angle around
    // each corner) and triangulates each.
    bool split_and_triangulate() {
        const int edges = m_n + static_cast<int>(m_diagonals.size());
        const int half_edges = 2 * edges;
        std::vector<int> origin(half_edges);
        for (int i = 0; i < m_n; ++i) {
            origin[2 * i] = i;
            origin[2 * i + 1] = next(i);
        }
        for (size_t k = 0; k < m_diagonals.size(); ++k) {
            origin[2 * (m_n + k)] = m_diagonals[k][0];
            origin[2 * (m_n + k) + 1] = m_diagonals[k][1];
        }
        auto destination = [&](int h) { return origin[h ^ 1]; };
        // Outgoing half-edges of each corner, counterclockwise.
        std::vector<int> first(m_n + 1, 0);
        for (int h = 0; h < half_edges; ++h) ++first[origin[h] + 1];
        for (int v = 0; v < m_n; ++v) first[v + 1] += first[v];
        std::vector<int> outgoing(half_edges);
        std::vector<double> angle(half_edges);
        {
            std::vector<int> fill(first.begin(), first.end() - 1);
            for (int h = 0; h < half_edges; ++h) {
                outgoing[fill[origin[h]]++] = h;
                const Point2& o = m_p[origin[h]];
                const Point2& d = m_p[destination(h)];
                angle[h] = std::atan2(d.y - o.y, d.x - o.x);
            }
        }
        std::vector<int> next_half(half_edges, -1);
        for (int v = 0; v < m_n; ++v) {
            auto begin = outgoing.begin() + first[v], end = outgoing.begin() + first[v + 1];
            std::sort(begin, end, [&](int a, int b) { return angle[a] != angle[b] ? angle[a] < angle[b] : a < b; });
            const int degree = first[v + 1] - first[v];
            // Arriving along the twin of outgoing j, the piece on the left
            // continues along the outgoing edge just clockwise of it.
            for (int j = 0; j < degree; ++j) next_half[begin[j] ^ 1] = begin[j == 0 ? degree - 1 : j - 1];
        }
        std::vector<char> visited(half_edges, 0);
        std::vector<int> piece;
        for (int h = 0; h < half_edges; ++h) {
            const bool outside = h < 2 * m_n && (h & 1);
            if (outside || visited[h]) continue;
            piece.clear();
            int current = h;
            do {
                if (visited[current] || (current < 2 * m_n && (current & 1))) return false;
                visited[current] = 1;
                piece.push_back(origin[current]);
                current = next_half[current];
                if (piece.size() > static_cast<size_t>(m_n)) return false;
            } while (current != h);
            if (!triangulate_monotone(piece)) return false;
        }
        return true;
    }

    void emit(int a, int b, int c) {
        double doubled = cross(m_p[a], m_p[b], m_p[c]);
        if (doubled < 0.0) {
            std::swap(b, c);
            doubled = -doubled;
        }
        *m_doubled_area += doubled;
        m_triangles->push_back({a, b, c});
    }

    // The stack algorithm on one y-monotone piece given counterclockwise.
    bool triangulate_monotone(const std::vector<int>& piece) {
        const int k = static_cast<int>(piece.size());
        if (k < 3) return false;
        if (k == 3) {
            emit(piece[0], piece[1], piece[2]);
            return true;
        }
        int top = 0, bottom = 0;
        for (int i = 1; i < k; ++i) {
            if (above(piece[i], piece[top])) top = i;
            if (above(piece[bottom], piece[i])) bottom = i;
        }
        // Counterclockwise from the top runs down the left chain; the right
        // chain is the rest, backwards. Both must descend.
        std::vector<int> left, right;
        for (int i = (top + 1) % k; i != bottom; i = (i + 1) % k) left.push_back(piece[i]);
        for (int i = (top + k - 1) % k; i != bottom; i = (i + k - 1) % k) right.push_back(piece[i]);
        std::vector<int> sequence{piece[top]};
        std::vector<char> on_left{1};
        for (size_t i = 1; i < left.size(); ++i)
            if (!above(left[i - 1], left[i])) return false;
        for (size_t i = 1; i < right.size(); ++i)
            if (!above(right[i - 1], right[i])) return false;
        for (size_t l = 0, r = 0; l < left.size() || r < right.size();) {
            const bool take_left = r == right.size() || (l < left.size() && above(left[l], right[r]));
            sequence.push_back(take_left ? left[l++] : right[r++]);
            on_left.push_back(take_left);
        }
        sequence.push_back(piece[bottom]);
        on_left.push_back(0);

        std::vector<int> stack{0, 1};  // positions in sequence
        for (int j = 2; j < k - 1; ++j) {
            const int u = sequence[j];
            if (on_left[j] != on_left[stack.back()]) {
                for (size_t t = stack.size() - 1; t >= 1; --t) emit(u, sequence[stack[t]], sequence[stack[t - 1]]);
                stack = {j - 1, j};
            } else {
                int popped = stack.back();
                stack.pop_back();
                while (!stack.empty()) {
                    const Point2& pu = m_p[u];
                    const Point2& pl = m_p[sequence[popped]];
                    const Point2& pt = m_p[sequence[stack.back()]];
                    const bool inside = on_left[j] ? cross(pt, pl, pu) > 0.0 : cross(pu, pl, pt) > 0.0;
                    if (!inside) break;
                    emit(u, sequence[popped], sequence[stack.back()]);
                    popped = stack.back();
                    stack.pop_back();
                }
                stack.push_back(popped);
                stack.push_back(j);
            }
        }
        const int u = sequence[k - 1];
        for (size_t t = stack.size() - 1; t >= 1; --t) emit(u, sequence[stack[t]], sequence[stack[t - 1]]);
        return true;
    }

    const std::vector<Point2>& m_p;
    const int m_n;
    int m_event = 0;
    Status m_status{EdgeLess{this}};
    std::vector<Status::iterator> m_where;
    std::vector<char> m_in_status, m_merge;
    std::vector<int> m_helper;
    std::vector<std::array<int, 2>> m_diagonals;
    std::vector<std::array<int, 3>>* m_triangles = nullptr;
    double* m_doubled_area = nullptr;
};

}  // namespace

PolygonTriangulation triangulate_polygon(const std::vector<sg::Vec3>& points) {
    PolygonTriangulation result;
    const size_t n = points.size();
    if (n < 3) return result;

    // The plane: Newell's normal (twice the vector area), about the first
    // corner so that far-away faces keep their precision.
    const sg::Vec3 origin = points[0];
    sg::Vec3 normal(0.0);
    for (size_t i = 0; i < n; ++i) normal += glm::cross(points[i] - origin, points[i + 1 == n ? 0 : i + 1] - origin);
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length)) return result;
    const sg::Vec3 w = normal / length;
    const sg::Vec3 u = glm::normalize(glm::cross(w, std::abs(w.x) > 0.9 ? sg::Vec3(0, 1, 0) : sg::Vec3(1, 0, 0)));
    const sg::Vec3 v = glm::cross(w, u);  // u x v = w: the polygon runs counterclockwise in (u, v)

    // Corners in the plane, without repeats.
    std::vector<Point2> p;
    std::vector<std::uint32_t> kept;
    p.reserve(n);
    kept.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const sg::Vec3 d = points[i] - origin;
        const Point2 q{glm::dot(d, u), glm::dot(d, v)};
        if (!p.empty() && p.back() == q) continue;
        p.push_back(q);
        kept.push_back(static_cast<std::uint32_t>(i));
    }
    while (p.size() > 1 && p.back() == p.front()) {
        p.pop_back();
        kept.pop_back();
    }
    const int m = static_cast<int>(p.size());
    if (m < 3) return result;
    double doubled_area = 0.0;
    for (int i = 0; i < m; ++i) doubled_area += cross(p[0], p[i], p[(i + 1) % m]);
    if (!(doubled_area > 0.0)) return result;

    auto fan = [&](PolygonTriangulation::Kind kind) {
        result.kind = kind;
        result.triangles.clear();
        for (int i = 1; i + 1 < m; ++i) result.triangles.push_back({kept[0], kept[i], kept[i + 1]});
        return result;
    };

    // Convex: every turn to the left, and the boundary goes down once and
    // up once (a pentagram turns left everywhere but goes down twice).
    auto above = [&](int a, int b) {
        if (p[a].y != p[b].y) return p[a].y > p[b].y;
        if (p[a].x != p[b].x) return p[a].x < p[b].x;
        return a < b;
    };
    bool left_turns = true;
    int reversals = 0;
    for (int i = 0; i < m; ++i) {
        const int a = i == 0 ? m - 1 : i - 1, b = i + 1 == m ? 0 : i + 1;
        if (cross(p[a], p[i], p[b]) < 0.0) left_turns = false;
        if (above(a, i) != above(i, b)) ++reversals;
    }
    if (left_turns && reversals == 2) {
        if (m == 4) {
            // tinyobjloader's split of a quad: along the shorter diagonal.
            result.kind = PolygonTriangulation::Kind::Convex;
            const auto& a = points[kept[0]];
            const auto& b = points[kept[1]];
            const auto& c = points[kept[2]];
            const auto& d = points[kept[3]];
            if (glm::dot(c - a, c - a) < glm::dot(d - b, d - b))
                result.triangles = {{kept[0], kept[1], kept[2]}, {kept[0], kept[2], kept[3]}};
            else
                result.triangles = {{kept[0], kept[1], kept[3]}, {kept[1], kept[2], kept[3]}};
            return result;
        }
        return fan(PolygonTriangulation::Kind::Convex);
    }

    std::vector<std::array<int, 3>> local;
    local.reserve(m - 2);
    double covered = 0.0;
    MonotoneTriangulator triangulator(p);
    const bool ok = triangulator.run(local, covered);
    // A simple polygon's triangles cover it once: n - 2 of them, adding up
    // to its area. A boundary that crosses itself shows here.
    if (!ok || static_cast<int>(local.size()) != m - 2 || std::abs(covered - doubled_area) > 1e-6 * doubled_area)
        return fan(PolygonTriangulation::Kind::NotSimple);
    result.kind = PolygonTriangulation::Kind::General;
    result.triangles.reserve(local.size());
    for (const auto& t : local) result.triangles.push_back({kept[t[0]], kept[t[1]], kept[t[2]]});
    return result;
}

}  // namespace lancer::parse
