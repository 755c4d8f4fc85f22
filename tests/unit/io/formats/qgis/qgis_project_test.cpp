// SPDX-License-Identifier: MIT
// The QGIS project is checked structurally (QGIS itself is not installed): parsed with GDAL's XML
// parser and walked the way QgsProject reads it.
#include "dtm/io/formats/qgis_project.hpp"

#include <cpl_minixml.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace {

struct XmlFree {
    void operator()(CPLXMLNode* node) const { CPLDestroyXMLNode(node); }
};
using Xml = std::unique_ptr<CPLXMLNode, XmlFree>;

std::string value_of(const CPLXMLNode* node, const char* path) {
    const char* value = CPLGetXMLValue(const_cast<CPLXMLNode*>(node), path, nullptr);
    return value != nullptr ? value : "";
}

std::vector<const CPLXMLNode*> children(const CPLXMLNode* node, std::string_view name) {
    std::vector<const CPLXMLNode*> out;
    for (const CPLXMLNode* c = node != nullptr ? node->psChild : nullptr; c != nullptr;
         c = c->psNext) {
        if (c->eType == CXT_Element && name == c->pszValue) {
            out.push_back(c);
        }
    }
    return out;
}

std::string epsg_wkt(int code) {
    OGRSpatialReference srs;
    srs.importFromEPSG(code);
    char* wkt = nullptr;
    srs.exportToWkt(&wkt);
    std::string text(wkt);
    CPLFree(wkt);
    return text;
}

dtm::io::QgisProject sample_project() {
    dtm::io::QgisProject project;
    project.title = "Site <A> & B";
    project.crs_wkt = epsg_wkt(5514);
    project.extent = dtm::Box2{-750300.0, -1050200.0, -750050.0, -1050020.0};
    project.z_min = 310.0;
    project.z_max = 330.0;
    project.dem = "dem.tif";
    project.hillshade = "hillshade.tif";
    project.contours = "contours.gpkg";
    project.contour_layer = "contours";
    project.index_field = "index";
    project.index_interval = 2.5;
    project.mesh = "tin.2dm";
    return project;
}

class QgisProjectXml : public ::testing::Test {
protected:
    void SetUp() override {
        text_ = dtm::io::qgis_project_xml(sample_project());
        doc_.reset(CPLParseXMLString(text_.c_str()));
        ASSERT_TRUE(doc_) << "not well-formed XML";
        root_ = CPLGetXMLNode(doc_.get(), "=qgis");
        ASSERT_NE(root_, nullptr);
        for (const CPLXMLNode* layer :
             children(CPLGetXMLNode(root_, "projectlayers"), "maplayer")) {
            layers_[value_of(layer, "id")] = layer;
        }
    }
    std::string text_;
    Xml doc_;
    const CPLXMLNode* root_ = nullptr;
    std::map<std::string, const CPLXMLNode*> layers_;
};

TEST_F(QgisProjectXml, ProjectCrsIsEpsg5514WithParsableWkt) {
    EXPECT_EQ(value_of(root_, "projectCrs.spatialrefsys.authid"), "EPSG:5514");
    OGRSpatialReference srs;
    ASSERT_EQ(srs.SetFromUserInput(value_of(root_, "projectCrs.spatialrefsys.wkt").c_str()),
              OGRERR_NONE);
    EXPECT_STREQ(srs.GetAuthorityCode(nullptr), "5514");
    EXPECT_EQ(value_of(root_, "projectCrs.spatialrefsys.ellipsoidacronym"), "EPSG:7004");
    EXPECT_EQ(value_of(root_, "title"), "Site <A> & B");  // escaped and read back
    EXPECT_EQ(value_of(root_, "properties.Paths.Absolute"), "false");
}

TEST_F(QgisProjectXml, EveryTreeLayerHasAMapLayerWithSourceProviderAndCrs) {
    const auto tree = children(CPLGetXMLNode(root_, "layer-tree-group"), "layer-tree-layer");
    ASSERT_EQ(tree.size(), 4u);
    ASSERT_EQ(layers_.size(), 4u);
    const std::map<std::string, std::pair<std::string, std::string>> expected{
        {"Contours", {"ogr", "./contours.gpkg|layername=contours"}},
        {"TIN (mesh)", {"mdal", "./tin.2dm"}},
        {"DEM", {"gdal", "./dem.tif"}},
        {"Hillshade", {"gdal", "./hillshade.tif"}}};
    for (const CPLXMLNode* entry : tree) {
        const std::string id = value_of(entry, "id");
        ASSERT_EQ(layers_.count(id), 1u) << id;
        const CPLXMLNode* layer = layers_[id];
        const std::string name = value_of(layer, "layername");
        ASSERT_EQ(expected.count(name), 1u) << name;
        EXPECT_EQ(value_of(layer, "provider"), expected.at(name).first) << name;
        EXPECT_EQ(value_of(entry, "providerKey"), expected.at(name).first) << name;
        EXPECT_EQ(value_of(layer, "datasource"), expected.at(name).second) << name;
        EXPECT_EQ(value_of(layer, "srs.spatialrefsys.authid"), "EPSG:5514") << name;
        EXPECT_FALSE(value_of(layer, "srs.spatialrefsys.wkt").empty()) << name;
    }
    // Drawing order: contours on top, the hillshade at the bottom beneath the DEM.
    EXPECT_EQ(value_of(tree.front(), "name"), "Contours");
    EXPECT_EQ(value_of(tree.back(), "name"), "Hillshade");
}

