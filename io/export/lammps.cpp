#include "io/export/lammps.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/units.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace clumpkit {

namespace {

/// The simulation box around the container (or, tiled, around all copies).
struct LammpsBox {
  double pad = 0, half_x = 0, half_y = 0, z_hi = 0;
  bool tiled = false;
};

/// How many atoms (spheres), rock bodies and soil bodies the specimen has.
struct LammpsCounts {
  std::size_t atoms = 0, rocks = 0, soils = 0;
};

/// data.specimen: the box and one atom per sphere.
void write_lammps_data(std::ostream& o, const std::vector<SpecimenBody>& bodies,
                       const std::vector<StiffnessClass>& classes, std::size_t atoms,
                       const LammpsBox& box) {
  o << "clumpkit specimen: atom_style hybrid sphere molecular, SI units\n\n"
    << atoms << " atoms\n"
    << (classes.empty() ? 2 : classes.size() + 1) << " atom types\n\n"
    << format_number(-box.half_x) << " " << format_number(box.half_x) << " xlo xhi\n"
    << format_number(-box.half_y) << " " << format_number(box.half_y) << " ylo yhi\n"
    << format_number(-box.pad) << " " << format_number(box.z_hi)
    << " zlo zhi\n\nAtoms # hybrid\n\n";
  std::size_t id = 0;
  for (const SpecimenBody& b : bodies) {
    const bool rock = b.kind == dem::BodyKind::rock;
    // Rock: Σ m_i = M (per-atom quantities only; the rigid fix takes M from the infile).
    const double density = lammps_atom_density(b);
    const int type = rock ? 1 : classes.empty() ? 2 : 2 + stiffness_class_of(classes, b);
    for (const Sphere& s : b.spheres)
      o << ++id << " " << type << " " << format_number(s.center.x()) << " "
        << format_number(s.center.y()) << " " << format_number(s.center.z()) << " "
        << format_number(2 * s.radius) << " " << format_number(density) << " " << (rock ? b.id : 0)
        << "\n";
  }
}

/// bodies.infile: the exact mass properties of every rock body, for fix rigid/small.
void write_lammps_infile(std::ostream& o, const std::vector<SpecimenBody>& bodies,
                         std::size_t rocks, double start_vz) {
  o << "# clumpkit exact rigid-body properties for fix rigid/small ... infile (SI): id mass\n"
       "# xcm ycm zcm ixx iyy izz ixy ixz iyz (box frame, R diag(I1,I2,I3) R^T) vxcm vycm vzcm\n"
       "# lx ly lz ixcm iycm izcm\n"
    << rocks << "\n";
  for (const SpecimenBody& b : bodies) {
    if (b.kind != dem::BodyKind::rock) continue;
    const Eigen::Matrix3d R = b.orientation.toRotationMatrix();
    const Eigen::Matrix3d I = R * b.moments.asDiagonal() * R.transpose();
    o << b.id << " " << format_number(b.mass) << " " << format_number(b.position.x()) << " "
      << format_number(b.position.y()) << " " << format_number(b.position.z()) << " "
      << format_number(I(0, 0)) << " " << format_number(I(1, 1)) << " " << format_number(I(2, 2))
      << " " << format_number(I(0, 1)) << " " << format_number(I(0, 2)) << " "
      << format_number(I(1, 2)) << " 0 0 " << format_number(start_vz) << " 0 0 0 0 0 0\n";
  }
}

/// bodies_map.csv: which LAMMPS molecule or atom each specimen body became.
void write_lammps_body_map(std::ostream& o, const std::vector<SpecimenBody>& bodies) {
  o << "# specimen.csv body id -> LAMMPS id: molecule id (rock, fix rigid/small) or atom id "
       "(soil)\n"
    << csv_header("bodies_map", "body,lammps_kind,lammps_id", si_length()) << "\n";
  std::size_t atom = 0;
  for (const SpecimenBody& b : bodies) {
    const bool rock = b.kind == dem::BodyKind::rock;
    o << b.id << "," << (rock ? "molecule" : "atom") << ","
      << (rock ? b.id : static_cast<long>(atom + 1)) << "\n";
    atom += b.spheres.size();
  }
}

/// in.clumpkit up to the end of the settle under gravity.
void write_lammps_settle(std::ostream& o, const EngineSettings& settings, const LammpsContact& lc,
                         const std::string& contact_args, const LammpsCounts& n,
                         const LammpsBox& box, double m_min) {
  const dem::ContactParams& c = settings.contact;
  const double dt = lc.dt;
  o << "# clumpkit export for LAMMPS (syntax of LAMMPS 29 Sep 2021, Debian 12 `lammps`): the\n"
       "# specimen with clumpkit's exact clump mass properties forced on fix rigid/small,\n"
       "# settled under gravity in its container. Runs on any number of ranks:\n"
       "#   lmp -in in.clumpkit     or     mpirun -np N lmp -in in.clumpkit\n"
       "# -var nsteps N (default 1000), -var exact 0: LAMMPS's own mass properties instead.\n"
       "# Dumps bodies.STEP.txt (id mol mass x y z inertiax inertiay inertiaz, as LAMMPS sees\n"
       "# them) and atoms.STEP.txt (id mol x y z radius) at step 0 and at the end.\n"
    << "variable    nsteps index 1000\n"
    << "variable    exact  index 1\n"
    << "variable    dt     index " << format_number(dt) << "\n"
    << lammps_preamble(lc)
    << "read_data   data.specimen\n"
       "group       rock type 1\n"
       "group       soil type 2\n"
    << "neighbor    " << format_number(lc.skin) << " bin\n"
    << "neigh_modify delay 0 every 1 check yes exclude molecule/intra rock\n"
    << "pair_style  gran/hooke/history " << contact_args << "\n"
    << "pair_coeff  * *\n"
       "timestep    ${dt}\n"
       "# Gravity on the soil atoms; the rigid fix applies M*g at each body's centroid (the\n"
       "# overlapping spheres' atom masses do not sum to the body's mass distribution).\n"
       "fix         grav soil gravity "
    << format_number(settings.gravity) << " vector 0 0 -1\n";
  // clumpkit prepares specimens with masses scaled by λ (report.json density_scaling), so its
  // contacts carry λ times the overlap of the true weight. The deck damps that stored energy
  // away while it settles: a zero-temperature Langevin drag on the clumps (time constant 50
  // steps; no random force at T = 0, so any rank count gives the same run) and a viscous drag
  // on the soil (damping ratio 0.5 for the lightest body).
  o << "# clumpkit's specimen carries the contact overlaps of its mass-scaled preparation; the\n"
       "# deck damps their energy while it settles (-var relax 0: no damping).\n"
       "variable    relax index 1\n"
       "variable    rigid_damp string \"\"\n"
    << "if \"${relax} == 1\" then \"variable rigid_damp string 'langevin 0 0 "
    << format_number(50 * dt) << " 48271'\"\n";
  if (n.rocks > 0)
    o << "if \"${exact} == 1\" then \"fix rig rock rigid/small molecule infile bodies.infile "
         "gravity grav ${rigid_damp}\" else \"fix rig rock rigid/small molecule gravity grav "
         "${rigid_damp}\"\n";
  if (n.soils > 0)
    o << "fix         nve soil nve/sphere\n"
      << "if \"${relax} == 1\" then \"fix visc soil viscous "
      << format_number(std::sqrt(c.kn * m_min)) << "\"\n";
  o << "fix         floor all wall/gran hooke/history " << contact_args << " zplane 0.0 NULL\n";
  if (box.tiled)
    o << "# tiled copies of the specimen: the box's side planes instead of each cylinder\n"
      << "fix         wallx all wall/gran hooke/history " << contact_args << " xplane "
      << format_number(-(box.half_x - box.pad)) << " " << format_number(box.half_x - box.pad)
      << "\n"
      << "fix         wally all wall/gran hooke/history " << contact_args << " yplane "
      << format_number(-(box.half_y - box.pad)) << " " << format_number(box.half_y - box.pad)
      << "\n";
  else
    o << "fix         cyl all wall/gran hooke/history " << contact_args << " zcylinder "
      << format_number(settings.container_radius) << "\n";
  if (n.rocks > 0)
    o << "compute     rl rock rigid/local rig id mol mass x y z inertiax inertiay inertiaz\n"
         "dump        bodies rock local ${nsteps} bodies.*.txt c_rl[1] c_rl[2] c_rl[3] "
         "c_rl[4] c_rl[5] c_rl[6] c_rl[7] c_rl[8] c_rl[9]\n"
         "dump_modify bodies format float %.17g\n";
  o << "dump        atoms all custom ${nsteps} atoms.*.txt id mol x y z radius\n"
       "dump_modify atoms sort id format float %.17g\n"
       "compute     kea all ke\n"
       "thermo_style custom step atoms c_kea cpu\n"
       "thermo_modify lost ignore norm no\n"
       "thermo      100\n"
       "run         ${nsteps}\n";
}

/// in.clumpkit's oedometer test, run after the settle.
void write_lammps_oedometer(std::ostream& o, const EngineSettings& settings,
                            const LammpsContact& lc, const LammpsDeck& deck,
                            const LammpsCounts& n) {
  o << "# Oedometer test: a platen starts at the top H0 of the settled specimen (highest\n"
       "# sphere surface) and moves down at rate*H0 until the strain maxstrain; strain and\n"
       "# vertical stress (platen force / container area, compression positive) every 100\n"
       "# steps in oedometer.csv. Walls and platen are frictionless, as in clumpkit test's\n"
       "# cell (wall friction would carry part of the platen's load).\n"
    << "undump      atoms\n"
    << (n.soils > 0 ? "if \"${relax} == 1\" then \"unfix visc\"\n" : "")
    << (n.rocks > 0 ? "undump      bodies\n" : "") << "variable    maxstrain index "
    << format_number(deck.max_strain) << "\n"
    << "variable    rate index " << format_number(deck.strain_rate) << "\n"
    << "compute     rad all property/atom radius\n"
       "variable    ztop atom z+c_rad\n"
       "compute     top all reduce max v_ztop\n"
       "thermo_style custom step atoms c_top\n"
       "thermo_modify lost ignore norm no\n"
       "run         0\n"
       "variable    H0 equal $(c_top:%.17g)\n"
       "variable    s0 equal $(step)\n"
       "variable    dz equal -${rate}*${H0}*(step-${s0})*dt\n"
       "unfix       floor\n"
    << "fix         floor all wall/gran hooke/history " << lammps_contact_args(lc, 0.0)
    << " zplane 0.0 NULL\n"
    << "unfix       cyl\n"
    << "fix         cyl all wall/gran hooke/history " << lammps_contact_args(lc, 0.0)
    << " zcylinder " << format_number(settings.container_radius) << "\n"
    << "region      platen plane 0 0 ${H0} 0 0 -1 side in units box move NULL NULL v_dz\n"
    << "fix         platen all wall/gran/region hooke/history " << lammps_contact_args(lc, 0.0)
    << " region platen contacts\n"
    << "compute     pf all reduce sum f_platen[4]\n"
       "variable    strain equal -v_dz/${H0}\n"
    << "variable    stress equal -c_pf/(PI*" << format_number(settings.container_radius) << "^2)\n"
    << "variable    nload equal ceil(${maxstrain}/(${rate}*dt))\n"
       "fix         curve all print 100 \"$(v_strain:%.17g),$(v_stress:%.17g)\" file "
       "oedometer.csv screen no title \""
    << csv_header("oedometer", "strain,stress", si_length())
    << "\"\n"
       "thermo_style custom step v_strain v_stress cpu\n"
       "thermo_modify lost ignore norm no\n"
       "thermo      1000\n"
       "run         ${nload}\n"
       "write_dump  all custom atoms.final.txt id mol x y z radius modify sort id format "
       "float %.17g\n";
}

}  // namespace

