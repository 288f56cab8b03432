#include "io/formats/specimen_vtp.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"

namespace clumpkit {

void write_specimen_vtp(const std::string& path, const std::vector<SpecimenBody>& bodies,
                        const std::vector<BodyLabels>& labels) {
  for (const BodyLabels& l : labels)
    if (l.values.size() != bodies.size())
      throw InvalidInput(path + ": labels '" + l.name + "' has " + std::to_string(l.values.size()) +
                         " values for " + std::to_string(bodies.size()) + " bodies");
  write_file_atomically(path, [&](std::ostream& o) {
    std::size_t n = 0;
    for (const SpecimenBody& b : bodies) n += b.spheres.size();
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\""
      << n << "\" NumberOfVerts=\"" << n << "\">\n<Points>\n"
      << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (const Sphere& s : b.spheres)
        o << format_number(s.center.x()) << " " << format_number(s.center.y()) << " "
          << format_number(s.center.z()) << "\n";
    o << "</DataArray>\n</Points>\n<PointData Scalars=\"radius\">\n"
      << "<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (const Sphere& s : b.spheres) o << format_number(s.radius) << "\n";
    o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (std::size_t s = 0; s < b.spheres.size(); ++s) o << b.id << "\n";
    o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"kind\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (std::size_t s = 0; s < b.spheres.size(); ++s)
        o << (b.kind == dem::BodyKind::rock ? 1 : 0) << "\n";
    o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"zone\" format=\"ascii\">\n";
    for (const SpecimenBody& b : bodies)
      for (std::size_t s = 0; s < b.spheres.size(); ++s) o << b.zone << "\n";
    o << "</DataArray>\n";
    for (const BodyLabels& l : labels) {
      o << "<DataArray type=\"Int32\" Name=\"" << l.name << "\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < bodies.size(); ++k)
        for (std::size_t s = 0; s < bodies[k].spheres.size(); ++s) o << l.values[k] << "\n";
      o << "</DataArray>\n";
    }
    o << "</PointData>\n<Verts>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < n; ++k) o << k << "\n";
    o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < n; ++k) o << k + 1 << "\n";
    o << "</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  });
}

}  // namespace clumpkit
