#include "io/export/lammps_cpt.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/formats/cpt_curve.h"

#include <cmath>
#include <functional>
#include <vector>

namespace clumpkit {

void check_lammps_cpt(const LammpsCpt& cpt, const EngineSettings& settings,
                      const std::string& where) {
  try {
    dem::validate_probe(cpt.probe);
    dem::check_probe_width(cpt.probe, 2 * settings.container_radius);
  } catch (const InvalidInput& e) {
    throw InvalidInput(where + ": " + e.what());
  }
  if (!dem::kFriction.contains(cpt.probe.friction))
    throw InvalidInput(where + ": probe.friction " + outside(dem::kFriction, cpt.probe.friction) +
                       ", got " + format_number(cpt.probe.friction));
}

namespace {

// The chamber in the probe's frame: the floor rises at the push speed (the base is fixed); with
// `-var servo 1` (the default) the lid and the lateral cylinder hold the confining stress (BC1)
// by the servo of clumpkit's cell (dem/lab/servo.h): each step a wall moves in by
// α·A·(σ_target − σ)/(N_c·kn), at most `servo_step` (a millionth of the specimen's height),
// the whole step when it touches nothing. LAMMPS keeps no state in a variable, so a wall's
// travel is the running mean of its steps (fix ave/time ... ave running, which samples from the
// run's first step on) times their count; the walls read it from the step before.
// The laws of the walls: one fix for every atom under the specimen's law, or, with stiffness
// classes, one per class (group kN, fix NAME_N) under the class's law; their per-atom columns
// are summed wherever the deck reads a wall.
struct WallLaws {
  std::vector<std::string> group, suffix;
  std::vector<std::string> chamber;  ///< frictionless, no dashpot
  std::vector<std::string> probe;    ///< the probe's friction and the dashpot
  std::vector<double> kn;            ///< a chamber wall's normal stiffness (the servo's)
};

WallLaws wall_laws(const LammpsCpt& cpt, const EngineSettings& settings, const LammpsContact& lc) {
  const dem::ContactParams& c = settings.contact;
  WallLaws w;
  if (cpt.classes.empty()) {
    w.group = {"all"};
    w.suffix = {""};
    w.chamber = {"hooke/history " + lammps_hooke_args(c.kn, c.ks, 0.0, 0.0)};
    // The probe is a wall: the body's mass is the contact's m_eff (as in clumpkit's probe).
    w.probe = {"hooke/history " +
               lammps_hooke_args(c.kn, c.ks, lc.wall_gamma_n, cpt.probe.friction)};
    w.kn = {c.kn};
    return w;
  }
  for (std::size_t k = 0; k < cpt.classes.size(); ++k) {
    const StiffnessClass& cl = cpt.classes[k];
    w.group.push_back("k" + std::to_string(k + 1));
    w.suffix.push_back("_" + std::to_string(k + 1));
    w.chamber.push_back(lammps_class_wall_law(cl, c, 0.0, false));
    w.probe.push_back(lammps_class_wall_law(cl, c, cpt.probe.friction, true));
    w.kn.push_back(c.kn * dem::wall_stiffness_factor(c, cl.diameter));
  }
  return w;
}

// The fixes of the wall `name` on `region_args` ("region R [contacts]"), one per law.
std::string wall_fixes(const WallLaws& w, const std::string& name,
                       const std::vector<std::string>& law, const std::string& region_args) {
  std::string s;
  for (std::size_t k = 0; k < law.size(); ++k)
    s += "fix         " + name + w.suffix[k] + " " + w.group[k] + " wall/gran/region " + law[k] +
         " " + region_args + "\n";
  return s;
}

// term(fix) summed over the wall's fixes (the one term itself for one law).
std::string summed(const WallLaws& w, const std::string& name,
                   const std::function<std::string(const std::string&)>& term) {
  if (w.suffix.size() == 1) return term(name + w.suffix[0]);
  std::string s = "(";
  for (std::size_t k = 0; k < w.suffix.size(); ++k) s += (k ? "+" : "") + term(name + w.suffix[k]);
  return s + ")";
}

// `compute ID all reduce sum` of column `col` of the wall's fixes.
std::string reduce_column(const WallLaws& w, const std::string& id, const std::string& name,
                          int col) {
  const auto column = [col](const std::string& f) {
    return "f_" + f + "[" + std::to_string(col) + "]";
  };
  if (w.suffix.size() == 1) return "compute     " + id + " all reduce sum " + column(name) + "\n";
  return "variable    " + id + "_atom atom " + summed(w, name, column) + "\ncompute     " + id +
         " all reduce sum v_" + id + "_atom\n";
}

// The servo's stiffness of the wall's contacts Σ N_c,k·kn_k (one term for one law), never 0.
std::string contact_stiffness(const std::string& n) {
  return "(c_" + n + "+(c_" + n + "==0)*${kn})";
}
std::string stiffness_reduce(const WallLaws& w, const std::string& id, const std::string& name) {
  std::string s = "variable    " + id + "_atom atom (";
  for (std::size_t k = 0; k < w.suffix.size(); ++k)
    s += std::string(k ? "+" : "") + "f_" + name + w.suffix[k] + "[1]*" + format_number(w.kn[k]);
  return s + ")\ncompute     " + id + " all reduce sum v_" + id + "_atom\n";
}

// A segment's radial planes through the axis, at φ = 0 (normal +y) and φ = angle (normal
// (sin θ, −cos θ, 0)), frictionless and fixed: planes of symmetry of the whole chamber, which a
// translation along the axis leaves where they are. Empty for a whole cylinder.
std::string radial_planes(const EngineSettings& settings, const WallLaws& w) {
  if (settings.segment_angle_deg <= 0) return "";
  const double a = settings.segment_angle_deg * M_PI / 180.0;
  return "region      side0 plane 0 0 0 0 1 0 side in units box\n" +
         wall_fixes(w, "side0", w.chamber, "region side0") + "region      side1 plane 0 0 0 " +
         format_number(std::sin(a)) + " " + format_number(-std::cos(a)) + " 0 side in units box\n" +
         wall_fixes(w, "side1", w.chamber, "region side1");
}

void write_chamber(std::ostream& o, const LammpsCpt& cpt, const EngineSettings& settings,
                   const WallLaws& w) {
  // Frictionless and without a dashpot: LAMMPS takes the velocity of a region moved through a
  // variable a step late, and the dashpot's answer to that drove the lid's servo into a two-step
  // oscillation of ±10 kPa about 93 kPa (a consolidated specimen at 100 kPa).
  o << "variable    servo  index 1\n"
       "variable    sigma  equal "
    << format_number(cpt.confining) << "\n"
    << "variable    alpha  equal 0.5\n"
       "variable    kn     equal "
    << format_number(settings.contact.kn) << "\n"
    << "variable    servo_step index $(1e-6*v_top0:%.17g)\n"
       "variable    s0 equal $(step)\n"
       "variable    rise equal ${v}*(step-${s0})*dt\n"
       "region      floor plane 0 0 0 0 0 1 side in units box move NULL NULL v_rise\n"
    << wall_fixes(w, "floor", w.chamber, "region floor")
    << "# Stresses (compression positive): the lid's force over its area; the cylinder's radial\n"
       "# force (force . contact point / rc) over its area between floor and lid. The walls'\n"
       "# travel inwards (m): the running mean of their steps times their count.\n"
       "variable    lidz equal v_rise-f_utop*(step-${s0})\n"
       "variable    rc equal "
    << format_number(settings.container_radius)
    << "-f_ulat*(step-${s0})\n"
       "variable    frad atom ("
    << summed(w, "cyl",
              [](const std::string& f) {
                return "f_" + f + "[2]*f_" + f + "[5]+f_" + f + "[3]*f_" + f + "[6]";
              })
    << ")/v_rc\n"
       "variable    height equal ${top0}+v_lidz-v_rise\n"
       "variable    alid equal 0.5*${angle}*v_rc^2\n"
       "variable    acyl equal ${angle}*v_rc*v_height\n"
       "variable    saxial equal -c_flid/v_alid\n"
       "variable    slateral equal -c_fcyl/v_acyl\n"
       "variable    etop equal "
       "${servo}*${alpha}*v_alid*(${sigma}-v_saxial)/("
    << contact_stiffness("nlid")
    << ")\n"
       "variable    elat equal "
       "${servo}*${alpha}*v_acyl*(${sigma}-v_slateral)/("
    << contact_stiffness("ncyl")
    << ")\n"
       "variable    dtop equal v_etop-(v_etop>${servo_step})*(v_etop-${servo_step})"
       "+(v_etop<-${servo_step})*(-${servo_step}-v_etop)\n"
       "variable    dlat equal v_elat-(v_elat>${servo_step})*(v_elat-${servo_step})"
       "+(v_elat<-${servo_step})*(-${servo_step}-v_elat)\n"
       "fix         utop all ave/time 1 1 1 v_dtop ave running\n"
       "fix         ulat all ave/time 1 1 1 v_dlat ave running\n"
       "region      lid plane 0 0 ${top0} 0 0 -1 side in units box move NULL NULL v_lidz\n"
    << wall_fixes(w, "lid", w.chamber, "region lid contacts")
    << "region      cyl cylinder z 0 0 v_rc INF INF side in units box\n"
    << wall_fixes(w, "cyl", w.chamber, "region cyl contacts") << radial_planes(settings, w)
    << reduce_column(w, "flid", "lid", 4) << stiffness_reduce(w, "nlid", "lid")
    << "compute     fcyl all reduce sum v_frad\n"
    << stiffness_reduce(w, "ncyl", "cyl");
}

}  // namespace

void write_lammps_cpt_deck(std::ostream& o, const LammpsCpt& cpt, const EngineSettings& settings,
                           const LammpsContact& lc, bool rocks, bool soils) {
  const dem::ProbeSettings& p = cpt.probe;
  const WallLaws w = wall_laws(cpt, settings, lc);
  const std::size_t types = cpt.classes.size();
  o << "# clumpkit export for LAMMPS (syntax of LAMMPS 29 Sep 2021, Debian 12 `lammps`): the cone\n"
       "# penetration test of `clumpkit test cpt` on this specimen, in the probe's frame (the\n"
       "# probe is one static region; the chamber moves up at the push speed). Any number of\n"
       "# ranks:   lmp -in in.clumpkit     or     mpirun -np N lmp -in in.clumpkit\n"
    << "# cpt.csv: " << cpt_curve_header()
    << " every ${every} steps.\n"
       "# -var apex Z: the apex's start height (default: the highest sphere surface);\n"
       "# -var dt T: the time step (default: the test's of a consolidated state, else a tenth\n"
       "# of the lightest sphere's period); -var depth D: push to D (m) instead; -var every N:\n"
       "# a row every N steps; -var servo 0: the lid and the cylinder fixed instead of holding\n"
       "# the confining stress (BC1; the base is fixed either way). Walls frictionless, as in\n"
       "# clumpkit's cell; the thermo output shows their stresses.\n"
    << "variable    dt     index "
    << format_number(settings.test_timestep > 0 ? settings.test_timestep : lc.dt) << "\n"
    << "variable    apex   index -1\n"
    << "variable    every  index " << cpt.record_every << "\n"
    << "variable    v      equal " << format_number(p.velocity) << "\n"
    << "variable    R      equal " << format_number(0.5 * p.diameter) << "\n"
    << "variable    angle  equal "
    << (settings.segment_angle_deg > 0 ? format_number(settings.segment_angle_deg) + "*PI/180"
                                       : std::string("2*PI"))
    << "\n"
    << "variable    depth  index " << format_number(p.depth) << "\n"
    << "variable    hcone  equal ${R}/tan(" << format_number(0.5 * p.apex_deg) << "*PI/180)\n"
    << lammps_preamble(lc)
    << "read_data   data.specimen\n"
       "group       rock type 1\n"
    << (types == 0 ? std::string("group       soil type 2\n")
                   : "group       soil type <> 2 " + std::to_string(types + 1) + "\n");
  for (std::size_t k = 0; k < types; ++k)
    o << "group       " << w.group[k] << " type " << k + 2 << "\n";
  o << "neighbor    " << format_number(lc.skin) << " bin\n"
    << "neigh_modify delay 0 every 1 check yes" << (rocks ? " exclude molecule/intra rock" : "")
    << "\n";
  if (types == 0) {
    o << "pair_style  gran/hooke/history " << lammps_contact_args(lc) << "\npair_coeff  * *\n";
  } else {
    const dem::ContactParams& c = settings.contact;
    o << "# Contact stiffness ∝ diameter: soil type 2 + k is size class k (diameters "
         "within\n# "
      << format_number(100 * stiffness_class_error(cpt.classes))
      << " % of its mean), each pair of types its kn, kt and dashpot (type 1 holds no atom).\n"
         "pair_style  granular\n"
         "pair_coeff  * * hooke "
      << format_number(c.kn) << " 0 tangential linear_history " << format_number(c.ks) << " 0 "
      << format_number(c.friction) << " damping mass_velocity\n"
      << lammps_class_pair_coeffs(cpt.classes, 2, c);
  }
  o << "timestep    ${dt}\n";
  const bool gravity = settings.gravity != 0;
  if (gravity)
    o << "fix         grav soil gravity " << format_number(settings.gravity) << " vector 0 0 -1\n";
  if (rocks)
    o << "# bodies.infile starts every rock body moving up at v (the probe's frame)\n"
      << "fix         rig rock rigid/small molecule infile bodies.infile"
      << (gravity ? " gravity grav" : "") << "\n";
  if (soils)
    o << "fix         nve soil nve/sphere\n"
         "velocity    soil set 0 0 ${v}\n";
  o << "compute     rad all property/atom radius\n"
       "variable    ztop atom z+c_rad\n"
       "compute     top all reduce max v_ztop\n"
       "thermo_style custom step c_top\n"
       "thermo_modify lost ignore norm no\n"
       "run         0\n"
       "# The specimen's top: its highest sphere surface, or the container's height when\n"
       "# lower (a consolidated state's top platen, on which the spheres press).\n"
       "variable    ztop0 equal $(c_top:%.17g)\n"
    << "variable    top0 equal ${ztop0}-(${ztop0}>" << format_number(settings.container_height)
    << ")*(${ztop0}-" << format_number(settings.container_height)
    << ")\n"
       "if \"${apex} < 0\" then \"variable H0 equal ${top0}\" else \"variable H0 equal "
       "${apex}\"\n"
       "variable    zs equal ${H0}+${hcone}\n"
       "# The probe: outside a cone (apex up to the shoulder zs) and outside the shaft above it,\n"
       "# as one region. Radius 0 gives no contacts in this version: the cone starts at radius\n"
       "# 1e-9 m, that much above the apex, so that its faces pass through the apex exactly.\n"
       "variable    zlo equal ${H0}+1e-9*${hcone}/${R}\n"
       "region      cone cone z 0 0 1e-9 ${R} ${zlo} ${zs} side out\n"
       "region      shaft cylinder z 0 0 ${R} ${zs} INF side out\n"
       "region      probe intersect 2 cone shaft\n"
    << wall_fixes(w, "probe", w.probe, "region probe contacts");
  write_chamber(o, cpt, settings, w);
  o << "# A contact below the shoulder is the tip's, else the sleeve's; forces on the probe.\n"
       "variable    tipz atom "
    << summed(w, "probe",
              [](const std::string& f) { return "f_" + f + "[4]*(f_" + f + "[7]<${zs})"; })
    << "\nvariable    slvz atom "
    << summed(w, "probe",
              [](const std::string& f) { return "f_" + f + "[4]*(f_" + f + "[7]>=${zs})"; })
    << "\n"
       "compute     tip all reduce sum v_tipz\n"
       "compute     slv all reduce sum v_slvz\n"
       "# Forces for the whole chamber: a segment's times 2 pi / its angle.\n"
       "variable    tip equal -c_tip*2*PI/${angle}\n"
       "variable    sleeve equal -c_slv*2*PI/${angle}\n"
       "variable    qc equal v_tip/(PI*${R}^2)\n"
       "variable    emb equal ${top0}+v_lidz-${zs}\n"
       "variable    fs equal (v_emb>0)*v_sleeve/(2*PI*${R}*(abs(v_emb)+(v_emb<=0)))\n"
       "# Whole rows, as clumpkit's push: the last at or just past the depth.\n"
       "variable    npush equal ${every}*ceil(${depth}/(${v}*dt*${every}))\n"
       "fix         curve all print ${every} \"$(step-v_s0),$(v_rise:%.17g),$(v_tip:%.17g),"
       "$(v_sleeve:%.17g),$(v_qc:%.17g),$(v_fs:%.17g)\" file cpt.csv screen no title \""
    << cpt_curve_header()
    << "\"\n"
       "thermo_style custom step v_rise v_qc v_saxial v_slateral cpu\n"
       "thermo_modify lost ignore norm no\n"
       "thermo      1000\n"
       "run         ${npush}\n"
       "write_dump  all custom atoms.final.txt id mol x y z radius fx fy fz modify sort id "
       "format float %.17g\n";
}

}  // namespace clumpkit
