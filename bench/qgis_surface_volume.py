# QGIS's native:rastersurfacevolume on difference DEMs, for bench/compare_volume.sh: for each
# raster given, the volume above and below level 0 (methods 0 and 1) and the time QGIS took.
# Prints one line per raster: "<path> fill <v> cut <v> seconds <t>".
import os, sys, time
sys.path.append('/usr/share/qgis/python/plugins')
from qgis.core import QgsApplication, QgsRasterLayer
QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
from processing.core.Processing import Processing
Processing.initialize()
from qgis import processing

for path in sys.argv[1:]:
    layer = QgsRasterLayer(path, 'difference')
    assert layer.isValid(), path
    start = time.perf_counter()
    fill = processing.run('native:rastersurfacevolume', {
        'INPUT': layer, 'BAND': 1, 'LEVEL': 0, 'METHOD': 0,
        'OUTPUT_TABLE': 'TEMPORARY_OUTPUT'})['VOLUME']
    cut = processing.run('native:rastersurfacevolume', {
        'INPUT': layer, 'BAND': 1, 'LEVEL': 0, 'METHOD': 1,
        'OUTPUT_TABLE': 'TEMPORARY_OUTPUT'})['VOLUME']
    seconds = time.perf_counter() - start
    print(f'{path} fill {abs(fill):.6f} cut {abs(cut):.6f} seconds {seconds:.3f}', flush=True)
os._exit(0)
