# Opens a QGIS project headless with PyQGIS and checks every layer is valid in EPSG:5514, as is
# the project CRS; then renders each layer alone over its own extent (QgsMapSettings +
# QgsMapRendererCustomPainterJob, offscreen) and checks that it drew: a share of the pixels
# differs from the background (rasters and meshes 20 %, lines 0.5 %). The DEM (raster), contours
# (vector) and mesh layers must be there.
# Usage: qgis_open_check.py PROJECT.qgs [IMAGE_DIR]. Exit 0 when all hold.
# Used by tests/cli/qgis_open_test.cpp (QT_QPA_PLATFORM=offscreen, Debian's /usr/bin/python3).
import os
import sys
from qgis.core import (QgsApplication, QgsMapRendererCustomPainterJob, QgsMapSettings,
                       QgsProject)
from qgis.PyQt.QtCore import QSize
from qgis.PyQt.QtGui import QColor, QImage, QPainter

QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
p = QgsProject.instance()
ok = p.read(sys.argv[1])
image_dir = sys.argv[2] if len(sys.argv) > 2 else None
project_crs = p.crs().authid()
print('read', ok, 'project crs', project_crs)
BACKGROUND = QColor(255, 0, 255)  # a colour no dtm style uses
SIZE = 200
MIN_DRAWN = {'raster': 0.2, 'mesh': 0.2, 'vector': 0.005}


def drawn_fraction(layer):
    settings = QgsMapSettings()
    settings.setLayers([layer])
    settings.setDestinationCrs(p.crs())
    settings.setBackgroundColor(BACKGROUND)
    settings.setOutputSize(QSize(SIZE, SIZE))
    settings.setExtent(settings.layerExtentToOutputExtent(layer, layer.extent()))
    image = QImage(QSize(SIZE, SIZE), QImage.Format_ARGB32)
    image.fill(BACKGROUND)
    painter = QPainter(image)
    job = QgsMapRendererCustomPainterJob(settings, painter)
    job.start()
    job.waitForFinished()
    painter.end()
    if image_dir:
        image.save(os.path.join(image_dir, layer.name() + '.png'))
    background = BACKGROUND.rgb()
    drawn = sum(1 for y in range(SIZE) for x in range(SIZE) if image.pixel(x, y) != background)
    return drawn / (SIZE * SIZE)


bad = 0
kinds = set()
for lid, layer in p.mapLayers().items():
    valid = layer.isValid() and layer.crs().authid() == 'EPSG:5514'
    fraction = drawn_fraction(layer) if layer.isValid() else 0.0
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
