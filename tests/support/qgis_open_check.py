# Opens a QGIS project headless with PyQGIS and checks every layer is valid in EPSG:5514, as
# is the project CRS. Exit 0 when all are; used by tests/cli/qgis_open_test.cpp when PyQGIS exists.
import sys
from qgis.core import QgsApplication, QgsProject
QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
p = QgsProject.instance()
ok = p.read(sys.argv[1])
project_crs = p.crs().authid()
print('read', ok, 'project crs', project_crs)
bad = 0
for lid, layer in p.mapLayers().items():
    print(f'{layer.name():20s} {layer.providerType():6s} valid={layer.isValid()} crs={layer.crs().authid()}')
    bad += 0 if layer.isValid() and layer.crs().authid() == 'EPSG:5514' else 1
app.exitQgis()
sys.exit(1 if bad or not ok or project_crs != "EPSG:5514" else 0)
