// SPDX-License-Identifier: MIT
// `dtm contour` labels, checked by readers dtm did not write: ezdxf reads the DXF's TEXT labels
// and the TIN's 3DFACEs (`dtm tin -o tin.dxf` of the same input) and checks that every label's
// text is the level of the TIN at its insertion point, that the surface rises along the text's
// up vector, and that no two labels (contour numbers and spot heights) overlap; OGR reads the
// GeoPackage's label layers and their QGIS default styles.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace {

namespace test = dtm::test;

/// A slope with a hill on a jittered 5 m grid in S-JTSK: index contours every 2.5 m (0.5 x 5).
std::filesystem::path write_hill(const test::ScratchDir& dir) {
    std::ostringstream csv;
    csv.precision(12);
    csv << "x,y,z\n";
    for (int i = 0; i <= 80; ++i) {
        for (int j = 0; j <= 60; ++j) {
            const double jx = (i > 0 && i < 80) ? 0.37 * ((i * 7 + j * 3) % 5) : 0.0;
            const double jy = (j > 0 && j < 60) ? 0.29 * ((i * 3 + j * 5) % 7) : 0.0;
            const double x = 5.0 * i + jx;
            const double y = 5.0 * j + jy;
            const double r2 = (x - 200.0) * (x - 200.0) + (y - 150.0) * (y - 150.0);
            const double z = 200.0 + 0.05 * x + 15.0 * std::exp(-r2 / (2.0 * 60.0 * 60.0));
            csv << -750'000.0 + x << ',' << -1'050'000.0 + y << ',' << z << '\n';
        }
    }
    const auto path = dir / "hill.csv";
    test::write_file(path, csv.str());
    return path;
}

constexpr const char* check_script = R"py(
import sys, math, ezdxf
tin = ezdxf.readfile(sys.argv[1])
labels = ezdxf.readfile(sys.argv[2])
faces = [(f.dxf.vtx0, f.dxf.vtx1, f.dxf.vtx2) for f in tin.modelspace().query('3DFACE')]
assert len(faces) > 1000, len(faces)
B = 20.0
grid = {}
for i, (a, b, c) in enumerate(faces):
    xs = (a.x, b.x, c.x); ys = (a.y, b.y, c.y)
    for gx in range(math.floor(min(xs) / B), math.floor(max(xs) / B) + 1):
        for gy in range(math.floor(min(ys) / B), math.floor(max(ys) / B) + 1):
            grid.setdefault((gx, gy), []).append(i)

def height(x, y):
    for i in grid.get((math.floor(x / B), math.floor(y / B)), []):
        a, b, c = faces[i]
        d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y)
        l1 = ((b.y - c.y) * (x - c.x) + (c.x - b.x) * (y - c.y)) / d
        l2 = ((c.y - a.y) * (x - c.x) + (a.x - c.x) * (y - c.y)) / d
        l3 = 1.0 - l1 - l2
        if min(l1, l2, l3) >= -1e-9:
            return l1 * a.z + l2 * b.z + l3 * c.z
    return None

msp = labels.modelspace()
boxes = []
numbers = msp.query('TEXT[layer=="CONTOUR_LABELS"]')
assert len(numbers) >= 10, len(numbers)
for t in numbers:
    assert t.dxf.halign == 1 and t.dxf.valign == 2, (t.dxf.halign, t.dxf.valign)
    p = t.dxf.align_point
    h = t.dxf.height
    level = float(t.dxf.text)
    assert abs(level / 2.5 - round(level / 2.5)) < 1e-9, t.dxf.text  # index contours only
    z = height(p.x, p.y)
    assert z is not None, (p.x, p.y)
    assert abs(z - level) < 1e-6, (t.dxf.text, z, p)
    a = math.radians(t.dxf.rotation)
    ux, uy = -math.sin(a), math.cos(a)
    d = 0.1 * h
    up = height(p.x + d * ux, p.y + d * uy)
    down = height(p.x - d * ux, p.y - d * uy)
    assert up > level > down, (t.dxf.text, up, down)
    boxes.append((p.x, p.y, math.cos(a), math.sin(a), len(t.dxf.text) * 0.8 * h / 2, h / 2))
points = msp.query('POINT[layer=="SPOT_HEIGHTS"]')
assert len(points) >= 3, len(points)
for s in points:
    p = s.dxf.location
    assert abs(height(p.x, p.y) - p.z) < 1e-6, p
