// SPDX-License-Identifier: MIT
// LandXML reader (1.0-1.2 and profiles such as the Finnish Inframodel: elements are matched by
// local name, any namespace). One pass with expat keeps the selected Surface: Definition/Pnts
// (P id: "northing easting elevation"), Faces (3 ids a TIN face, 4 a grid cell split in two;
// i="1" invisible faces are left out, so they become holes; n= and b= are not needed), and the
// SourceData lines (Breakline, Boundary outer/void/island, Contour with elev, DataPoints).
// Faces are turned counter-clockwise in (easting, northing): Civil 3D writes them so, OpenRoads
// clockwise.
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/formats/landxml.hpp"
#include "io/formats/xml/xml_sax.hpp"

namespace dtm::io {
namespace {

enum class LineKind { none, breakline, soft_breakline, boundary, hole, contour, data_points };

struct SourceLine {
    LineKind kind;
    Polyline line;
};

/// The numbers of a space-separated list.
void parse_numbers(xml::Parser& parser, std::string_view text, std::vector<double>& out) {
    out.clear();
    std::size_t at = 0;
    while (at < text.size()) {
        while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
        if (at == text.size()) break;
        std::size_t end = at;
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
        double v = 0;
        const auto r = std::from_chars(text.data() + at, text.data() + end, v);
        if (r.ec != std::errc{} || r.ptr != text.data() + end) {
            parser.fail("expected a number, found '" + std::string(text.substr(at, end - at)) +
                        "'");
        }
        out.push_back(v);
        at = end;
    }
}

class Handler final : public xml::Handler {
public:
    explicit Handler(const ReadOptions& options) : options_(options) {}

    void start(xml::Parser& p,
               std::string_view name,
               std::span<const xml::Attribute> attributes) override {
        if (name == "Surface") {
            const std::string surface(xml::attribute(attributes, "name"));
            names.push_back(surface);
            selected_ = !found && (options_.surface.empty() || surface == options_.surface);
            if (selected_) surface_name = surface;
        } else if (name == "CoordinateSystem") {
            epsg = xml::attribute(attributes, "epsgCode");
            wkt = xml::attribute(attributes, "ogcWktCode");
        } else if (name == "Metric" || name == "Imperial") {
            linear_unit = xml::attribute(attributes, "linearUnit");
        }
        if (!selected_) return;
        if (name == "P") {
            id_ = xml::attribute(attributes, "id");
            if (id_.empty()) p.fail("expected an id attribute in <P>");
        } else if (name == "F") {
            invisible_face_ = xml::attribute(attributes, "i") == "1";
        } else if (name == "Breakline") {
            const auto type = xml::attribute(attributes, "brkType");
            line_ = type == "nondestructive" ? LineKind::soft_breakline : LineKind::breakline;
        } else if (name == "Boundary") {
            line_ = xml::attribute(attributes, "bndType") == "void" ? LineKind::hole
                                                                    : LineKind::boundary;
        } else if (name == "Contour") {
            line_ = LineKind::contour;
            std::vector<double> elev;
            parse_numbers(p, xml::attribute(attributes, "elev"), elev);
            contour_z_ = elev.size() == 1 ? elev[0] : std::numeric_limits<double>::quiet_NaN();
        } else if (name == "DataPoints") {
            line_ = LineKind::data_points;
        }
    }

    void end(xml::Parser& p, std::string_view name, std::string_view text) override {
        if (name == "Surface" && selected_) {
            selected_ = false;
            found = true;
        }
        if (!selected_) return;
        if (name == "P") {
            parse_numbers(p, text, numbers_);
            if (numbers_.size() != 3) {
                p.fail("expected 'northing easting elevation' in <P id=\"" + id_ + "\">, found " +
                       std::to_string(numbers_.size()) + " numbers");
            }
            if (!ids_.emplace(id_, static_cast<VertexIndex>(points.size())).second) {
                p.fail("point id '" + id_ + "' is defined twice");
            }
            points.push_back({numbers_[1], numbers_[0], numbers_[2]});
            point_ids.push_back(id_);
        } else if (name == "F") {
            face(p, text);
        } else if (name == "PntList3D" || name == "PntList2D") {
            line(p, text, name == "PntList3D" ? 3 : 2);
        } else if (name == "Breakline" || name == "Boundary" || name == "Contour" ||
                   name == "DataPoints") {
            line_ = LineKind::none;
        }
    }

