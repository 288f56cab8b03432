#include "io/export/lammps_import.h"

#include "geom/errors.h"
#include "io/export/engine_settings.h"

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace clumpkit {

namespace fs = std::filesystem;

std::string final_lammps_dump(const std::string& run_dir) {
  const fs::path dir(run_dir);
  if (!fs::is_directory(dir))
    throw InvalidInput(run_dir +
                       ": not a directory (import reads the run directory of an "
                       "exported deck)");
  if (fs::exists(dir / "atoms.final.txt")) return (dir / "atoms.final.txt").string();
  long best = -1;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("atoms.", 0) != 0 || name.size() < 11 || name.substr(name.size() - 4) != ".txt")
      continue;
    const std::string step = name.substr(6, name.size() - 10);
    if (step.empty() || step.find_first_not_of("0123456789") != std::string::npos) continue;
    best = std::max(best, std::stol(step));
  }
  if (best < 0)
    throw InvalidInput(run_dir + ": no atoms.STEP.txt dump (run the deck in.clumpkit there first)");
  return (dir / ("atoms." + std::to_string(best) + ".txt")).string();
}

std::vector<LammpsAtom> read_lammps_dump(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open");
  std::string line;
  std::vector<LammpsAtom> atoms;
  long line_no = 0;
  bool data = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.rfind("ITEM:", 0) == 0) {
      data = line.rfind("ITEM: ATOMS", 0) == 0;
      if (data) {
        if (line.find("id mol x y z radius") == std::string::npos)
          throw InvalidInput(path + ":" + std::to_string(line_no) +
                             ": expected columns 'id mol x y z radius', found '" + line + "'");
        atoms.clear();  // a later snapshot replaces an earlier one
      }
      continue;
    }
    if (!data) continue;
    std::istringstream s(line);
    LammpsAtom a;
    double x, y, z;
    if (!(s >> a.id >> a.mol >> x >> y >> z >> a.radius) || !std::isfinite(x) ||
        !std::isfinite(y) || !std::isfinite(z) || !(a.radius > 0))
      throw InvalidInput(path + ":" + std::to_string(line_no) + ": not an atom row 'id mol x y z " +
                         "radius' with finite numbers: '" + line.substr(0, 80) + "'");
    a.position = Vec3(x, y, z);
    atoms.push_back(a);
  }
  if (atoms.empty()) throw InvalidInput(path + ": no atoms (not a dump of the exported deck)");
  return atoms;
}

std::vector<SpecimenBody> bodies_from_lammps_atoms(const std::vector<SpecimenBody>& specimen,
                                                   const std::vector<LammpsAtom>& atoms,
                                                   const std::string& path, std::size_t& lost,
                                                   double& residual) {
  std::unordered_map<long, const LammpsAtom*> by_id;
  for (const LammpsAtom& a : atoms) by_id[a.id] = &a;
  std::vector<SpecimenBody> out;
  lost = 0;
  residual = 0;
  long id = 0;
  for (const SpecimenBody& b : specimen) {
    std::vector<const LammpsAtom*> mine;
    for (const Sphere& s : b.spheres) {
      const auto it = by_id.find(++id);
      if (it == by_id.end()) continue;
      const LammpsAtom& a = *it->second;
      const long mol = b.kind == dem::BodyKind::rock ? b.id : 0;
      if (std::abs(a.radius - s.radius) > 1e-9 * s.radius || a.mol != mol)
        throw InvalidInput(path + ": atom " + std::to_string(a.id) + " does not match sphere " +
                           std::to_string(id) +
                           " of the specimen (radius or molecule differs): a dump of another "
                           "specimen?");
      mine.push_back(&a);
    }
    if (mine.size() != b.spheres.size()) {
      ++lost;
      continue;
    }
    SpecimenBody moved = b;
    if (b.spheres.size() == 1 && b.kind == dem::BodyKind::soil) {
      moved.position = mine.front()->position;
      moved.spheres.front().center = moved.position;
      out.push_back(std::move(moved));
      continue;
    }
    const std::vector<Sphere> local = body_frame_spheres(b);
    Eigen::Matrix3Xd from(3, local.size()), to(3, local.size());
    for (std::size_t k = 0; k < local.size(); ++k) {
      from.col(static_cast<Eigen::Index>(k)) = local[k].center;
      to.col(static_cast<Eigen::Index>(k)) = mine[k]->position;
    }
    // Fewer than three spheres leave a rotation undetermined: keep the spin about the axis.
    Eigen::Matrix3d R = b.orientation.toRotationMatrix();
    Vec3 t = to.rowwise().mean() - R * from.rowwise().mean();
    if (local.size() >= 3) {
      const Eigen::Matrix4d T = Eigen::umeyama(from, to, false);
      R = T.topLeftCorner<3, 3>();
      t = T.topRightCorner<3, 1>();
    }
    moved.orientation = Eigen::Quaterniond(R).normalized();
    moved.position = t;
    for (std::size_t k = 0; k < local.size(); ++k) {
      moved.spheres[k].center = moved.orientation * local[k].center + moved.position;
      residual = std::max(residual, (moved.spheres[k].center - mine[k]->position).norm());
    }
    out.push_back(std::move(moved));
  }
  return out;
}

}  // namespace clumpkit