TEST_F(QgisProjectXml, DemIsTerrainRampMultipliedOverHillshade) {
    const CPLXMLNode* dem = layers_.at("dtm_dem_layer");
    EXPECT_EQ(value_of(dem, "type"), "raster");
    const CPLXMLNode* renderer = CPLGetXMLNode(const_cast<CPLXMLNode*>(dem), "pipe.rasterrenderer");
    ASSERT_NE(renderer, nullptr);
    EXPECT_EQ(value_of(renderer, "type"), "singlebandpseudocolor");
    EXPECT_EQ(value_of(dem, "blendMode"), "6");  // QgsPainting::BlendMultiply
    const auto items = children(
        CPLGetXMLNode(const_cast<CPLXMLNode*>(renderer), "rastershader.colorrampshader"), "item");
    ASSERT_GE(items.size(), 3u);
    EXPECT_DOUBLE_EQ(std::stod(value_of(items.front(), "value")), 310.0);
    EXPECT_DOUBLE_EQ(std::stod(value_of(items.back(), "value")), 330.0);
    for (std::size_t i = 1; i < items.size(); ++i) {
        EXPECT_LT(std::stod(value_of(items[i - 1], "value")),
                  std::stod(value_of(items[i], "value")));
    }
    const CPLXMLNode* hillshade = layers_.at("dtm_hillshade_layer");
    EXPECT_EQ(value_of(hillshade, "pipe.rasterrenderer.type"), "singlebandgray");
}

TEST_F(QgisProjectXml, ContoursAreLabelledByElevationWithIndexContoursEmphasised) {
    const CPLXMLNode* contours = layers_.at("dtm_contours_layer");
    EXPECT_EQ(value_of(contours, "type"), "vector");
    EXPECT_EQ(value_of(contours, "labeling.type"), "simple");
    EXPECT_EQ(value_of(contours, "labeling.settings.text-style.fieldName"), "elevation");
    EXPECT_EQ(value_of(contours, "labelsEnabled"), "1");

    const CPLXMLNode* renderer = CPLGetXMLNode(const_cast<CPLXMLNode*>(contours), "renderer-v2");
    ASSERT_NE(renderer, nullptr);
    EXPECT_EQ(value_of(renderer, "type"), "RuleRenderer");
    const auto rules = children(CPLGetXMLNode(const_cast<CPLXMLNode*>(renderer), "rules"), "rule");
    ASSERT_EQ(rules.size(), 2u);
    EXPECT_EQ(value_of(rules[0], "filter"), "\"index\"");
    EXPECT_EQ(value_of(rules[1], "filter"), "ELSE");

    std::map<std::string, double> widths;
    for (const CPLXMLNode* symbol :
         children(CPLGetXMLNode(const_cast<CPLXMLNode*>(renderer), "symbols"), "symbol")) {
        for (const CPLXMLNode* prop :
             children(CPLGetXMLNode(const_cast<CPLXMLNode*>(symbol), "layer"), "prop")) {
            if (value_of(prop, "k") == "line_width") {
                widths[value_of(symbol, "name")] = std::stod(value_of(prop, "v"));
            }
        }
    }
    ASSERT_EQ(widths.size(), 2u);
    EXPECT_GT(widths.at(value_of(rules[0], "symbol")),
              2.0 * widths.at(value_of(rules[1], "symbol")));
}

TEST_F(QgisProjectXml, MeshLayerUsesMdalProvider) {
    const CPLXMLNode* mesh = layers_.at("dtm_tin_mesh_layer");
    EXPECT_EQ(value_of(mesh, "type"), "mesh");
    EXPECT_EQ(value_of(mesh, "provider"), "mdal");
    EXPECT_NE(CPLGetXMLNode(const_cast<CPLXMLNode*>(mesh), "mesh-renderer-settings"), nullptr);
}

TEST(QgisProject, WithoutIndexFieldIndexContoursAreRecognisedFromElevation) {
    dtm::io::QgisProject project = sample_project();
    project.index_field.clear();
    project.index_interval = 5.0;
    const std::string text = dtm::io::qgis_project_xml(project);
    EXPECT_NE(text.find("abs(&quot;elevation&quot; / 5 - round(&quot;elevation&quot; / 5))"),
              std::string::npos);
}

