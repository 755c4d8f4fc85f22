// SPDX-License-Identifier: MIT
// The incremental Voronoi methods' graph (voronoi_incremental_graph.hpp): the initial graph G3
// of the three auxiliary generators (000 §3.6.1, Fig. 3), nearest-generator location, the
// in-circle tests with optional fault injection, Sugihara and Iri's H, and procedure A.
#include "methods/detail/voronoi_incremental_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/geom/constructions.hpp"
#include "methods/detail/free_storage.hpp"

namespace dtm::methods::detail {
namespace {

using HalfEdge = VoronoiDiagram::HalfEdge;

/// Position of cell (x, y) along a Hilbert curve over a 2^16 x 2^16 grid.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
    constexpr std::uint32_t n = 1u << 16;
    std::uint64_t d = 0;
    for (std::uint32_t s = n / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (x & s) ? 1 : 0;
        const std::uint32_t ry = (y & s) ? 1 : 0;
        d += std::uint64_t{s} * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = n - 1 - x;
                y = n - 1 - y;
            }
            std::swap(x, y);
        }
    }
    return d;
}

/// The binary exponent of the unit in the last place of v (v != 0).
int ulp_exponent(double v) {
    int e = 0;
    (void)std::frexp(v, &e);
    return e - 53;
}

}  // namespace

IncrementalVoronoi::IncrementalVoronoi(Sites& sites, CountingPredicates& predicates)
    : sites_(sites), pred_(predicates), real_(sites.real) {
    Box2 box;
    int e0 = std::numeric_limits<int>::max();
    for (std::uint32_t i = 0; i < real_; ++i) {
        const Point2& p = sites.xy[i];
        box.add(p);
        if (p.x != 0.0) e0 = std::min(e0, ulp_exponent(p.x));
        if (p.y != 0.0) e0 = std::min(e0, ulp_exponent(p.y));
    }
    const double span = std::max(box.xmax - box.xmin, box.ymax - box.ymin);
    int s = 0;
    (void)std::frexp(span, &s);  // span < 2^s
    const long long exponent = 4LL * s - 2LL * e0 + 6;
    if (exponent > 1000) {
        throw InputError("the coordinates span too many binary orders of magnitude (2^" +
                         std::to_string(s) + " against units of 2^" + std::to_string(e0) +
                         ") to place the auxiliary generators of the incremental Voronoi methods");
    }
    const double d = std::ldexp(1.0, static_cast<int>(std::max<long long>(exponent, s + 4)));
    const double cx = 0.5 * (box.xmin + box.xmax);
    const double cy = 0.5 * (box.ymin + box.ymax);
    sites.xy.push_back({cx, cy + d});      // A1, top
    sites.xy.push_back({cx - d, cy - d});  // A2, bottom left
    sites.xy.push_back({cx + d, cy - d});  // A3, bottom right
    face_edge_.assign(real_ + 4, no_index);
    incident_.assign(real_ + 4, 0);
    region_stamp_.assign(real_ + 4, 0);
    he_.reserve(6 * std::size_t{real_} + 32);
    vout_.reserve(2 * std::size_t{real_} + 8);
    start_graph();
}

void IncrementalVoronoi::start_graph() {
    // G3: the centre c of A1 A2 A3, the ends q12, q23, q31 of its three rays on the curve.
    const std::uint32_t a1 = real_, a2 = real_ + 1, a3 = real_ + 2, omega = real_ + 3;
    const std::uint32_t c = new_vertex(), q12 = new_vertex(), q23 = new_vertex(),
                        q31 = new_vertex();
    const std::uint32_t r12 = new_edge(), r23 = new_edge(), r31 = new_edge();
    const std::uint32_t k1 = new_edge(), k2 = new_edge(), k3 = new_edge();
    const auto set = [&](std::uint32_t h, std::uint32_t o, std::uint32_t f, std::uint32_t n) {
        he_[h] = {o, n, f};
        vout_[o] = h;
    };
    // Face A1 (top): c -> q31 -> q12 -> c.
    set(r31, c, a1, k1);
    set(k1, q31, a1, r12 ^ 1u);
    set(r12 ^ 1u, q12, a1, r31);
    // Face A2 (bottom left): c -> q12 -> q23 -> c.
    set(r12, c, a2, k2);
    set(k2, q12, a2, r23 ^ 1u);
    set(r23 ^ 1u, q23, a2, r12);
    // Face A3 (bottom right): c -> q23 -> q31 -> c.
    set(r23, c, a3, k3);
    set(k3, q23, a3, r31 ^ 1u);
    set(r31 ^ 1u, q31, a3, r23);
    // The outer face: q12 -> q31 -> q23 -> q12.
    set(k1 ^ 1u, q12, omega, k3 ^ 1u);
    set(k3 ^ 1u, q31, omega, k2 ^ 1u);
    set(k2 ^ 1u, q23, omega, k1 ^ 1u);
    face_edge_[a1] = r31;
    face_edge_[a2] = r12;
    face_edge_[a3] = r23;
    face_edge_[omega] = k1 ^ 1u;
    label_.assign(vout_.size(), Label::unknown);
}

