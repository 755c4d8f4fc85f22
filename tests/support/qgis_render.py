# SPDX-License-Identifier: MIT
# Rendering one QGIS layer alone over its extent (QgsMapSettings + QgsMapRendererCustomPainterJob,
# offscreen) and measuring the share of pixels it drew; shared by the PyQGIS checks beside it.
import os

from qgis.core import QgsMapRendererCustomPainterJob, QgsMapSettings
from qgis.PyQt.QtCore import QSize
from qgis.PyQt.QtGui import QColor, QImage, QPainter

BACKGROUND = QColor(255, 0, 255)  # a colour no dtm style uses
SIZE = 200
MIN_DRAWN = {'raster': 0.2, 'mesh': 0.2, 'vector': 0.005}


def drawn_fraction(layer, crs, image_dir=None):
    settings = QgsMapSettings()
    settings.setLayers([layer])
    settings.setDestinationCrs(crs)
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
