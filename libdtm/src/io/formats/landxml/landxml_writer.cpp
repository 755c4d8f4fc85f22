// SPDX-License-Identifier: MIT
// LandXML 1.2 writer: one Surface streamed through a buffer (no document tree). A <P> holds
// "northing easting elevation" (y first: the standard's order); numbers are the shortest text
// that reads back to the same double, so a dtm LandXML read and written again is byte-identical.
// Reference: LandXML-1.2.xsd (landxml.org), elements Units, CoordinateSystem, Surface,
// SourceData, Definition, Pnts, Faces.
#include <ogr_spatialref.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>

#include "dtm/algo/constraint_chains.hpp"
#include "dtm/algo/surface_stats.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/formats/landxml.hpp"
#include "io/formats/qgis/qgis_project_xml.hpp"  // qgis::escape: the one XML escaping

namespace dtm::io {
namespace {

class Out {
public:
    explicit Out(const std::filesystem::path& path) : path_(path), file_(path, std::ios::binary) {
        if (!file_) throw Error("cannot write " + path.string());
        buffer_.reserve(block + 256);
    }
    Out& operator<<(std::string_view s) {
        buffer_.append(s);
        if (buffer_.size() >= block) flush();
        return *this;
    }
    Out& number(double v) {
        char text[32];
        const char* end = std::to_chars(text, text + sizeof text, v).ptr;
        return *this << std::string_view(text, static_cast<std::size_t>(end - text));
    }
    Out& integer(std::size_t v) {
        char text[24];
        const char* end = std::to_chars(text, text + sizeof text, v).ptr;
        return *this << std::string_view(text, static_cast<std::size_t>(end - text));
    }
    /// northing easting elevation
    Out& point(const Point3& p) {
        number(p.y) << " ";
        number(p.x) << " ";
        return number(p.z);
    }
    void flush() {
        file_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
        buffer_.clear();
    }
    void close() {
        flush();
        file_.close();
        if (!file_) throw Error("cannot write " + path_.string());
    }

private:
    static constexpr std::size_t block = std::size_t{1} << 20;
    std::filesystem::path path_;
    std::ofstream file_;
    std::string buffer_;
};

/// SOURCE_DATE_EPOCH (reproducible-builds.org) when set, else now.
std::int64_t timestamp() {
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr) {
        std::int64_t v = 0;
        const std::string_view s(epoch);
        if (std::from_chars(s.data(), s.data() + s.size(), v).ec == std::errc{}) return v;
    }
    return static_cast<std::int64_t>(std::time(nullptr));
}

void write_units(Out& out, const std::string& wkt) {
    double metres = 1.0;
    if (!wkt.empty()) {
        OGRSpatialReference srs;
        if (srs.importFromWkt(wkt.c_str()) == OGRERR_NONE && srs.IsProjected()) {
            metres = srs.GetLinearUnits();
        }
    }
    const char* feet = std::abs(metres - 1200.0 / 3937.0) < 1e-9 ? "USSurveyFoot"
                       : std::abs(metres - 0.3048) < 1e-9        ? "foot"
                                                                 : nullptr;
    out << "  <Units>\n";
    if (feet != nullptr) {
        out << "    <Imperial areaUnit=\"squareFoot\" linearUnit=\"" << feet
            << "\" volumeUnit=\"cubicFeet\" temperatureUnit=\"fahrenheit\" "
               "pressureUnit=\"inchHG\" angularUnit=\"decimal degrees\" directionUnit=\"decimal "
               "degrees\"/>\n";
    } else {
        out << "    <Metric areaUnit=\"squareMeter\" linearUnit=\"meter\" "
               "volumeUnit=\"cubicMeter\" temperatureUnit=\"celsius\" pressureUnit=\"milliBars\" "
               "angularUnit=\"decimal degrees\" directionUnit=\"decimal degrees\"/>\n";
    }
    out << "  </Units>\n";
}

void write_crs(Out& out, const std::string& wkt) {
    if (wkt.empty()) return;
    const std::string label = crs_label(wkt);
    OGRSpatialReference srs;
    std::string name = label;
    if (srs.importFromWkt(wkt.c_str()) == OGRERR_NONE && srs.GetName() != nullptr) {
        name = srs.GetName();
    }
    out << "  <CoordinateSystem name=\"" << qgis::escape(name) << "\"";
    if (label.starts_with("EPSG:")) out << " epsgCode=\"" << label.substr(5) << "\"";
    out << " ogcWktCode=\"" << qgis::escape(wkt) << "\"/>\n";
}

void write_chain(Out& out, const Tin& tin, const ConstraintChain& chain) {
    out << "<PntList3D>";
    for (std::size_t i = 0; i < chain.vertices.size(); ++i) {
        if (i > 0) out << " ";
        out.point(tin.vertex(chain.vertices[i]));
    }
    if (chain.closed) {
        out << " ";
        out.point(tin.vertex(chain.vertices[0]));
    }
    out << "</PntList3D>";
}

void write_source_data(Out& out, const Tin& tin) {
    if (tin.constraints.empty()) return;
    const auto hard = constraint_chains(tin, ConstraintKind::breakline);
    const auto soft = constraint_chains(tin, ConstraintKind::soft_breakline);
    const auto outer = constraint_chains(tin, ConstraintKind::boundary);
    const auto voids = constraint_chains(tin, ConstraintKind::hole);
    out << "      <SourceData>\n";
    std::size_t number = 0;
    if (!hard.empty() || !soft.empty()) {
        out << "        <Breaklines>\n";
        for (const auto* group : {&hard, &soft}) {
            const char* type = group == &hard ? "standard" : "nondestructive";
            for (const ConstraintChain& c : *group) {
                out << "          <Breakline brkType=\"" << type << "\" name=\"";
                out.integer(++number) << "\">";
                write_chain(out, tin, c);
                out << "</Breakline>\n";
            }
        }
        out << "        </Breaklines>\n";
    }
    if (!outer.empty() || !voids.empty()) {
        out << "        <Boundaries>\n";
        for (const auto* group : {&outer, &voids}) {
            const char* type = group == &outer ? "outer" : "void";
            for (const ConstraintChain& c : *group) {
                out << "          <Boundary bndType=\"" << type << "\" edgeTrim=\"true\" name=\"";
                out.integer(++number) << "\">";
                write_chain(out, tin, c);
                out << "</Boundary>\n";
            }
        }
        out << "        </Boundaries>\n";
    }
    out << "      </SourceData>\n";
}

}  // namespace

