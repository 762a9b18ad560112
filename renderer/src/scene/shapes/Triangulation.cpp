#include "scene/shapes/Triangulation.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace bxdflab {
namespace {

/// Positions in the polygon's plane, in double precision: neighbouring
/// vertices of a large face are so close that float areas lose their sign.
using Point2 = glm::dvec2;

/// Twice the signed area of triangle abc (positive when counter-clockwise).
double area2(Point2 const& a, Point2 const& b, Point2 const& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// A vertex of the loop being cut: a doubly linked ring over positions.
struct Node {
    int index;   ///< into the caller's points
    Point2 p;
    int prev = -1, next = -1;
    bool removed = false;
};

class EarCutter {
public:
    EarCutter(std::vector<Node> nodes, int start) : m_nodes(std::move(nodes)), m_start(start) {}

    void cut(std::vector<int>& triangles) {
        int remaining = count();
        buildGrid();
        int current = m_start, stalled = 0;
        while (remaining > 3) {
            Node& b = m_nodes[static_cast<size_t>(current)];
            int a = b.prev, c = b.next;
            if (isEar(a, current, c) || stalled > remaining) {
                // After a full turn without an ear (a self-intersecting or degenerate
                // loop) the next convex-or-not corner is cut anyway: a best effort.
                triangles.insert(triangles.end(), {m_nodes[static_cast<size_t>(a)].index, b.index,
                                                   m_nodes[static_cast<size_t>(c)].index});
                unlink(current);
                --remaining;
                stalled = 0;
                // Skip a vertex: cutting ear after ear around one corner makes a fan of
                // ever longer triangles, whose boxes cover ever more of the grid.
                current = m_nodes[static_cast<size_t>(c)].next;
                continue;
            }
            current = c;
            ++stalled;
        }
        if (remaining == 3) {
            Node const& b = m_nodes[static_cast<size_t>(current)];
            triangles.insert(triangles.end(), {m_nodes[static_cast<size_t>(b.prev)].index, b.index,
                                               m_nodes[static_cast<size_t>(b.next)].index});
        }
    }

private:
    int count() const {
        int n = 0, i = m_start;
        do {
            ++n;
            i = m_nodes[static_cast<size_t>(i)].next;
        } while (i != m_start);
        return n;
    }
    Point2 at(int i) const { return m_nodes[static_cast<size_t>(i)].p; }
    bool reflex(int i) const {
        Node const& n = m_nodes[static_cast<size_t>(i)];
        return area2(at(n.prev), at(i), at(n.next)) <= 0.0;
    }

    void buildGrid() {
        Point2 lo(1e300), hi(-1e300);
        int n = 0, i = m_start;
        do {
            lo = glm::min(lo, at(i));
            hi = glm::max(hi, at(i));
            ++n;
            i = m_nodes[static_cast<size_t>(i)].next;
        } while (i != m_start);
        m_lo = lo;
        m_cells = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
        Point2 extent = glm::max(hi - lo, Point2(1e-300));
        m_cellSize = extent / static_cast<double>(m_cells);
        do {
            if (reflex(i)) m_grid[cellKey(cellOf(at(i)))].push_back(i);
            i = m_nodes[static_cast<size_t>(i)].next;
        } while (i != m_start);
    }
    glm::ivec2 cellOf(Point2 const& p) const {
        glm::ivec2 c((p - m_lo) / m_cellSize);
        return glm::clamp(c, glm::ivec2(0), glm::ivec2(m_cells - 1));
    }
    long cellKey(glm::ivec2 c) const { return static_cast<long>(c.y) * m_cells + c.x; }

    /// abc is convex and no reflex vertex of the loop lies inside it.
    bool isEar(int a, int b, int c) const {
        Point2 pa = at(a), pb = at(b), pc = at(c);
        if (area2(pa, pb, pc) <= 0.0) return false;
        glm::ivec2 c0 = cellOf(glm::min(pa, glm::min(pb, pc))), c1 = cellOf(glm::max(pa, glm::max(pb, pc)));
        for (int y = c0.y; y <= c1.y; ++y)
            for (int x = c0.x; x <= c1.x; ++x) {
                auto found = m_grid.find(cellKey({x, y}));
                if (found == m_grid.end()) continue;
                for (int other : found->second) {
                    Node const& o = m_nodes[static_cast<size_t>(other)];
                    if (o.removed || other == a || other == b || other == c) continue;
                    if (o.p == pa || o.p == pb || o.p == pc) continue;  // a bridge's twin vertex
                    if (area2(pa, pb, o.p) >= 0.0 && area2(pb, pc, o.p) >= 0.0 && area2(pc, pa, o.p) >= 0.0 &&
                        reflex(other))
                        return false;
                }
            }
        return true;
    }

    void unlink(int i) {
        Node& n = m_nodes[static_cast<size_t>(i)];
        m_nodes[static_cast<size_t>(n.prev)].next = n.next;
        m_nodes[static_cast<size_t>(n.next)].prev = n.prev;
        n.removed = true;
        if (i == m_start) m_start = n.next;
    }

    std::vector<Node> m_nodes;
    int m_start;
    Point2 m_lo{0.0}, m_cellSize{1.0};
    int m_cells = 1;
    std::unordered_map<long, std::vector<int>> m_grid;  ///< reflex vertices by cell
};

/// Appends a loop as a ring of nodes (wound as `counterClockwise` asks); returns one of its nodes.
int addRing(std::vector<Node>& nodes, std::vector<Point2> const& flat, std::vector<int> const& loop, bool counterClockwise) {
    double area = 0.0;
    for (size_t k = 0; k < loop.size(); ++k) {
        Point2 const& a = flat[static_cast<size_t>(loop[k])];
        Point2 const& b = flat[static_cast<size_t>(loop[(k + 1) % loop.size()])];
        area += a.x * b.y - b.x * a.y;
    }
    std::vector<int> order = loop;
    if ((area > 0.0) != counterClockwise) std::reverse(order.begin(), order.end());
    int first = static_cast<int>(nodes.size());
    for (size_t k = 0; k < order.size(); ++k) {
        Node n;
        n.index = order[k];
        n.p = flat[static_cast<size_t>(order[k])];
        n.prev = first + static_cast<int>((k + order.size() - 1) % order.size());
        n.next = first + static_cast<int>((k + 1) % order.size());
        nodes.push_back(n);
    }
    return first;
}

/// Joins a hole (clockwise ring starting anywhere) to the outer ring: a bridge
/// from the hole's rightmost vertex to an outer vertex it can see, walked both ways.
void bridgeHole(std::vector<Node>& nodes, int outer, int hole) {
    // The hole's rightmost vertex.
    int h = hole, best = hole;
    do {
        if (nodes[static_cast<size_t>(h)].p.x > nodes[static_cast<size_t>(best)].p.x) best = h;
        h = nodes[static_cast<size_t>(h)].next;
    } while (h != hole);
    Point2 const m = nodes[static_cast<size_t>(best)].p;
    // Cast a ray to the right: the nearest edge it crosses, then that edge's vertex
    // farther right, or a reflex vertex inside the triangle it spans that sees m best.
    int candidate = -1;
    double nearestX = 1e300;
    int i = outer;
    do {
        Node const& a = nodes[static_cast<size_t>(i)];
        Node const& b = nodes[static_cast<size_t>(a.next)];
        if ((a.p.y <= m.y && b.p.y >= m.y) || (b.p.y <= m.y && a.p.y >= m.y)) {
            double x = a.p.y == b.p.y ? std::max(a.p.x, b.p.x) : a.p.x + (m.y - a.p.y) * (b.p.x - a.p.x) / (b.p.y - a.p.y);
            if (x >= m.x && x < nearestX) {
                nearestX = x;
                candidate = a.p.x > b.p.x ? i : a.next;
            }
        }
        i = a.next;
    } while (i != outer);
    if (candidate < 0) candidate = outer;  // degenerate input: any vertex keeps the result one loop
    // Prefer a vertex inside triangle (m, ray hit, candidate) that is closest in angle to the ray.
    Point2 hit(nearestX, m.y), cp = nodes[static_cast<size_t>(candidate)].p;
    double bestTan = 1e300;
    i = outer;
    do {
        Point2 p = nodes[static_cast<size_t>(i)].p;
        if (i != candidate && p.x >= m.x && p.x <= hit.x) {
            bool inside = std::fabs(area2(m, hit, cp)) > 0.0 && area2(m, hit, p) * area2(m, hit, cp) >= 0.0 &&
                          area2(hit, cp, p) * area2(hit, cp, m) >= 0.0 && area2(cp, m, p) * area2(cp, m, hit) >= 0.0;
            if (inside) {
                double tan = std::fabs(m.y - p.y) / std::max(p.x - m.x, 1e-300);
                if (tan < bestTan) {
                    bestTan = tan;
                    candidate = i;
                }
            }
        }
        i = nodes[static_cast<size_t>(i)].next;
    } while (i != outer);
    // Split: outer ... candidate -> best ... (around the hole) ... best' -> candidate' ... outer.
    int a = candidate, b = best;
    Node a2 = nodes[static_cast<size_t>(a)], b2 = nodes[static_cast<size_t>(b)];
    int ia2 = static_cast<int>(nodes.size()), ib2 = ia2 + 1;
    int an = nodes[static_cast<size_t>(a)].next, bp = nodes[static_cast<size_t>(b)].prev;
    nodes[static_cast<size_t>(a)].next = b;
    nodes[static_cast<size_t>(b)].prev = a;
    a2.next = an;
    a2.prev = ib2;
    b2.next = ia2;
    b2.prev = bp;
    nodes.push_back(a2);
    nodes.push_back(b2);
    nodes[static_cast<size_t>(an)].prev = ia2;
    nodes[static_cast<size_t>(bp)].next = ib2;
}

}  // namespace

std::vector<int> triangulatePolygon(std::vector<Vec3> const& points, std::vector<std::vector<int>> const& loops) {
    std::vector<int> triangles;
    if (loops.empty() || loops[0].size() < 3) return triangles;
    // Newell's normal of the outer loop picks the plane to work in.
    Vec3 normal(0.0f);
    std::vector<int> const& outer = loops[0];
    for (size_t k = 0; k < outer.size(); ++k) {
        Vec3 const& a = points[static_cast<size_t>(outer[k])];
        Vec3 const& b = points[static_cast<size_t>(outer[(k + 1) % outer.size()])];
        normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    int axis = std::fabs(normal.x) > std::fabs(normal.y) ? (std::fabs(normal.x) > std::fabs(normal.z) ? 0 : 2)
                                                         : (std::fabs(normal.y) > std::fabs(normal.z) ? 1 : 2);
    int ax = (axis + 1) % 3, ay = (axis + 2) % 3;
    float orientation = normal[axis] >= 0.0f ? 1.0f : -1.0f;
    std::vector<Point2> flat(points.size());
    for (size_t i = 0; i < points.size(); ++i) flat[i] = Point2(points[i][ax], orientation * points[i][ay]);

    // In this plane the outer loop runs counter-clockwise; holes clockwise.
    std::vector<Node> nodes;
    int start = addRing(nodes, flat, outer, true);
    std::vector<int> holes;
    for (size_t h = 1; h < loops.size(); ++h)
        if (loops[h].size() >= 3) holes.push_back(addRing(nodes, flat, loops[h], false));
    // Bridge the holes from the one reaching farthest right, so later bridges cannot cross earlier ones.
    auto rightmost = [&](int ring) {
        double x = -1e300;
        int i = ring;
        do {
            x = std::max(x, nodes[static_cast<size_t>(i)].p.x);
            i = nodes[static_cast<size_t>(i)].next;
        } while (i != ring);
        return x;
    };
    std::sort(holes.begin(), holes.end(), [&](int a, int b) { return rightmost(a) > rightmost(b); });
    for (int hole : holes) bridgeHole(nodes, start, hole);
    EarCutter(std::move(nodes), start).cut(triangles);
    return triangles;
}

}  // namespace bxdflab