spot_texts = msp.query('TEXT[layer=="SPOT_LABELS"]')
assert 0 < len(spot_texts) <= len(points)
heights = {'%.2f' % s.dxf.location.z for s in points}
for t in spot_texts:
    assert t.dxf.text in heights, t.dxf.text
    p = t.dxf.align_point
    boxes.append((p.x, p.y, 1.0, 0.0, len(t.dxf.text) * 0.8 * t.dxf.height / 2, t.dxf.height / 2))

def corners(b):
    x, y, cx, cy, hw, hh = b
    return [(x + sx * hw * cx - sy * hh * cy, y + sx * hw * cy + sy * hh * cx)
            for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]

def overlap(p, q):
    for b in (p, q):
        for ax in ((b[2], b[3]), (-b[3], b[2])):
            pa = [u * ax[0] + v * ax[1] for u, v in corners(p)]
            qa = [u * ax[0] + v * ax[1] for u, v in corners(q)]
            if max(pa) <= min(qa) + 1e-9 or max(qa) <= min(pa) + 1e-9:
                return False
    return True

for i in range(len(boxes)):
    for j in range(i + 1, len(boxes)):
        assert not overlap(boxes[i], boxes[j]), (boxes[i], boxes[j])
print(len(numbers), len(points), len(spot_texts))
)py";

TEST(CliContourLabels, DxfLabelsShowTheLevelReadUphillAndDoNotOverlap) {
    if (std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "python3-ezdxf missing";
    }
    const test::ScratchDir dir;
    const auto hill = write_hill(dir).string();
    auto r = test::run_dtm({"tin", hill, "-o", (dir / "tin.dxf").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = test::run_dtm({"contour", hill, "-o", (dir / "c.dxf").string(), "--interval", "0.5",
                       "--spot-heights", "--label-scale", "500", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("labels at 1:500"), std::string::npos) << r.out;
    test::write_file(dir / "check.py", check_script);
    const std::string command = "/usr/bin/python3 '" + (dir / "check.py").string() + "' '" +
                                (dir / "tin.dxf").string() + "' '" + (dir / "c.dxf").string() +
                                "' >'" + (dir / "log").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << test::read_file(dir / "log");
}

TEST(CliContourLabels, GeoPackageHasLabelLayersWithTheirQgisStyles) {
    const test::ScratchDir dir;
    const auto r =
        test::run_dtm({"contour", write_hill(dir).string(), "-o", (dir / "c.gpkg").string(),
                       "--interval", "0.5", "--crs", "EPSG:5514", "--spot-heights", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    GDALAllRegister();
    std::unique_ptr<GDALDataset> ds(static_cast<GDALDataset*>(GDALOpenEx(
        (dir / "c.gpkg").c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    ASSERT_TRUE(ds);
    OGRLayer* labels = ds->GetLayerByName("contour_labels");
    ASSERT_NE(labels, nullptr);
    ASSERT_NE(labels->GetSpatialRef(), nullptr);
    EXPECT_GE(labels->GetFeatureCount(), 10);
    for (auto& f : *labels) {
        const double level = f->GetFieldAsDouble("level");
        EXPECT_DOUBLE_EQ(std::strtod(f->GetFieldAsString("text"), nullptr), level);
        EXPECT_NEAR(std::remainder(level, 2.5), 0.0, 1e-9);
        EXPECT_TRUE(f->IsFieldSetAndNotNull(f->GetFieldIndex("angle")));
    }
    OGRLayer* spots = ds->GetLayerByName("spot_heights");
    ASSERT_NE(spots, nullptr);
    EXPECT_GE(spots->GetFeatureCount(), 3);
    OGRLayer* styles = ds->GetLayerByName("layer_styles");
    ASSERT_NE(styles, nullptr);
    int styled = 0;
    for (auto& f : *styles) {
        const std::string table = f->GetFieldAsString("f_table_name");
        const std::string qml = f->GetFieldAsString("styleQML");
        EXPECT_EQ(f->GetFieldAsInteger("useAsDefault"), 1);
        if (table == "contour_labels") {
            EXPECT_NE(qml.find("LabelRotation"), std::string::npos);
            ++styled;
        }
        if (table == "spot_heights") {
            EXPECT_NE(qml.find("PositionX"), std::string::npos);
            ++styled;
        }
    }
    EXPECT_EQ(styled, 2);
}

TEST(CliContourLabels, SpotHeightsNeedALayeredFormat) {
    const test::ScratchDir dir;
    const auto r = test::run_dtm({"contour", write_hill(dir).string(), "-o",
                                  (dir / "c.shp").string(), "--interval", "1", "--spot-heights"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--spot-heights"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "c.shp"));
}

}  // namespace
