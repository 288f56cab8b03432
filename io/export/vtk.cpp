#include "io/export/vtk.h"

#include "io/base/atomic_file.h"
#include "io/formats/specimen_vtp.h"

#include <filesystem>

namespace clumpkit {

std::vector<std::string> write_vtk_export(const std::vector<SpecimenBody>& bodies,
                                          const std::string& dir) {
  const std::filesystem::path d(dir);
  const std::string vtp = (d / "specimen.vtp").string();
  write_specimen_vtp(vtp, bodies);
  const std::string script = (d / "glyph_clumpkit.py").string();
  write_file_atomically(script, [](std::ostream& o) {
    o << R"py(# clumpkit export for ParaView/VTK (python3-vtk9 9.1 or ParaView's pvpython).
# specimen.vtp holds one point per sphere centre with point arrays radius (m), body (the id of
# specimen.csv), kind (1 rock, 0 soil) and zone (region of a zoned specimen). This script makes the spheres ParaView's Glyph filter
# makes (Glyph Type Sphere of radius 0.5, Scale Array radius, Scale Factor 2, all points) and
# writes them as spheres.vtp, a surface coloured by body. In the ParaView GUI: open specimen.vtp,
# Filters > Glyph with those settings, colour by body.
import sys

try:
    from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
    from vtkmodules.vtkFiltersCore import vtkGlyph3D
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
except ImportError:  # python3-vtk9 of Debian 12 ships the monolithic module
    from vtk import (vtkAlgorithm, vtkGlyph3D, vtkSphereSource, vtkXMLPolyDataReader,
                     vtkXMLPolyDataWriter)

reader = vtkXMLPolyDataReader()
reader.SetFileName("specimen.vtp")
reader.Update()
cloud = reader.GetOutput()
arrays = [cloud.GetPointData().GetArrayName(i)
          for i in range(cloud.GetPointData().GetNumberOfArrays())]
for name in ("radius", "body", "kind"):
    if name not in arrays:
        sys.exit("specimen.vtp: point array '%s' missing (found %s)" % (name, arrays))
cloud.GetPointData().SetActiveScalars("radius")

sphere = vtkSphereSource()
sphere.SetRadius(0.5)
sphere.SetThetaResolution(24)  # 15 degree steps, so the vertices reach each axis extreme
sphere.SetPhiResolution(13)
sphere.SetOutputPointsPrecision(vtkAlgorithm.DOUBLE_PRECISION)
glyph = vtkGlyph3D()
glyph.SetInputData(cloud)
glyph.SetSourceConnection(sphere.GetOutputPort())
glyph.SetScaleModeToScaleByScalar()
glyph.SetScaleFactor(2.0)
glyph.SetColorModeToColorByScalar()
glyph.OrientOff()
glyph.SetOutputPointsPrecision(vtkAlgorithm.DOUBLE_PRECISION)
glyph.Update()

writer = vtkXMLPolyDataWriter()
writer.SetFileName("spheres.vtp")
writer.SetInputConnection(glyph.GetOutputPort())
writer.Write()
b = glyph.GetOutput().GetBounds()
print("points %d arrays %s" % (cloud.GetNumberOfPoints(), " ".join(arrays)))
print("bounds %.17g %.17g %.17g %.17g %.17g %.17g" % b)
)py";
  });
  return {vtp, script};
}

}  // namespace clumpkit