std::vector<std::string> write_lammps_export(const std::vector<SpecimenBody>& bodies,
                                             const EngineSettings& settings, const std::string& dir,
                                             const LammpsDeck& deck) {
  if (bodies.empty()) throw InvalidInput("LAMMPS export: the specimen has no bodies");
  const SpecimenExtents e = specimen_extents(bodies);
  std::vector<std::string> files;
  LammpsCounts n;
  for (const SpecimenBody& b : bodies) {
    n.atoms += b.spheres.size();
    (b.kind == dem::BodyKind::rock ? n.rocks : n.soils) += 1;
  }

  // The box holds the container with a margin of one sphere diameter and room above the top.
  LammpsBox box;
  box.pad = 2 * e.r_max;
  box.tiled = deck.tiles_x * deck.tiles_y > 1;
  box.half_x = deck.tiles_x * settings.container_radius + box.pad;
  box.half_y = deck.tiles_y * settings.container_radius + box.pad;
  // The CPT's chamber rises by the push's depth (it runs in the probe's frame).
  box.z_hi = std::max(settings.container_height, e.top) + box.pad +
             (deck.cpt ? deck.cpt->probe.depth : 0.0);
  // Linear stiffness scaling: soil sphere of size class k is type 2 + k (lammps_stiffness.h).
  const std::vector<StiffnessClass> no_classes;
  const std::vector<StiffnessClass>& classes = deck.cpt ? deck.cpt->classes : no_classes;
  files.push_back(write_export_file(dir, "data.specimen", [&](std::ostream& o) {
    write_lammps_data(o, bodies, classes, n.atoms, box);
  }));

  // The CPT runs in the probe's frame: every body starts moving up at the probe's speed.
  const double start_vz = deck.cpt ? deck.cpt->probe.velocity : 0.0;
  files.push_back(write_export_file(dir, "bodies.infile", [&](std::ostream& o) {
    write_lammps_infile(o, bodies, n.rocks, start_vz);
  }));

  files.push_back(write_export_file(dir, "bodies_map.csv",
                                    [&](std::ostream& o) { write_lammps_body_map(o, bodies); }));

  const LammpsContact lc = lammps_contact(e, settings);
  const std::string contact_args = lammps_contact_args(lc);
  if (deck.cpt) {
    files.push_back(write_export_file(dir, "in.clumpkit", [&](std::ostream& o) {
      write_lammps_cpt_deck(o, *deck.cpt, settings, lc, n.rocks > 0, n.soils > 0);
    }));
    return files;
  }
  files.push_back(write_export_file(dir, "in.clumpkit", [&](std::ostream& o) {
    write_lammps_settle(o, settings, lc, contact_args, n, box, e.m_min);
    if (deck.oedometer) write_lammps_oedometer(o, settings, lc, deck, n);
  }));
  return files;
}

}  // namespace clumpkit