    std::vector<std::string> names;
    bool found = false;
    std::string surface_name;
    std::string epsg;
    std::string wkt;
    std::string linear_unit;
    std::vector<Point3> points;
    std::vector<std::string> point_ids;
    std::vector<Triangle> faces;
    std::size_t invisible = 0;
    std::size_t degenerate = 0;
    std::size_t flipped = 0;
    std::vector<SourceLine> lines;
    std::vector<Point3> data_points;

private:
    VertexIndex vertex(xml::Parser& p, std::string_view id) {
        const auto it = ids_.find(std::string(id));
        if (it == ids_.end()) {
            p.fail("a face refers to point id '" + std::string(id) + "', which no <P> defines");
        }
        return it->second;
    }

    void face(xml::Parser& p, std::string_view text) {
        if (invisible_face_) {
            ++invisible;
            return;
        }
        std::array<VertexIndex, 4> v{};
        std::size_t n = 0;
        std::size_t at = 0;
        while (at < text.size()) {
            while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
            std::size_t end = at;
            while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
            if (end == at) break;
            if (n == 4) p.fail("expected 3 (TIN) or 4 (grid) point ids in <F>");
            v[n++] = vertex(p, text.substr(at, end - at));
            at = end;
        }
        if (n < 3)
            p.fail("expected 3 (TIN) or 4 (grid) point ids in <F>, found " + std::to_string(n));
        add_triangle(v[0], v[1], v[2]);
        if (n == 4) add_triangle(v[0], v[2], v[3]);
    }

    void add_triangle(VertexIndex a, VertexIndex b, VertexIndex c) {
        const Point3& pa = points[a];
        const Point3& pb = points[b];
        const Point3& pc = points[c];
        const int o = geom::orient2d(pa.x, pa.y, pb.x, pb.y, pc.x, pc.y);
        if (o == 0) {
            ++degenerate;
            return;
        }
        if (o < 0) {
            std::swap(b, c);
            ++flipped;
        }
        Triangle t;
        t.v = {a, b, c};
        faces.push_back(t);
    }

    void line(xml::Parser& p, std::string_view text, std::size_t dimension) {
        if (line_ == LineKind::none) return;
        parse_numbers(p, text, numbers_);
        if (numbers_.size() % dimension != 0) {
            p.fail("expected a multiple of " + std::to_string(dimension) + " numbers, found " +
                   std::to_string(numbers_.size()));
        }
        const double nan = std::numeric_limits<double>::quiet_NaN();
        SourceLine s{line_, {}};
        s.line.source = p.path().filename().string() + ":" + std::to_string(p.line());
        for (std::size_t i = 0; i < numbers_.size(); i += dimension) {
            double z = dimension == 3 ? numbers_[i + 2] : nan;
            if (line_ == LineKind::contour) z = contour_z_;
            s.line.points.push_back({numbers_[i + 1], numbers_[i], z});
        }
        if (line_ == LineKind::data_points) {
            data_points.insert(data_points.end(), s.line.points.begin(), s.line.points.end());
            return;
        }
        if (dimension == 2 && line_ == LineKind::breakline) s.kind = LineKind::soft_breakline;
        auto& pts = s.line.points;
        if (pts.size() > 2 && pts.front().x == pts.back().x && pts.front().y == pts.back().y) {
            pts.pop_back();
            s.line.closed = true;
        }
        if (s.kind == LineKind::boundary || s.kind == LineKind::hole) s.line.closed = true;
        lines.push_back(std::move(s));
    }

