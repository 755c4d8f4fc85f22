# SPDX-License-Identifier: MIT
# QGIS's native:rastersurfacevolume on dtm's difference rasters, finest cell last, against dtm's
# exact fill and cut: prints each relative error (the larger of fill's and cut's) and exits 1
# unless the finest cell's error is below BOUND, below every coarser cell's, and under a tenth of
# the coarsest's (the midpoint rule's error is not monotone from one cell size to the next).
#   qgis_volume_check.py FILL CUT BOUND RASTER...
import os
import sys

sys.path.append('/usr/share/qgis/python/plugins')
from qgis.core import QgsApplication, QgsRasterLayer

QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
from processing.core.Processing import Processing

Processing.initialize()
from qgis import processing

fill, cut, bound = (float(a) for a in sys.argv[1:4])
errors = []
for path in sys.argv[4:]:
    layer = QgsRasterLayer(path, 'difference')
    if not layer.isValid():
        print(f'{path}: QGIS cannot open it')
        os._exit(1)
    volumes = [abs(processing.run('native:rastersurfacevolume', {
        'INPUT': layer, 'BAND': 1, 'LEVEL': 0, 'METHOD': method,
        'OUTPUT_TABLE': 'TEMPORARY_OUTPUT'})['VOLUME']) for method in (0, 1)]
    error = max(abs(volumes[0] - fill) / fill, abs(volumes[1] - cut) / cut)
    print(f'{path}: QGIS fill {volumes[0]:.6f} cut {volumes[1]:.6f} relative error {error:.3e}')
    errors.append(error)
ok = errors[-1] < bound and errors[-1] < min(errors[:-1]) and 10 * errors[-1] < errors[0]
print('converges' if ok else f'does not converge below {bound:g}')
sys.stdout.flush()
os._exit(0 if ok else 1)
