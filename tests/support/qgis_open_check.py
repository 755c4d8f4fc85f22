# Opens a QGIS project headless with PyQGIS and checks every layer is valid in EPSG:5514, as is
# the project CRS; then renders each layer alone over its own extent (QgsMapSettings +
# QgsMapRendererCustomPainterJob, offscreen) and checks that it drew: a share of the pixels
# differs from the background (rasters and meshes 20 %, lines 0.5 %). The DEM (raster), contours
# (vector) and mesh layers must be there.
# Usage: qgis_open_check.py PROJECT.qgs [IMAGE_DIR]. Exit 0 when all hold.
# Used by tests/cli/qgis_open_test.cpp (QT_QPA_PLATFORM=offscreen, Debian's /usr/bin/python3).
import os
import sys
from qgis.core import QgsApplication, QgsProject

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from qgis_render import MIN_DRAWN, drawn_fraction  # noqa: E402

QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
p = QgsProject.instance()
ok = p.read(sys.argv[1])
image_dir = sys.argv[2] if len(sys.argv) > 2 else None
project_crs = p.crs().authid()
print('read', ok, 'project crs', project_crs)
bad = 0
kinds = set()
for lid, layer in p.mapLayers().items():
    valid = layer.isValid() and layer.crs().authid() == 'EPSG:5514'
    fraction = drawn_fraction(layer, p.crs(), image_dir) if layer.isValid() else 0.0
    kind = {'gdal': 'raster', 'ogr': 'vector', 'mdal': 'mesh'}.get(layer.providerType(), '?')
    print(f'{layer.name():20s} {layer.providerType():6s} valid={layer.isValid()} '
          f'crs={layer.crs().authid()} drawn={100 * fraction:.1f}% of its extent')
    if valid and fraction >= MIN_DRAWN.get(kind, 1.0):
        kinds.add(kind)
    else:
        bad += 1
missing = {'raster', 'vector', 'mesh'} - kinds
if missing:
    print('no layer drew of the kinds', sorted(missing))
app.exitQgis()
sys.exit(1 if bad or missing or not ok or project_crs != 'EPSG:5514' else 0)
