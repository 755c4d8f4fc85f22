# Reads a QGIS project headless with PyQGIS and prints its print layout "Map sheet" as QGIS
# understood it: page size, the map item's scale, extent and CRS, the grid, the items linked to
# the map. Used by tests/cli/qgis_open_test.cpp; exit 1 when the layout or its map is missing.
import sys
from qgis.core import (QgsApplication, QgsProject, QgsLayoutItemMap, QgsLayoutItemScaleBar,
                       QgsLayoutItemLegend, QgsLayoutItemLabel, QgsLayoutItemPicture)
QgsApplication.setPrefixPath('/usr', True)
app = QgsApplication([], False)
app.initQgis()
p = QgsProject.instance()
ok = p.read(sys.argv[1])
layout = p.layoutManager().layoutByName('Map sheet')
if not ok or layout is None:
    print('no layout')
    sys.exit(1)
page = layout.pageCollection().page(0).pageSize()
print(f'page {page.width():.3f} {page.height():.3f}')
maps = [i for i in layout.items() if isinstance(i, QgsLayoutItemMap)]
if not maps:
    print('no map item')
    sys.exit(1)
m = maps[0]
e = m.extent()
print(f'scale {m.scale():.3f}')
print(f'extent {e.xMinimum():.3f} {e.yMinimum():.3f} {e.xMaximum():.3f} {e.yMaximum():.3f}')
print(f'crs {m.crs().authid()}')
g = m.grids().asList()[0] if m.grids().size() else None
print(f'grid {m.grids().size()} {g.intervalX() if g else 0}')
for cls, name in ((QgsLayoutItemScaleBar, 'scalebar'), (QgsLayoutItemLegend, 'legend'),
                  (QgsLayoutItemPicture, 'picture'), (QgsLayoutItemLabel, 'label')):
    items = [i for i in layout.items() if isinstance(i, cls)]
    linked = [i for i in items if hasattr(i, 'linkedMap') and i.linkedMap() is m]
    print(f'{name} {len(items)} linked {len(linked)}')
labels = [i for i in layout.items() if isinstance(i, QgsLayoutItemLabel)]
if labels:
    print('title ' + labels[0].text().split('\n')[0])
app.exitQgis()
