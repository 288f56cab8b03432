#include "io/formats/clump_vtp.h"

#include "geom/format.h"
#include "io/base/atomic_file.h"

#include <ostream>

namespace clumpkit {

void write_clump_vtp(const std::string& path, const Mesh& mesh, const Clump& clump) {
  write_file_atomically(path, [&](std::ostream& o) {
    const std::size_t nv = mesh.vertices.size(), ns = clump.spheres.size();
    const std::size_t nt = mesh.triangles.size();
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\""
      << nv + ns << "\" NumberOfVerts=\"" << ns << "\" NumberOfPolys=\"" << nt
      << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    auto point = [&](const Vec3& p) {
      o << format_number(p.x()) << " " << format_number(p.y()) << " " << format_number(p.z())
        << "\n";
    };
    for (const Vec3& v : mesh.vertices) point(v);
    for (const Sphere& s : clump.spheres) point(s.center);
    o << "</DataArray>\n</Points>\n<PointData Scalars=\"radius\">\n";
    for (const double factor : {1.0, 2.0}) {
      o << "<DataArray type=\"Float64\" Name=\"" << (factor == 1.0 ? "radius" : "diameter")
        << "\" format=\"ascii\">\n";
      for (std::size_t k = 0; k < nv; ++k) o << "0\n";
      for (const Sphere& s : clump.spheres) o << format_number(factor * s.radius) << "\n";
      o << "</DataArray>\n";
    }
    o << "<DataArray type=\"Int32\" Name=\"sphere\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < nv; ++k) o << "-1\n";
    for (std::size_t k = 0; k < ns; ++k) o << k << "\n";
    o << "</DataArray>\n</PointData>\n<Verts>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < ns; ++k) o << nv + k << "\n";
    o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < ns; ++k) o << k + 1 << "\n";
    o << "</DataArray>\n</Verts>\n<Polys>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : mesh.triangles) o << t[0] << " " << t[1] << " " << t[2] << "\n";
    o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t k = 0; k < nt; ++k) o << 3 * (k + 1) << "\n";
    o << "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  });
}

}  // namespace clumpkit
