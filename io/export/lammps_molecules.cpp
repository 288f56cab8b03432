#include "io/export/lammps_molecules.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/units.h"
#include "io/export/lammps_deck.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace clumpkit {

std::string lammps_molecule_name(int template_id) {
  char name[32];
  std::snprintf(name, sizeof name, "clump_%05d.mol", template_id);
  return name;
}

std::vector<std::string> write_lammps_molecules(const std::vector<SpecimenBody>& bodies,
                                                const EngineSettings& settings,
                                                const std::string& dir) {
  if (bodies.empty()) throw InvalidInput("LAMMPS molecule export: no templates");
  std::vector<std::string> files;
  const SpecimenExtents e = specimen_extents(bodies);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const SpecimenBody& b = bodies[k];
    const std::vector<Sphere> local = body_frame_spheres(b);
    const double density = lammps_atom_density(b);
    files.push_back(
        write_export_file(dir, lammps_molecule_name(b.template_id), [&](std::ostream& o) {
          // The first line of a molecule file is a comment; the header's mass, com and inertia
          // (in this, the principal frame) override what LAMMPS would sum from the atoms.
          o << "clumpkit template " << b.template_id << ": principal frame, SI, exact mass "
            << "properties\n\n"
            << local.size() << " atoms\n"
            << format_number(b.mass) << " mass\n"
            << "0 0 0 com\n"
            << format_number(b.moments.x()) << " " << format_number(b.moments.y()) << " "
            << format_number(b.moments.z()) << " 0 0 0 inertia\n\nCoords\n\n";
          for (std::size_t i = 0; i < local.size(); ++i)
            o << i + 1 << " " << format_xyz(local[i].center) << "\n";
          o << "\nTypes\n\n";
          for (std::size_t i = 0; i < local.size(); ++i) o << i + 1 << " " << k + 1 << "\n";
          o << "\nDiameters\n\n";
          for (std::size_t i = 0; i < local.size(); ++i)
            o << i + 1 << " " << format_number(2 * local[i].radius) << "\n";
          o << "\nMasses\n\n";
          for (std::size_t i = 0; i < local.size(); ++i)
            o << i + 1 << " "
              << format_number(density * 4.0 / 3.0 * M_PI * std::pow(local[i].radius, 3)) << "\n";
        }));
  }

  files.push_back(write_export_file(dir, "molecules.csv", [&](std::ostream& o) {
    o << "# LAMMPS atom type -> clumpkit template: every atom of a body deposited from a molecule "
         "file has its type\n"
      << csv_header("molecules", "type,template,file,mass,I1,I2,I3,spheres", si_length()) << "\n";
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      const SpecimenBody& b = bodies[k];
      o << k + 1 << "," << b.template_id << "," << lammps_molecule_name(b.template_id) << ","
        << format_number(b.mass) << "," << format_number(b.moments.x()) << ","
        << format_number(b.moments.y()) << "," << format_number(b.moments.z()) << ","
        << b.spheres.size() << "\n";
    }
  }));

  // The drop region: inside the cylinder and above the floor by the largest reach, so every
  // deposited sphere starts inside the container whatever its random orientation.
  const LammpsContact lc = lammps_contact(e, settings);
  const double pad = 2 * e.r_max, R = settings.container_radius, H = settings.container_height;
  const std::size_t n = bodies.size();
  files.push_back(write_export_file(dir, "in.deposit", [&](std::ostream& o) {
    o << "# clumpkit molecule templates for LAMMPS (syntax of LAMMPS 29 Sep 2021, Debian 12\n"
         "# `lammps`): fix deposit pours -var count N bodies of each template (default 1, one\n"
         "# every -var every S steps) into the container; LAMMPS takes each body's mass, centre\n"
         "# and inertia from the molecule file's header (clumpkit's exact values). After\n"
         "# -var nsteps N steps (default 1000) it dumps deposit_bodies.N.txt (id mol mass x y z\n"
         "# inertiax inertiay inertiaz, as LAMMPS sees them) and deposit_atoms.N.txt (id mol\n"
         "# type x y z radius; type k = the k-th template of molecules.csv).\n"
         "#   lmp -in in.deposit     or     mpirun -np N lmp -in in.deposit\n"
      << "variable    count  index 1\n"
      << "variable    every  index 100\n"
      << "variable    nsteps index 1000\n"
      << lammps_preamble(lc) << "region      domain block " << format_number(-R - pad) << " "
      << format_number(R + pad) << " " << format_number(-R - pad) << " " << format_number(R + pad)
      << " " << format_number(-pad) << " " << format_number(H + pad) << " units box\n"
      << "create_box  " << n << " domain\n"
      << "mass        * 1.0\n"
      << "molecule    clumps";
    for (const SpecimenBody& b : bodies) o << " " << lammps_molecule_name(b.template_id);
    o << "\n"
      << "neighbor    " << format_number(lc.skin) << " bin\n"
      << "neigh_modify delay 0 every 1 check yes exclude molecule/intra all\n"
      << "pair_style  gran/hooke/history " << lammps_contact_args(lc) << "\n"
      << "pair_coeff  * *\n"
      << "timestep    " << format_number(lc.dt) << "\n"
      << "# Gravity reaches the bodies through the rigid fix (M*g at each centroid); the atoms\n"
         "# get none of their own.\n"
         "group       none empty\n"
         "fix         grav none gravity 9.81 vector 0 0 -1\n"
         "fix         rig all rigid/small molecule mol clumps gravity grav\n"
      << "region      drop cylinder z 0 0 " << format_number(std::max(R - e.reach, 0.5 * R)) << " "
      << format_number(e.reach) << " " << format_number(H - e.reach) << " side in units box\n";
    for (std::size_t k = 0; k < n; ++k) {
      // molfrac picks the k-th molecule of the set for this fix (cumulative fractions).
      o << "fix         dep" << k + 1 << " all deposit ${count} 0 ${every} " << 10007 + 2 * k
        << " region drop near " << format_number(2 * e.r_max)
        << " attempt 1000 units box mol clumps molfrac";
      for (std::size_t j = 0; j < n; ++j) o << (j == k ? " 1" : " 0");
      o << " rigid rig\n";
    }
    o << "fix         floor all wall/gran hooke/history " << lammps_contact_args(lc)
      << " zplane 0.0 NULL\n"
      << "fix         cyl all wall/gran hooke/history " << lammps_contact_args(lc) << " zcylinder "
      << format_number(R) << "\n"
      << "compute     rl all rigid/local rig id mol mass x y z inertiax inertiay inertiaz\n"
         "dump        bodies all local ${nsteps} deposit_bodies.*.txt c_rl[1] c_rl[2] c_rl[3] "
         "c_rl[4] c_rl[5] c_rl[6] c_rl[7] c_rl[8] c_rl[9]\n"
         "dump_modify bodies format float %.17g\n"
         "dump        atoms all custom ${nsteps} deposit_atoms.*.txt id mol type x y z radius\n"
         "dump_modify atoms sort id format float %.17g\n"
         "thermo_style custom step atoms cpu\n"
         "thermo      100\n"
         "run         ${nsteps}\n";
  }));
  return files;
}

}  // namespace clumpkit