    const ReadOptions& options_;
    bool selected_ = false;
    bool invisible_face_ = false;
    LineKind line_ = LineKind::none;
    double contour_z_ = 0;
    std::string id_;
    std::unordered_map<std::string, VertexIndex> ids_;
    std::vector<double> numbers_;
};

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
    return out;
}

ConstraintKind constraint_kind(LineKind kind) {
    switch (kind) {
        case LineKind::soft_breakline:
            return ConstraintKind::soft_breakline;
        case LineKind::boundary:
            return ConstraintKind::boundary;
        case LineKind::hole:
            return ConstraintKind::hole;
        default:
            return ConstraintKind::breakline;
    }
}

/// The vertex within a micrometre of each line vertex (exports write a breakline's coordinates
/// rounded differently from its points), by a search in x order.
class VertexFinder {
public:
    explicit VertexFinder(const std::vector<Point3>& vertices)
        : v_(vertices), order_(vertices.size()) {
        for (VertexIndex i = 0; i < order_.size(); ++i) order_[i] = i;
        std::stable_sort(order_.begin(), order_.end(),
                         [&](VertexIndex a, VertexIndex b) { return v_[a].x < v_[b].x; });
    }
    [[nodiscard]] VertexIndex find(const Point3& p) const {
        constexpr double tolerance = 1e-6;
        auto it = std::lower_bound(order_.begin(), order_.end(), p.x - tolerance,
                                   [&](VertexIndex i, double x) { return v_[i].x < x; });
        VertexIndex best = no_vertex;
        double best_d = tolerance * tolerance;
        for (; it != order_.end() && v_[*it].x <= p.x + tolerance; ++it) {
            const double dx = v_[*it].x - p.x;
            const double dy = v_[*it].y - p.y;
            if (dx * dx + dy * dy <= best_d) {
                best_d = dx * dx + dy * dy;
                best = *it;
            }
        }
        return best;
    }

private:
    const std::vector<Point3>& v_;
    std::vector<VertexIndex> order_;
};

/// The SourceData segments that are edges of the TIN, as its constrained edges; returns how
/// many segments are not.
std::size_t constrain(Tin& tin, const std::vector<SourceLine>& lines) {
    const VertexFinder at(tin.vertices);
    std::unordered_set<std::uint64_t> edges;
    const auto key = [](VertexIndex a, VertexIndex b) {
        return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
    };
    for (const Triangle& t : tin.triangles) {
        for (int s = 0; s < 3; ++s) edges.insert(key(t.v[s], t.v[(s + 1) % 3]));
    }
    std::size_t missing = 0;
    for (const SourceLine& s : lines) {
        std::vector<VertexIndex> vertices;
        for (const Point3& p : s.line.points) {
            vertices.push_back(at.find(p));
        }
        const std::size_t n = vertices.size();
        const std::size_t segments = s.line.closed && n > 2 ? n : (n > 0 ? n - 1 : 0);
        for (std::size_t i = 0; i < segments; ++i) {
            const VertexIndex a = vertices[i];
            const VertexIndex b = vertices[(i + 1) % n];
            if (a == no_vertex || b == no_vertex || a == b || edges.count(key(a, b)) == 0) {
                ++missing;
                continue;
            }
            tin.constraints.push_back({std::min(a, b), std::max(a, b), constraint_kind(s.kind)});
        }
    }
    auto& c = tin.constraints;
    std::stable_sort(c.begin(), c.end(), [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
        return std::pair{x.a, x.b} < std::pair{y.a, y.b};
    });
    c.erase(std::unique(c.begin(), c.end(),
                        [](const auto& x, const auto& y) { return x.a == y.a && x.b == y.b; }),
            c.end());
    return missing;
}

}  // namespace

