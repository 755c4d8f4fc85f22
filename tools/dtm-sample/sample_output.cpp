// SPDX-License-Identifier: MIT
// Writers of the sample files. The shapefiles go through OGR so their .prj is the one GDAL writes
// for EPSG:5514; the CSV and HP-GL are plain text.
#include "sample_output.hpp"

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

namespace dtm::sample {
namespace {

std::ofstream open_text(const std::filesystem::path& path) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) {
        throw std::runtime_error("cannot create " + path.string());
    }
    return file;
}

std::string format(const char* pattern, double a, double b, double c) {
    char text[128];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

struct DatasetCloser {
    void operator()(GDALDataset* dataset) const noexcept { GDALClose(dataset); }
};

void write_layer(const std::filesystem::path& path, const std::vector<Line>& lines, bool polygons) {
    GDALAllRegister();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("ESRI Shapefile");
    if (std::filesystem::exists(path)) {
        driver->Delete(path.string().c_str());
    }
    std::unique_ptr<GDALDataset, DatasetCloser> dataset(
        driver->Create(path.string().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!dataset) {
        throw std::runtime_error("cannot create " + path.string());
    }
    OGRSpatialReference srs;
    srs.importFromEPSG(epsg);
    OGRLayer* layer = dataset->CreateLayer(path.stem().string().c_str(), &srs,
                                           polygons ? wkbPolygon25D : wkbLineString25D, nullptr);
    OGRFieldDefn kind("kind", OFTString);
    kind.SetWidth(24);
    layer->CreateField(&kind);
    for (const Line& line : lines) {
        OGRFeature feature(layer->GetLayerDefn());
        feature.SetField("kind", line.kind.c_str());
        auto curve =
            polygons ? std::make_unique<OGRLinearRing>() : std::make_unique<OGRLineString>();
        for (const SurveyPoint& p : line.vertices) {
            curve->addPoint(p.e, p.n, p.z);
        }
        if (polygons) {
            OGRPolygon polygon;
            polygon.addRingDirectly(static_cast<OGRLinearRing*>(curve.release()));
            feature.SetGeometry(&polygon);
        } else {
            feature.SetGeometry(curve.get());
        }
        if (layer->CreateFeature(&feature) != OGRERR_NONE) {
            throw std::runtime_error("cannot write a feature to " + path.string());
        }
    }
}

long plotter(double ground, double origin) {
    return std::lround((ground - origin) / ground_metres_per_plotter_unit);
}

std::string hpgl_point(const SurveyPoint& p) {
    return std::to_string(plotter(p.e, plan_origin_e)) + "," +
           std::to_string(plotter(p.n, plan_origin_n));
}

/// A spot height: the symbol at the point, then its label 1 mm right and 0.5 mm up.
void write_spot_height(std::ofstream& out, const SurveyPoint& p) {
    char label[32];
    std::snprintf(label, sizeof label, "%.2f", p.z);
    const long x = plotter(p.e, plan_origin_e);
    const long y = plotter(p.n, plan_origin_n);
    out << "SM*;PU" << x << ',' << y << ";SM;PU" << x + 40 << ',' << y + 20 << ";LB" << label
        << '\x03' << '\n';
}

void write_polyline(std::ofstream& out, const Line& line) {
    out << "PU" << hpgl_point(line.vertices.front()) << ";PD";
    for (std::size_t i = 1; i < line.vertices.size(); ++i) {
        out << (i > 1 ? "," : "") << hpgl_point(line.vertices[i]);
        if (i % 8 == 0 && i + 1 < line.vertices.size()) {
            out << ";\nPD";
        }
    }
    out << ";PU;\n";
}

}  // namespace

void write_csv_files(const Survey& survey, const std::filesystem::path& dir) {
    std::ofstream points = open_text(dir / "points.csv");
    points << "id,x,y,z\n";
    for (std::size_t i = 0; i < survey.points.size(); ++i) {
        const SurveyPoint& p = survey.points[i];
        points << p.id << format(",%.3f,%.3f,%.3f\n", p.e, p.n, p.z);
        if (i == survey.points.size() / 3) {
            points << survey.bad_lines[0] << '\n';
        } else if (i == 2 * survey.points.size() / 3) {
            points << survey.bad_lines[1] << '\n';
        }
    }
    std::ofstream checks = open_text(dir / "checkpoints.csv");
    checks << "id,x,y,z\n";
    for (const SurveyPoint& p : survey.check_points) {
        checks << p.id << format(",%.3f,%.3f,%.4f\n", p.e, p.n, p.z);
    }
}

void write_shapefiles(const Survey& survey, const std::filesystem::path& dir) {
    write_layer(dir / "breaklines.shp", survey.breaklines, false);
    write_layer(dir / "boundary.shp", {survey.boundary}, true);
    write_layer(dir / "building.shp", {survey.building}, true);
}

void write_natural_files(const Survey& natural, const std::filesystem::path& dir) {
    std::ofstream points = open_text(dir / "natural_points.csv");
    points << "id,x,y,z\n";
    for (const SurveyPoint& p : natural.points) {
        points << p.id << format(",%.3f,%.3f,%.3f\n", p.e, p.n, p.z);
    }
    write_layer(dir / "natural_breaklines.shp", natural.breaklines, false);
    write_layer(dir / "natural_boundary.shp", {natural.boundary}, true);
    write_layer(dir / "natural_building.shp", {natural.building}, true);
}

void write_hpgl_plan(const Survey& survey, const std::filesystem::path& dir) {
    std::ofstream out = open_text(dir / "plan_500.hpgl");
    out << "IN;SP1;SI0.12,0.18;\nPU400,200;LBSAMPLE SITE S-JTSK 1:500\x03\n";
    for (const SurveyPoint& p : survey.points) {
        if (p.id.front() != 'R') {  // a re-measured point is plotted once
            write_spot_height(out, p);
        }
    }
    for (const Line& line : survey.breaklines) {
        for (const SurveyPoint& p : line.vertices) {
            write_spot_height(out, p);
        }
    }
    for (const Line* ring : {&survey.boundary, &survey.building}) {
        for (std::size_t i = 0; i + 1 < ring->vertices.size(); ++i) {
            write_spot_height(out, ring->vertices[i]);
        }
    }
    out << "SP2;\n";
    for (const Line& line : survey.breaklines) {
        write_polyline(out, line);
    }
    out << "SP3;\n";
    write_polyline(out, survey.boundary);
    out << "SP4;\n";
    write_polyline(out, survey.building);
    out << "SP0;\n";
}

}  // namespace dtm::sample
