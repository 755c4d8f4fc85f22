# Runs QGIS's native:meshexportcrosssection on a mesh (a dtm tin.2dm) along the lines of a layer
# and compares its samples with dtm profile's breakpoints (profile.csv) interpolated at the same
# offsets. Usage: qgis_profile_check.py MESH LINES PROFILE_CSV SURFACE RESOLUTION OUT_CSV
# Exit 0 when every sample QGIS has lies within 1e-6 of dtm's profile (and dtm has a height
# wherever QGIS has one); prints the largest difference and the sample count.
import bisect, csv, os, sys
sys.path.append('/usr/share/qgis/python/plugins')
from qgis.core import QgsApplication, QgsMeshLayer, QgsVectorLayer
QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
from processing.core.Processing import Processing
Processing.initialize()
from qgis import processing

mesh_path, lines_path, profile_csv, surface, resolution, out_csv = sys.argv[1:7]
mesh = QgsMeshLayer(mesh_path, 'mesh', 'mdal')
lines = QgsVectorLayer(lines_path, 'lines', 'ogr')
assert mesh.isValid() and lines.isValid()
mesh.setCrs(lines.crs())
mesh.updateTriangularMesh()
processing.run('native:meshexportcrosssection', {
    'INPUT': mesh, 'DATASET_GROUPS': [0], 'DATASET_TIME': {'type': 'static'}, 'INPUT_LINES': lines, 'RESOLUTION': float(resolution),
    'COORDINATES_DIGITS': 8, 'DATASET_DIGITS': 9, 'OUTPUT': out_csv})

runs = {}  # line -> list of runs (lists of (chainage, z))
with open(profile_csv) as f:
    for row in csv.DictReader(f):
        if row['surface'] != surface:
            continue
        line = int(row['line'])
        run = int(row['run'])
        runs.setdefault(line, {}).setdefault(run, []).append((float(row['chainage']), float(row['z'])))

def dtm_height(line, c):
    for pts in runs.get(line, {}).values():
        cs = [p[0] for p in pts]
        if cs[0] - 1e-6 <= c <= cs[-1] + 1e-6:
            i = min(max(bisect.bisect_left(cs, c), 1), len(cs) - 1)
            (c0, z0), (c1, z1) = pts[i - 1], pts[i]
            return z0 if c1 == c0 else z0 + (c - c0) / (c1 - c0) * (z1 - z0)
    return None

worst, samples, missing = 0.0, 0, 0
with open(out_csv) as f:
    reader = csv.reader(f)
    header = next(reader)
    for row in reader:
        if len(row) < 5 or row[4].strip() == '':
            continue
        line = int(float(row[0])) + 1  # QGIS numbers features from 0, dtm lines from 1
        ours = dtm_height(line, float(row[3]))
        if ours is None:
            missing += 1
            continue
        samples += 1
        worst = max(worst, abs(ours - float(row[4])))
print('header', header, 'samples', samples, 'missing', missing, 'max difference', worst)
sys.stdout.flush()
# Leave without QGIS's teardown, which can crash after processing runs headless.
os._exit(0 if samples > 0 and missing == 0 and worst < 1e-6 else 1)