bool is_landxml(const FileHead& head) { return xml::root_element(head.bytes) == "LandXML"; }

ReadResult read_landxml(const InputFile& file,
                        const ReadOptions& options,
                        const Progress& progress) {
    if (file.role != InputRole::points) {
        throw InputError(file.path, 0, 0,
                         "a LandXML surface is a survey input (its TIN or, with "
                         "`retriangulate`, its points and lines), not a line or ring input");
    }
    Handler h(options);
    xml::Parser parser(file.path);
    parser.parse(h, progress);
    if (!h.found) {
        if (h.names.empty()) throw InputError(file.path, 0, 0, "expected a <Surface>, found none");
        throw InputError(file.path, 0, 0,
                         "no surface named '" + options.surface + "' (`surface`); the file has " +
                             join(h.names));
    }
    ReadResult r;
    InputSummary& s = r.summary;
    s.path = file.path;
    s.format = "LandXML surface '" + h.surface_name + "'";
    if (h.names.size() > 1 && options.surface.empty()) {
        s.warnings.push_back(std::to_string(h.names.size()) + " surfaces (" + join(h.names) +
                             "): read the first; choose another with `surface`");
    }
    if (!h.epsg.empty() || !h.wkt.empty()) {
        try {
            r.crs_wkt = crs_to_wkt(!h.epsg.empty() ? "EPSG:" + h.epsg : h.wkt);
        } catch (const UsageError&) {
            s.warnings.push_back("CoordinateSystem not known to PROJ (epsgCode '" + h.epsg +
                                 "'): no CRS taken from the file");
        }
    }
    if (!h.linear_unit.empty() && h.linear_unit != "meter" && r.crs_wkt.empty()) {
        s.warnings.push_back("coordinates are in " + h.linear_unit + " (Units) and no CRS says so");
    }
    if (h.degenerate > 0) {
        s.warnings.push_back(std::to_string(h.degenerate) +
                             " faces with three collinear points left out");
    }
    r.labels.ids = std::move(h.point_ids);
    r.terrain.points = std::move(h.points);
    for (SourceLine& l : h.lines) {
        switch (l.kind) {
            case LineKind::soft_breakline:
                r.terrain.soft_breaklines.push_back(l.line);
                break;
            case LineKind::boundary:
                r.terrain.boundaries.push_back(l.line);
                break;
            case LineKind::hole:
                r.terrain.holes.push_back(l.line);
                break;
            default:
                r.terrain.breaklines.push_back(l.line);
        }
    }
    if (options.retriangulate) {
        if (!h.data_points.empty()) {
            r.terrain.points.insert(r.terrain.points.end(), h.data_points.begin(),
                                    h.data_points.end());
            r.labels.ids.resize(r.terrain.points.size());
        }
        return r;
    }
    Tin tin;
    tin.vertices = r.terrain.points;
    tin.triangles = std::move(h.faces);
    try {
        link_neighbours(tin);
    } catch (const InputError& e) {
        throw InputError(file.path, 0, 0, std::string("the faces do not form a TIN: ") + e.what());
    }
    const std::size_t missing = constrain(tin, h.lines);
    if (missing > 0) {
        s.warnings.push_back(std::to_string(missing) +
                             " SourceData line segments are not edges of the TIN (not constrained "
                             "edges; `retriangulate` makes them so)");
    }
    if (h.invisible > 0) {
        s.warnings.push_back(std::to_string(h.invisible) +
                             " invisible faces (i=\"1\") left out as holes");
    }
    if (h.flipped > 0 && h.flipped < tin.triangles.size()) {
        s.warnings.push_back(std::to_string(h.flipped) + " of " +
                             std::to_string(tin.triangles.size()) +
                             " faces were clockwise (turned counter-clockwise)");
    }
    s.triangles = tin.triangles.size();
    r.tin = std::move(tin);
    return r;
}

}  // namespace dtm::io