void write_landxml(const Tin& tin,
                   const std::filesystem::path& path,
                   const TinWriteOptions& options) {
    if (tin.triangles.empty()) {
        throw Error("cannot write " + path.string() + ": a LandXML surface needs a triangle");
    }
    const std::time_t t = static_cast<std::time_t>(timestamp());
    std::tm utc{};
    gmtime_r(&t, &utc);
    char date[16];
    char time[16];
    std::strftime(date, sizeof date, "%Y-%m-%d", &utc);
    std::strftime(time, sizeof time, "%H:%M:%S", &utc);
    Out out(path);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<LandXML xmlns=\"http://www.landxml.org/schema/LandXML-1.2\" "
           "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
           "xsi:schemaLocation=\"http://www.landxml.org/schema/LandXML-1.2 "
           "http://www.landxml.org/schema/LandXML-1.2/LandXML-1.2.xsd\" date=\""
        << date << "\" time=\"" << time << "\" version=\"1.2\" language=\"English\" "
        << "readOnly=\"false\">\n";
    write_units(out, options.crs_wkt);
    write_crs(out, options.crs_wkt);
    out << "  <Application name=\"dtm\" desc=\"terrain modelling\" version=\"" DTM_VERSION
           "\" timeStamp=\""
        << date << "T" << time << "\"/>\n";
    out << "  <Surfaces>\n    <Surface name=\"TIN\">\n";
    write_source_data(out, tin);
    const SurfaceStats stats = surface_stats(tin);
    out << "      <Definition surfType=\"TIN\" area2DSurf=\"";
    out.number(stats.planimetric_area) << "\" area3DSurf=\"";
    out.number(stats.surface_area) << "\" elevMax=\"";
    out.number(stats.z_max) << "\" elevMin=\"";
    out.number(stats.z_min) << "\">\n        <Pnts>\n";
    for (std::size_t i = 0; i < tin.vertices.size(); ++i) {
        out << "          <P id=\"";
        out.integer(i + 1) << "\">";
        out.point(tin.vertices[i]) << "</P>\n";
    }
    out << "        </Pnts>\n        <Faces>\n";
    for (const Triangle& f : tin.triangles) {
        out << "          <F>";
        out.integer(f.v[0] + 1U) << " ";
        out.integer(f.v[1] + 1U) << " ";
        out.integer(f.v[2] + 1U) << "</F>\n";
    }
    out << "        </Faces>\n      </Definition>\n    </Surface>\n  </Surfaces>\n</LandXML>\n";
    out.close();
}

}  // namespace dtm::io
