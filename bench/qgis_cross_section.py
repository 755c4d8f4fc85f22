# QGIS's native:meshexportcrosssection on a mesh along every line of a layer, for
# bench/compare_volume.sh: prints "<samples> samples seconds <t>" (the time of the processing run).
# Usage: qgis_cross_section.py MESH LINES RESOLUTION OUT_CSV
import os, sys, time
sys.path.append('/usr/share/qgis/python/plugins')
from qgis.core import QgsApplication, QgsMeshLayer, QgsVectorLayer
QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
from processing.core.Processing import Processing
Processing.initialize()
from qgis import processing

mesh_path, lines_path, resolution, out_csv = sys.argv[1:5]
mesh = QgsMeshLayer(mesh_path, 'mesh', 'mdal')
lines = QgsVectorLayer(lines_path, 'lines', 'ogr')
assert mesh.isValid() and lines.isValid()
mesh.setCrs(lines.crs())
start = time.perf_counter()
mesh.updateTriangularMesh()
processing.run('native:meshexportcrosssection', {
    'INPUT': mesh, 'DATASET_GROUPS': [0], 'DATASET_TIME': {'type': 'static'},
    'INPUT_LINES': lines, 'RESOLUTION': float(resolution), 'COORDINATES_DIGITS': 3,
    'DATASET_DIGITS': 3, 'OUTPUT': out_csv})
seconds = time.perf_counter() - start
with open(out_csv) as f:
    samples = sum(1 for _ in f) - 1
print(f'{samples} samples seconds {seconds:.3f}', flush=True)
os._exit(0)
