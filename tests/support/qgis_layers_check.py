# SPDX-License-Identifier: MIT
# Opens files as QGIS layers headless (PyQGIS) and checks each is valid in EPSG:5514 and draws
# over its extent (qgis_render.py); a vector layer must hold features. Arguments: KIND:PATH with
# KIND raster or vector (a GDAL VRT of DEM tiles, an OGR VRT of contour pieces, ...).
# Usage: qgis_layers_check.py raster:dem.vrt vector:contours.vrt. Exit 0 when all hold.
# Used by tests/cli/qgis_open_test.cpp (QT_QPA_PLATFORM=offscreen, Debian's /usr/bin/python3).
import os
import sys

from qgis.core import (QgsApplication, QgsCoordinateReferenceSystem, QgsRasterLayer,
                       QgsVectorLayer)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from qgis_render import MIN_DRAWN, drawn_fraction  # noqa: E402

QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
crs = QgsCoordinateReferenceSystem('EPSG:5514')
bad = 0
for argument in sys.argv[1:]:
    kind, path = argument.split(':', 1)
    name = os.path.basename(path)
    layer = QgsRasterLayer(path, name, 'gdal') if kind == 'raster' else QgsVectorLayer(path, name, 'ogr')
    fraction = drawn_fraction(layer, crs) if layer.isValid() else 0.0
    features = layer.featureCount() if kind == 'vector' and layer.isValid() else None
    print(f'{name:20s} {kind:6s} valid={layer.isValid()} crs={layer.crs().authid()} '
          f'drawn={100 * fraction:.1f}% features={features}')
    if not (layer.isValid() and layer.crs().authid() == 'EPSG:5514' and fraction >= MIN_DRAWN[kind]
            and (features is None or features > 0)):
        bad += 1
    del layer  # before exitQgis: a layer outliving its providers crashes at exit
app.exitQgis()
sys.exit(1 if bad or len(sys.argv) < 2 else 0)
