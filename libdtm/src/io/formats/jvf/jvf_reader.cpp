// SPDX-License-Identifier: MIT
// JVF DTM reader (Jednotný výměnný formát digitální technické mapy, version 1.4.x). The file is
// GML 3.2 inside object-type elements under Data (PodrobnyBodZPS, TerenniHrana, ...), each a list
// of ZaznamObjektu records with attributes (ID, CisloBodu, TridaPresnostiPoloha/Vyska,
// TypTerenniHrany) and a geometry (Point pos, LineString or Polygon posList, "x y z" in the
// srsName CRS, EPSG:5514). Survey points: the object types PodrobnyBod* (detail points) and
// *VyskovyBod* (height points); breaklines: TerenniHrana (terrain edges; TypTerenniHrany 1 hrana,
// 2 pata, kept in the line's source). Other object types are counted in a warning. A change file
// (TypZapisu other than "kompletní zápis") is warned about: its records are read as they are.
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/formats/jvf.hpp"
#include "io/formats/xml/xml_sax.hpp"

namespace dtm::io {
namespace {

bool is_point_type(std::string_view type) {
    return type.starts_with("PodrobnyBod") || type.find("VyskovyBod") != std::string_view::npos;
}

class Handler final : public xml::Handler {
public:
    void start(xml::Parser& p,
               std::string_view name,
               std::span<const xml::Attribute> attributes) override {
        if (!stack_.empty() && stack_.back() == "Data") type_ = name;
        stack_.emplace_back(name);
        if (name == "ZaznamObjektu") {
            record_ = Record{};
            record_.line = p.line();
        } else if (name == "Point" || name == "LineString" || name == "Polygon") {
            record_.geometry = name;
            const auto srs = xml::attribute(attributes, "srsName");
            if (srs_.empty() && !srs.empty()) srs_ = srs;
            const auto dim = xml::attribute(attributes, "srsDimension");
            record_.dimension = dim == "2" ? 2 : 3;
        }
    }

    void end(xml::Parser& p, std::string_view name, std::string_view text) override {
        stack_.pop_back();
        const std::string_view parent = stack_.empty() ? std::string_view{} : stack_.back();
        if (name == "TypZapisu") {
            write_type = text;
        } else if (name == "ID" && parent == "SpolecneAtributyVsechObjektu") {
            record_.id = text;
        } else if (name == "CisloBodu") {
            record_.number = text;
        } else if (name == "TridaPresnostiPoloha") {
            record_.accuracy_xy = text;
        } else if (name == "TridaPresnostiVyska") {
            record_.accuracy_z = text;
        } else if (name == "TypTerenniHrany") {
            record_.edge_type = text;
        } else if ((name == "pos" || name == "posList") && record_.coordinates.empty()) {
            coordinates(p, text);  // a polygon's first ring is its exterior
        } else if (name == "ZaznamObjektu") {
            finish_record(p);
        }
    }

    TerrainInput terrain;
    PointLabels labels;
    std::map<std::string, std::size_t> ignored;
    std::string write_type;
    std::string srs_;

private:
    struct Record {
        std::string id;
        std::string number;
        std::string accuracy_xy;
        std::string accuracy_z;
        std::string edge_type;
        std::string geometry;
        int dimension = 3;
        std::size_t line = 0;
        std::vector<double> coordinates;
    };

    void coordinates(xml::Parser& p, std::string_view text) {
        std::size_t at = 0;
        while (at < text.size()) {
            while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
            std::size_t end = at;
            while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
            if (end == at) break;
            double v = 0;
            const auto r = std::from_chars(text.data() + at, text.data() + end, v);
            if (r.ec != std::errc{} || r.ptr != text.data() + end) {
                p.fail("expected a coordinate, found '" + std::string(text.substr(at, end - at)) +
                       "'");
            }
            record_.coordinates.push_back(v);
            at = end;
        }
        if (record_.coordinates.size() % static_cast<std::size_t>(record_.dimension) != 0) {
            p.fail("expected " + std::to_string(record_.dimension) +
                   " coordinates per position, found " +
                   std::to_string(record_.coordinates.size()) + " numbers");
        }
    }

    std::vector<Point3> positions() const {
        std::vector<Point3> out;
        const auto d = static_cast<std::size_t>(record_.dimension);
        for (std::size_t i = 0; i + d <= record_.coordinates.size(); i += d) {
            const double z =
                d == 3 ? record_.coordinates[i + 2] : std::numeric_limits<double>::quiet_NaN();
            out.push_back({record_.coordinates[i], record_.coordinates[i + 1], z});
        }
        return out;
    }

    void finish_record(xml::Parser& p) {
        std::vector<Point3> pts = positions();
        if (is_point_type(type_) && record_.geometry == "Point" && pts.size() == 1) {
            if (std::isnan(pts[0].z)) {
                p.fail("point " + record_.id + " of " + type_ + " has no height (srsDimension 2)");
            }
            terrain.points.push_back(pts[0]);
            labels.ids.push_back(record_.number.empty() ? record_.id : record_.number);
            labels.codes.push_back(type_ + " " + record_.accuracy_xy + "/" + record_.accuracy_z);
        } else if (type_ == "TerenniHrana" && pts.size() >= 2) {
            Polyline line;
            line.closed = record_.geometry == "Polygon";
            if (pts.size() > 2 && pts.front().x == pts.back().x && pts.front().y == pts.back().y) {
                pts.pop_back();
                line.closed = true;
            }
            line.points = std::move(pts);
            const char* kind = record_.edge_type == "2" ? "pata" : "hrana";
            line.source = p.path().filename().string() + ":" + std::to_string(record_.line) +
                          " TerenniHrana " + record_.id + " (" + kind + ")";
            terrain.breaklines.push_back(std::move(line));
        } else {
            ++ignored[type_];
        }
    }

    std::vector<std::string> stack_;
    std::string type_;
    Record record_;
};

}  // namespace

bool is_jvf(const FileHead& head) { return xml::root_element(head.bytes) == "JVFDTM"; }

ReadResult read_jvf(const InputFile& file, const ReadOptions&, const Progress& progress) {
    if (file.role != InputRole::points) {
        throw InputError(file.path, 0, 0,
                         "a JVF DTM file is a survey input (points and terrain edges), not a line "
                         "or ring input");
    }
    Handler h;
    xml::Parser parser(file.path);
    parser.parse(h, progress);
    ReadResult r;
    r.summary.path = file.path;
    r.summary.format = "JVF DTM";
    if (!h.srs_.empty()) {
        try {
            r.crs_wkt = crs_to_wkt(h.srs_);
        } catch (const UsageError&) {
            r.summary.warnings.push_back("srsName '" + h.srs_ + "' not known to PROJ");
        }
    }
    if (!h.write_type.empty() && h.write_type != "kompletní zápis") {
        r.summary.warnings.push_back("a change file (TypZapisu '" + h.write_type +
                                     "', změnové věty): its records are read as they are, not "
                                     "applied to an earlier state");
    }
    std::string ignored;
    for (const auto& [type, count] : h.ignored) {
        ignored += (ignored.empty() ? "" : ", ") + std::to_string(count) + " " + type;
    }
    if (!ignored.empty()) {
        r.summary.warnings.push_back(
            "objects that are neither survey points nor terrain edges, "
            "not used: " +
            ignored);
    }
    r.terrain = std::move(h.terrain);
    r.labels = std::move(h.labels);
    return r;
}

}  // namespace dtm::io