TEST(QgisProject, Wkt2InputIsIdentifiedAsEpsg5514) {
    OGRSpatialReference srs;
    srs.importFromEPSG(5514);
    char* wkt = nullptr;
    const char* options[] = {"FORMAT=WKT2_2018", nullptr};
    srs.exportToWkt(&wkt, options);
    dtm::io::QgisProject project;
    project.crs_wkt = wkt;
    CPLFree(wkt);
    project.dem = "dem.tif";
    Xml doc(CPLParseXMLString(dtm::io::qgis_project_xml(project).c_str()));
    ASSERT_TRUE(doc);
    const CPLXMLNode* root = CPLGetXMLNode(doc.get(), "=qgis");
    EXPECT_EQ(value_of(root, "projectCrs.spatialrefsys.authid"), "EPSG:5514");
    EXPECT_EQ(value_of(root, "projectCrs.spatialrefsys.ellipsoidacronym"), "EPSG:7004");
    EXPECT_EQ(value_of(root, "projectCrs.spatialrefsys.projectionacronym"), "krovak");
}

TEST(QgisProject, OnlyRequestedLayersAreWritten) {
    dtm::io::QgisProject project;
    project.crs_wkt = epsg_wkt(5514);
    project.dem = "dem.tif";
    Xml doc(CPLParseXMLString(dtm::io::qgis_project_xml(project).c_str()));
    ASSERT_TRUE(doc);
    const CPLXMLNode* root = CPLGetXMLNode(doc.get(), "=qgis");
    EXPECT_EQ(
        children(CPLGetXMLNode(const_cast<CPLXMLNode*>(root), "projectlayers"), "maplayer").size(),
        1u);
}

TEST(QgisProject, PrintLayoutHoldsTheSheetWithItsMapAndFurniture) {
    dtm::io::QgisProject project = sample_project();
    EXPECT_EQ(dtm::io::qgis_project_xml(project).find("<Layouts>"), std::string::npos);
    dtm::io::QgisLayout layout;
    layout.width_mm = 400.0;
    layout.height_mm = 280.0;
    layout.extent = {-744400.0, -1045340.0, -744200.0, -1045200.0};
    layout.scale = 500.0;
    layout.grid_interval = 50.0;
    layout.sjtsk = true;
    layout.title = "Horní Lhota";
    layout.fields = {{"Scale", "1 : 500"}};
    layout.title_box = {300.0, 230.0, 90.0, 40.0};
    project.layout = layout;
    Xml doc(CPLParseXMLString(dtm::io::qgis_project_xml(project).c_str()));
    ASSERT_TRUE(doc);
    CPLXMLNode* l = CPLGetXMLNode(doc.get(), "=qgis.Layouts.Layout");
    ASSERT_NE(l, nullptr);
    EXPECT_STREQ(CPLGetXMLValue(l, "name", ""), "Map sheet");
    EXPECT_STREQ(CPLGetXMLValue(l, "PageCollection.LayoutItem.size", ""), "400,280,mm");
    std::map<std::string, const CPLXMLNode*> items;
    for (const CPLXMLNode* item : children(l, "LayoutItem")) {
        items[CPLGetXMLValue(item, "type", "")] = item;
    }
    ASSERT_EQ(items.count("65639"), 1u);  // map
    const CPLXMLNode* map = items["65639"];
    EXPECT_STREQ(CPLGetXMLValue(map, "Extent.xmin", ""), "-744400");
    EXPECT_STREQ(CPLGetXMLValue(map, "Extent.ymax", ""), "-1045200");
    EXPECT_STREQ(CPLGetXMLValue(map, "crs.spatialrefsys.authid", ""), "EPSG:5514");
    EXPECT_STREQ(CPLGetXMLValue(map, "ComposerMapGrid.intervalX", ""), "50");
    EXPECT_NE(std::string(CPLGetXMLValue(map, "ComposerMapGrid.annotationExpression", ""))
                  .find("'Y ' || format_number(-@grid_number"),
              std::string::npos);
    const std::string uuid = CPLGetXMLValue(map, "uuid", "");
    for (const char* type : {"65640", "65646"}) {  // north arrow, scale bar
        ASSERT_EQ(items.count(type), 1u) << type;
        EXPECT_EQ(CPLGetXMLValue(items[type], "mapUuid", ""), uuid) << type;
    }
    ASSERT_EQ(items.count("65642"), 1u);  // legend
    EXPECT_EQ(CPLGetXMLValue(items["65642"], "map_uuid", ""), uuid);
    ASSERT_EQ(items.count("65641"), 1u);  // title block
    EXPECT_NE(std::string(CPLGetXMLValue(items["65641"], "labelText", "")).find("Horní Lhota"),
              std::string::npos);
    EXPECT_STREQ(CPLGetXMLValue(items["65641"], "position", ""), "300,230,mm");
}

TEST(QgisProject, WriteCreatesTheFile) {
    dtm::test::ScratchDir dir;
    dtm::io::write_qgis_project(sample_project(), dir / "dtm.qgs");
    const std::string text = dtm::test::read_file(dir / "dtm.qgs");
    EXPECT_EQ(text.rfind("<!DOCTYPE qgis", 0), 0u);
}

}  // namespace