void IncrementalVoronoi::set_faults(double probability, std::uint64_t seed) {
    fault_probability_ = probability;
    fault_rng_.seed(seed);
}

std::vector<std::uint32_t> IncrementalVoronoi::insertion_order() const {
    Box2 box;
    for (std::uint32_t i = 0; i < real_; ++i) box.add(sites_.xy[i]);
    const double w = std::max(box.xmax - box.xmin, 1e-300);
    const double h = std::max(box.ymax - box.ymin, 1e-300);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(real_);
    for (std::uint32_t i = 0; i < real_; ++i) {
        const auto cell = [](double t) {
            return static_cast<std::uint32_t>(std::clamp(t, 0.0, 1.0) * 65535.0);
        };
        keys[i] = {hilbert_index(cell((sites_.xy[i].x - box.xmin) / w),
                                 cell((sites_.xy[i].y - box.ymin) / h)),
                   i};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<std::uint32_t> order(real_);
    for (std::uint32_t i = 0; i < real_; ++i) order[i] = keys[i].second;
    return order;
}

std::uint32_t IncrementalVoronoi::new_edge() {
    if (!free_edges_.empty()) {
        const std::uint32_t e = free_edges_.back();
        free_edges_.pop_back();
        return e;
    }
    he_.resize(he_.size() + 2);
    return static_cast<std::uint32_t>(he_.size() - 2);
}

std::uint32_t IncrementalVoronoi::new_vertex() {
    if (!free_vertices_.empty()) {
        const std::uint32_t v = free_vertices_.back();
        free_vertices_.pop_back();
        return v;
    }
    vout_.push_back(no_index);
    label_.push_back(Label::unknown);
    return static_cast<std::uint32_t>(vout_.size() - 1);
}

bool IncrementalVoronoi::on_curve(std::uint32_t v) const {
    const std::uint32_t h = vout_[v];
    const std::uint32_t omega = outer_face();
    return face(h) == omega || face(cw(h)) == omega || face(ccw(h)) == omega;
}

void IncrementalVoronoi::generators(std::uint32_t v, std::uint32_t g[3]) const {
    const std::uint32_t h = vout_[v];
    g[0] = face(h);
    g[1] = face(ccw(h));
    g[2] = face(cw(h));
}

std::uint32_t IncrementalVoronoi::nearest(const Point2& p) {
    if (last_ == no_index) return no_index;
    std::uint32_t g = last_;
    for (bool moved = true; moved;) {
        moved = false;
        const std::uint32_t start = face_edge_[g];
        std::uint32_t h = start;
        do {
            const std::uint32_t q = face(h ^ 1u);
            if (q < real_ && pred_.compare_distances(p, sites_.xy[q], p, sites_.xy[g]) < 0) {
                g = q;
                moved = true;
                ++walk_steps_;
                break;
            }
            h = next(h);
        } while (h != start);
    }
    return g;
}

int IncrementalVoronoi::inside(std::uint32_t v, const Point2& p) {
    if (on_curve(v)) return -1;
    std::uint32_t g[3];
    generators(v, g);
    int s = pred_.incircle(sites_.xy[g[0]], sites_.xy[g[1]], sites_.xy[g[2]], p);
    if (fault_probability_ > 0.0 &&
        std::uniform_real_distribution<double>(0.0, 1.0)(fault_rng_) < fault_probability_) {
        ++faults_;
        s = s != 0 ? -s : (fault_rng_() & 1u ? 1 : -1);
    }
    return s;
}

double IncrementalVoronoi::h_value(std::uint32_t v, const Point2& p) const {
    if (on_curve(v)) return std::numeric_limits<double>::infinity();
    std::uint32_t g[3];
    generators(v, g);
    return sugihara_iri_h(sites_.xy[g[0]], sites_.xy[g[1]], sites_.xy[g[2]], p);
}

double sugihara_iri_h(const Point2& a, const Point2& b, const Point2& c, const Point2& p) noexcept {
    const Point2* g[3] = {&a, &b, &c};
    const int k = geom::nearest_right_angle(a, b, c);
    // (i, j, k) keeps the counter-clockwise order: i and j follow k.
    const Point2& pk = *g[k];
    const Point2& pi = *g[(k + 1) % 3];
    const Point2& pj = *g[(k + 2) % 3];
    const double xi = pi.x - pk.x, yi = pi.y - pk.y, xj = pj.x - pk.x, yj = pj.y - pk.y;
    const double wi = 0.5 * (xi * xi + yi * yi), wj = 0.5 * (xj * xj + yj * yj);
    const double j2 = yi * wj - wi * yj;  // eq. 8
    const double j3 = xi * wj - wi * xj;  // eq. 9
    const double j4 = xi * yj - yi * xj;  // eq. 10
    const double xl = p.x - pk.x, yl = p.y - pk.y;
    return j2 * xl - j3 * yl + 0.5 * j4 * (xl * xl + yl * yl);  // eq. 7
}

void IncrementalVoronoi::set_label(std::uint32_t v, Label l) {
    if (label_[v] == Label::unknown) labelled_.push_back(v);
    label_[v] = l;
}

void IncrementalVoronoi::set_incident(std::uint32_t f) {
    if (incident_[f] == 0) {
        incident_[f] = 1;
        incident_list_.push_back(f);
    }
}

void IncrementalVoronoi::clear_labels() {
    for (std::uint32_t v : labelled_) label_[v] = Label::unknown;
    for (std::uint32_t f : incident_list_) incident_[f] = 0;
    labelled_.clear();
    incident_list_.clear();
}

void IncrementalVoronoi::insert(std::uint32_t g, const std::vector<std::uint32_t>& tree) {
    const auto in_tree = [&](std::uint32_t v) { return label_[v] == Label::in; };
    // A boundary half-edge: from a vertex of T to one outside.
    std::uint32_t b0 = no_index;
    for (std::uint32_t t : tree) {
        std::uint32_t h = vout_[t];
        for (int i = 0; i < 3 && b0 == no_index; ++i, h = cw(h)) {
            if (!in_tree(dest(h))) b0 = h;
        }
        if (b0 != no_index) break;
    }
    if (b0 == no_index) throw Error("incremental Voronoi: the vertices to delete enclose nothing");
    // Around T: from boundary half-edge b into the region on its right, along that region to
    // the next half-edge that leaves T.
    boundary_.clear();
    const std::size_t limit = 3 * tree.size() + 3;
    std::uint32_t b = b0;
    do {
        boundary_.push_back(b);
        std::uint32_t h = next(b ^ 1u);
        std::size_t steps = 0;
        while (in_tree(dest(h))) {
            h = next(h);
            if (++steps > limit) throw Error("incremental Voronoi: the new region does not close");
        }
        b = h;
        if (boundary_.size() > limit)
            throw Error("incremental Voronoi: the new region does not close");
    } while (b != b0);
    if (boundary_.size() != tree.size() + 2) {
        throw Error("incremental Voronoi: the vertices to delete do not form a tree");
    }
    // Each region around T is met once (else it would be split, or share two edges with g's).
    ++insertions_;
    for (std::uint32_t e : boundary_) {
        const std::uint32_t region = face(e ^ 1u);
        if (region_stamp_[region] == insertions_) {
            throw Error("incremental Voronoi: a region meets the deleted vertices twice");
        }
        region_stamp_[region] = insertions_;
    }
    // The internal edges of T go; the new vertices split the boundary edges.
    for (std::uint32_t t : tree) {
        std::uint32_t h = vout_[t];
        for (int i = 0; i < 3; ++i, h = cw(h)) {
            if (in_tree(dest(h)) && h < (h ^ 1u)) free_edges_.push_back(h);
        }
    }
    const std::size_t m = boundary_.size();
    std::vector<std::uint32_t> ring(m);
    std::vector<std::uint32_t> xs(m);
    for (std::size_t i = 0; i < m; ++i) xs[i] = new_vertex();
    for (std::size_t i = 0; i < m; ++i) ring[i] = new_edge();
    for (std::size_t i = 0; i < m; ++i) {
        const std::uint32_t bi = boundary_[i];
        const std::uint32_t bn = boundary_[(i + 1) % m];
        const std::uint32_t n = ring[i];
        const std::uint32_t n_prev = ring[(i + m - 1) % m];
        const std::uint32_t region = face(bi ^ 1u);
        he_[bi].origin = xs[i];
        he_[bi ^ 1u].next = n;
        he_[n] = {xs[i], bn, region};
        he_[n ^ 1u] = {xs[(i + 1) % m], n_prev ^ 1u, g};
        vout_[xs[i]] = bi;
        face_edge_[region] = n;
    }
    face_edge_[g] = ring[0] ^ 1u;
    for (std::uint32_t t : tree) free_vertices_.push_back(t);
    last_ = g;
}

std::size_t IncrementalVoronoi::peak_bytes() const {
    return he_.capacity() * sizeof(HalfEdge) + vout_.capacity() * 4 + label_.capacity() +
           face_edge_.size() * 4 + incident_.size();
}

VoronoiGraph IncrementalVoronoi::release() {
    for (std::uint32_t e : free_edges_) {
        he_[e].face = dead_face;
        he_[e ^ 1u].face = dead_face;
    }
    VoronoiGraph g;
    g.vertex_count = static_cast<std::uint32_t>(vout_.size());
    g.he = std::move(he_);
    // The rest is the graph's own: freed before the result is made.
    free_storage(vout_);
    free_storage(face_edge_);
    free_storage(free_edges_);
    free_storage(free_vertices_);
    free_storage(label_);
    free_storage(incident_);
    free_storage(labelled_);
    free_storage(incident_list_);
    free_storage(boundary_);
    free_storage(region_stamp_);
    return g;
}

MethodResult run_incremental(const MethodInput& input,
                             const MethodOptions& options,
                             const Progress& progress,
                             const char* name,
                             ChooseTree choose) {
    double faults = 0.0;
    for (const auto& [key, value] : options.params) {
        if (key != "faults") {
            throw UsageError(std::string("method ") + name + " has no parameter '" + key +
                             "' (it takes faults=P)");
        }
        std::size_t used = 0;
        try {
            faults = std::stod(value, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != value.size() || !(faults >= 0.0 && faults <= 1.0)) {
            throw UsageError(std::string("method ") + name +
                             ": faults expects a probability in [0, 1], got '" + value + "'");
        }
    }
    Sites sites = make_sites(input.points, name);
    CountingPredicates pred;
    IncrementalVoronoi graph(sites, pred);
    graph.set_faults(faults, options.seed);
    std::uint64_t deleted = 0;
    progress.report(0.0, name);
    {
        const std::vector<std::uint32_t> order = graph.insertion_order();
        std::vector<std::uint32_t> tree;
        for (std::size_t i = 0; i < order.size(); ++i) {
            if ((i & 0x3fffu) == 0) progress.report(0.8 * double(i) / double(order.size()));
            const std::uint32_t g = order[i];
            graph.clear_labels();
            tree.clear();
            choose(graph, g, sites.xy[g], tree);
            deleted += tree.size();
            graph.insert(g, tree);
        }
    }
    graph.clear_labels();
    MethodResult result;
    result.counters.walk_steps = graph.walk_steps();
    result.counters.peak_bytes = graph.peak_bytes();
    result.counters.extra["deleted_vertices"] = deleted;
    if (faults > 0.0) {
        result.counters.extra["faults_injected"] = graph.faults_injected();
        result.stats_json = "\"faults_injected\": " + std::to_string(graph.faults_injected());
    }
    FinishOptions finish;
    finish.exact = faults == 0.0;
    finish_voronoi(graph.release(), std::move(sites), input.points, finish, pred, result,
                   progress.sub(0.8, 1.0));
    pred.add_to(result.counters);
    return result;
}

}  // namespace dtm::methods::detail
